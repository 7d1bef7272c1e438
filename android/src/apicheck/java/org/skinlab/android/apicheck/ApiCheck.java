package org.skinlab.android.apicheck;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.jf.dexlib2.iface.ClassDef;
import org.jf.dexlib2.iface.Method;

/**
 * Checks that a dex runs at the min SDK: every class and member it names from outside itself
 * must be in the platform's API at the min SDK (animal-sniffer's signature), unless the code
 * reaching it runs only when SDK_INT is at least the level where it appears ({@link SdkIntBounds};
 * R8's API outlines are judged at their call sites), or the exceptions file allows it.
 */
final class ApiCheck {
    private final ClassModels atMinSdk;
    private final ClassModels newer;
    private final int minSdk;
    private final ApiExceptions exceptions;

    /**
     * @param atMinSdk   the dex's classes (and any libraries it was compiled against) with the
     *                   platform at the min SDK
     * @param newer      the same with the platform at API 33 (to tell a missing member's level)
     * @param exceptions the reviewed exceptions
     */
    ApiCheck(ClassModels atMinSdk, ClassModels newer, int minSdk, ApiExceptions exceptions) {
        this.atMinSdk = atMinSdk;
        this.newer = newer;
        this.minSdk = minSdk;
        this.exceptions = exceptions;
    }

    ApiReport run(String what, DexProgram program) {
        Map<String, DexMethod> methods = new HashMap<>();
        Map<String, List<MethodBounds.CallSite>> outlineCalls = new HashMap<>();
        List<Located> missing = new ArrayList<>();
        Tally tally = new Tally();
        for (ClassDef c : program.classes()) {
            for (Reference r : DexReferences.ofDeclaration(c)) {
                tally.count(new Located(r, null, c), missing);
            }
            for (Method m : c.getMethods()) {
                if (m.getImplementation() == null) {
                    continue;
                }
                DexMethod method = new DexMethod(c, m);
                methods.put(method.key(), method);
                for (Reference r : DexReferences.ofCode(m.getImplementation())) {
                    if (r.use() == Reference.Use.CALLS && r.owner().contains(DexMethod.API_OUTLINE)) {
                        outlineCalls.computeIfAbsent("L" + r.owner() + ";->" + r.member(), k -> new ArrayList<>())
                                .add(new MethodBounds.CallSite(method.key(), r.index(), r.address()));
                    }
                    tally.count(new Located(r, method, c), missing);
                }
            }
        }
        MethodBounds bounds = new MethodBounds(methods, outlineCalls, minSdk);
        for (Located m : missing) {
            tally.judge(m, bounds, methods);
        }
        List<ApiExceptions.Entry> unused = exceptions.entries().stream().filter(e -> !tally.used.contains(e)).toList();
        return new ApiReport(what, minSdk, program.classes().size(), tally.platform, tally.guarded, tally.allowed,
                exceptions.name(), List.copyOf(tally.violations.values()), unused);
    }

    /** A reference and where it is: a method's code, or (method null) the class's declaration. */
    private record Located(Reference ref, DexMethod method, ClassDef declaring) {
    }

    /** The counts and findings of one run. */
    private final class Tally {
        int platform;
        int guarded;
        int allowed;
        final Set<ApiExceptions.Entry> used = new HashSet<>();
        final Map<String, Violation> violations = new LinkedHashMap<>();

        /** Counts a reference to the platform; one the min SDK lacks is kept to be judged. */
        void count(Located candidate, List<Located> missing) {
            ClassModels.Origin origin = resolve(atMinSdk, candidate.ref());
            if (origin == ClassModels.Origin.PROGRAM) {
                return;
            }
            platform++;
            if (origin == null) {
                missing.add(candidate);
            }
        }

        void judge(Located m, MethodBounds bounds, Map<String, DexMethod> methods) {
            Reference r = m.ref();
            LevelRange level = resolve(newer, r) != null ? LevelRange.API_27_TO_33 : LevelRange.ABOVE_API_33;
            if (m.method() == null) {
                // A class whose superclass or interface is missing fails to load: no guard helps.
                String className = JavaNames.className(m.declaring().getType());
                String file = m.declaring().getSourceFile() == null ? "no source file" : m.declaring().getSourceFile();
                Violation v = new Violation(className, null, file, r.use(), r.text(), level, null);
                violations.putIfAbsent(className + " " + r.use() + " " + r.text(), v);
                return;
            }
            int inside = bounds.at(m.method().key(), r.index());
            List<MethodBounds.Site> sites = m.method().isApiOutline() ? bounds.sitesOf(m.method().key()) : List.of();
            if (sites.isEmpty()) {
                judgeAt(m.method(), r.address(), inside, r, level, null);
            }
            String outline = m.method().className() + "." + m.method().display();
            for (MethodBounds.Site site : sites) {
                judgeAt(methods.get(site.method()), site.address(), Math.max(inside, site.bound()), r, level, outline);
            }
        }

        private void judgeAt(DexMethod where, int address, int bound, Reference r, LevelRange level, String outline) {
            // An instruction no path reaches (bound UNREACHED) never runs: it passes as guarded.
            if (bound >= level.lowest) {
                guarded++;
                return;
            }
            ApiExceptions.Entry entry = exceptions.find(r.text(), where.className());
            if (entry != null) {
                allowed++;
                used.add(entry);
                return;
            }
            Violation v = new Violation(where.className(), where.display(), where.source(address), r.use(), r.text(), level,
                    outline);
            violations.putIfAbsent(v.className() + "." + v.method() + " " + r.use() + " " + r.text(), v);
        }
    }

    private static ClassModels.Origin resolve(ClassModels models, Reference r) {
        return r.member() == null ? models.classOrigin(r.owner()) : models.resolve(r.owner(), r.member());
    }
}
