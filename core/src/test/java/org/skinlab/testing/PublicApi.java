package org.skinlab.testing;

import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.lang.reflect.Constructor;
import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.lang.reflect.Type;
import java.net.URISyntaxException;
import java.nio.file.FileSystem;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * A module's public API as text, one signature a line, sorted: every public type of the classes
 * folder a given class was loaded from (nested ones too, when every enclosing type is public),
 * outside the packages named {@code internal}, and
 * each one's public and protected constructors, methods and fields, with generic types as the
 * compiler keeps them. What a user of the published jar can call; {@code ApiFileTest} holds it to
 * the committed file, so that a change of the public API is a decision.
 */
public final class PublicApi {
    private PublicApi() {
    }

    /** The API of the module whose classes folder holds {@code anchor}. */
    public static List<String> of(Class<?> anchor) {
        Path classes;
        try {
            classes = Path.of(anchor.getProtectionDomain().getCodeSource().getLocation().toURI());
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
        if (Files.isRegularFile(classes)) {
            // The module as a jar (a build that tests against the archive): its entries instead of a folder.
            try (FileSystem jar = FileSystems.newFileSystem(classes)) {
                return of(anchor, jar.getPath("/"));
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        return of(anchor, classes);
    }

    private static List<String> of(Class<?> anchor, Path classes) {
        TreeSet<String> lines = new TreeSet<>();
        try (Stream<Path> files = Files.walk(classes)) {
            for (Path f : files.filter(p -> p.toString().endsWith(".class")).collect(Collectors.toList())) {
                String name = classes.relativize(f).toString().replace('/', '.').replace('\\', '.');
                name = name.substring(0, name.length() - ".class".length());
                if (name.endsWith("package-info") || name.endsWith("module-info") || name.startsWith("META-INF")) {
                    continue;
                }
                Class<?> c = Class.forName(name, false, anchor.getClassLoader());
                if (visible(c)) {
                    describe(c, lines);
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } catch (ClassNotFoundException e) {
            throw new IllegalStateException(e);
        }
        return new ArrayList<>(lines);
    }

    /**
     * Public, and so is every type it is nested in; not synthetic or anonymous; and not in a
     * package named {@code internal} (public only for skinlab's own modules, not API).
     */
    private static boolean visible(Class<?> c) {
        if (c.getPackageName().contains(".internal")) {
            return false;
        }
        for (Class<?> t = c; t != null; t = t.getEnclosingClass()) {
            if (!Modifier.isPublic(t.getModifiers()) || t.isSynthetic() || t.isAnonymousClass() || t.isLocalClass()) {
                return false;
            }
        }
        return true;
    }

    private static void describe(Class<?> c, TreeSet<String> lines) {
        String type = c.getName();
        StringBuilder head = new StringBuilder(type).append(": ").append(modifiers(c.getModifiers()
                & ~(c.isInterface() ? Modifier.ABSTRACT : 0)));
        head.append(c.isAnnotation() ? "@interface" : c.isInterface() ? "interface" : c.isEnum() ? "enum"
                : c.isRecord() ? "record" : "class");
        if (c.getGenericSuperclass() != null && c.getSuperclass() != Object.class && !c.isEnum() && !c.isRecord()) {
            head.append(" extends ").append(c.getGenericSuperclass().getTypeName());
        }
        Type[] interfaces = c.getGenericInterfaces();
        if (interfaces.length > 0) {
            head.append(c.isInterface() ? " extends " : " implements ").append(Arrays.stream(interfaces)
                    .map(Type::getTypeName).collect(Collectors.joining(", ")));
        }
        lines.add(head.toString());
        for (Constructor<?> k : c.getDeclaredConstructors()) {
            if (exposed(k.getModifiers()) && !k.isSynthetic()) {
                lines.add(type + ": " + modifiers(k.getModifiers()) + "<init>(" + types(k.getGenericParameterTypes())
                        + ")" + throwsClause(k.getGenericExceptionTypes()));
            }
        }
        for (Method m : c.getDeclaredMethods()) {
            if (exposed(m.getModifiers()) && !m.isSynthetic() && !m.isBridge()) {
                int mods = m.getModifiers() & ~(c.isInterface() ? Modifier.ABSTRACT | Modifier.PUBLIC : 0);
                lines.add(type + ": " + modifiers(mods) + (m.isDefault() ? "default " : "")
                        + m.getGenericReturnType().getTypeName() + " " + m.getName() + "("
                        + types(m.getGenericParameterTypes()) + ")" + throwsClause(m.getGenericExceptionTypes()));
            }
        }
        for (Field f : c.getDeclaredFields()) {
            if (exposed(f.getModifiers()) && !f.isSynthetic() && !f.isEnumConstant()) {
                lines.add(type + ": " + modifiers(f.getModifiers()) + f.getGenericType().getTypeName() + " "
                        + f.getName());
            } else if (f.isEnumConstant()) {
                lines.add(type + ": enum constant " + f.getName());
            }
        }
    }

    private static boolean exposed(int modifiers) {
        return Modifier.isPublic(modifiers) || Modifier.isProtected(modifiers);
    }

    private static String modifiers(int modifiers) {
        String m = Modifier.toString(modifiers & (Modifier.PUBLIC | Modifier.PROTECTED | Modifier.STATIC
                | Modifier.FINAL | Modifier.ABSTRACT));
        return m.isEmpty() ? "" : m + " ";
    }

    private static String types(Type[] types) {
        return Arrays.stream(types).map(Type::getTypeName).collect(Collectors.joining(", "));
    }

    private static String throwsClause(Type[] exceptions) {
        return exceptions.length == 0 ? "" : " throws " + types(exceptions);
    }

    /**
     * Fails, listing the lines that differ, unless {@code committed} holds {@code api} (then writes the
     * code's API into the module's build folder); fails too when the API names a type of a package
     * named internal, which would make it API after all.
     */
    public static void check(List<String> api, Path committed) throws IOException {
        List<String> leaks = api.stream().filter(line -> line.contains(".internal.")).collect(Collectors.toList());
        if (!leaks.isEmpty()) {
            fail("The public API names types of packages named internal, which are not API: make those types"
                    + " API, or keep them out of public signatures:\n  " + String.join("\n  ", leaks));
        }
        List<String> have = Files.isRegularFile(committed) ? Files.readAllLines(committed) : List.of();
        if (have.equals(api)) {
            return;
        }
        Path proposal = committed.resolveSibling("build").resolve(committed.getFileName());
        Files.createDirectories(proposal.getParent());
        Files.write(proposal, api);
        List<String> added = new ArrayList<>(api);
        added.removeAll(have);
        List<String> removed = new ArrayList<>(have);
        removed.removeAll(api);
        fail("The public API differs from " + TestPaths.root().relativize(committed) + " (" + added.size()
                + " line(s) added, " + removed.size() + " removed). If the change is meant, accept it:\n  cp "
                + TestPaths.root().relativize(proposal) + " " + TestPaths.root().relativize(committed)
                + "\nAdded:\n  " + String.join("\n  ", added.subList(0, Math.min(40, added.size())))
                + "\nRemoved:\n  " + String.join("\n  ", removed.subList(0, Math.min(40, removed.size()))));
    }
}
