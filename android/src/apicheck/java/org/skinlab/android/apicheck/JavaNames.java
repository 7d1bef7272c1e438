package org.skinlab.android.apicheck;

import java.util.Arrays;
import java.util.stream.Collectors;

import org.objectweb.asm.Type;

/**
 * Internal names and descriptors in Java's source form for messages:
 * {@code java.nio.file.Path.of(java.lang.String, java.lang.String[])}. Nested classes keep their
 * {@code $} (the name a stack trace and the mapping file use).
 */
final class JavaNames {
    private JavaNames() {
    }

    /** {@code java/nio/file/Path} or {@code Ljava/nio/file/Path;} to {@code java.nio.file.Path}. */
    static String className(String name) {
        String internal = name.startsWith("L") && name.endsWith(";") ? name.substring(1, name.length() - 1) : name;
        return internal.replace('/', '.');
    }

    /** A member in signature form ({@code name#desc} or {@code name(args)ret}) of an owner class. */
    static String member(String owner, String member) {
        int hash = member.indexOf('#');
        if (hash >= 0) {
            return className(owner) + "." + member.substring(0, hash);
        }
        int paren = member.indexOf('(');
        return className(owner) + "." + method(member.substring(0, paren), member.substring(paren));
    }

    /** {@code name(java.lang.String, int[])} from a name and a method descriptor. */
    static String method(String name, String descriptor) {
        return name + Arrays.stream(Type.getArgumentTypes(descriptor)).map(Type::getClassName)
                .collect(Collectors.joining(", ", "(", ")"));
    }
}
