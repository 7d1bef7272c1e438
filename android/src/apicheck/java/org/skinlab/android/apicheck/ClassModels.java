package org.skinlab.android.apicheck;

import java.util.HashSet;
import java.util.Map;
import java.util.Set;

import org.codehaus.mojo.animal_sniffer.Clazz;

/**
 * The classes a dex can reach at run time: its own (and, for a dex checked alone, the libraries
 * it is compiled against) and the platform's at one API level. Members resolve through the
 * hierarchy as animal-sniffer resolves them (the class, its superclasses, its interfaces;
 * constructors and initialisers are not inherited), across both kinds: a call to
 * {@code SkinlabActivity.setTitle} is found in the platform's {@code android.app.Activity}.
 */
final class ClassModels {
    /** Where a class or member was found. */
    enum Origin { PROGRAM, PLATFORM }

    private final Map<String, Clazz> program;
    private final Map<String, Clazz> platform;

    ClassModels(Map<String, Clazz> program, Map<String, Clazz> platform) {
        this.program = program;
        this.platform = platform;
    }

    /** Where the class with this internal name is defined, or null when nowhere. */
    Origin classOrigin(String name) {
        if (program.containsKey(name)) {
            return Origin.PROGRAM;
        }
        return platform.containsKey(name) ? Origin.PLATFORM : null;
    }

    /** Where the member ({@code name#desc} or {@code name(args)ret}) of owner resolves, or null. */
    Origin resolve(String owner, String member) {
        return find(owner, member, new HashSet<>());
    }

    private Origin find(String name, String member, Set<String> seen) {
        if (name == null || !seen.add(name)) {
            return null;
        }
        Clazz clazz = program.get(name);
        Origin origin = Origin.PROGRAM;
        if (clazz == null) {
            clazz = platform.get(name);
            origin = Origin.PLATFORM;
        }
        if (clazz == null) {
            return null;
        }
        if (clazz.getSignatures().contains(member)) {
            return origin;
        }
        if (member.startsWith("<")) {
            return null;
        }
        Origin inSuper = find(clazz.getSuperClass(), member, seen);
        if (inSuper != null) {
            return inSuper;
        }
        String[] interfaces = clazz.getSuperInterfaces();
        if (interfaces != null) {
            for (String i : interfaces) {
                Origin inInterface = find(i, member, seen);
                if (inInterface != null) {
                    return inInterface;
                }
            }
        }
        return null;
    }
}
