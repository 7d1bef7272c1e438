package org.skinlab.android.apicheck;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.codehaus.mojo.animal_sniffer.Clazz;
import org.jf.dexlib2.DexFileFactory;
import org.jf.dexlib2.iface.ClassDef;
import org.jf.dexlib2.iface.Field;
import org.jf.dexlib2.iface.Method;
import org.jf.dexlib2.iface.reference.MethodReference;

/**
 * The classes of one or more dex files, read with dexlib2, and their models in animal-sniffer's
 * form (so that members resolve through our classes into the platform's).
 */
record DexProgram(List<ClassDef> classes, Map<String, Clazz> models) {

    static DexProgram read(List<Path> dexFiles) throws IOException {
        List<ClassDef> classes = new ArrayList<>();
        Map<String, Clazz> models = new HashMap<>();
        for (Path file : dexFiles) {
            // No opcodes given: dexlib2 takes them from the file's dex version (038/039 from R8 at 26).
            for (ClassDef c : DexFileFactory.loadDexFile(file.toFile(), null).getClasses()) {
                classes.add(c);
                models.put(internalName(c.getType()), model(c));
            }
        }
        return new DexProgram(List.copyOf(classes), Map.copyOf(models));
    }

    private static Clazz model(ClassDef c) {
        Set<String> members = new HashSet<>();
        for (Field f : c.getFields()) {
            members.add(f.getName() + "#" + f.getType());
        }
        for (Method m : c.getMethods()) {
            members.add(signature(m.getName(), m.getParameterTypes(), m.getReturnType()));
        }
        String superclass = c.getSuperclass() == null ? null : internalName(c.getSuperclass());
        String[] interfaces = c.getInterfaces().stream().map(DexProgram::internalName).toArray(String[]::new);
        return new Clazz(internalName(c.getType()), members, superclass, interfaces);
    }

    /** {@code Ljava/lang/String;} to {@code java/lang/String}; other descriptors unchanged. */
    static String internalName(String descriptor) {
        return descriptor.startsWith("L") && descriptor.endsWith(";")
                ? descriptor.substring(1, descriptor.length() - 1) : descriptor;
    }

    /** A method in animal-sniffer's signature form: {@code name(params)ret}. */
    static String signature(String name, List<? extends CharSequence> parameters, String returnType) {
        StringBuilder s = new StringBuilder(name).append('(');
        parameters.forEach(s::append);
        return s.append(')').append(returnType).toString();
    }

    /** A method's key, as smali writes a method reference: {@code Lowner;->name(params)ret}. */
    static String key(MethodReference method) {
        return method.getDefiningClass() + "->"
                + signature(method.getName(), method.getParameterTypes(), method.getReturnType());
    }
}
