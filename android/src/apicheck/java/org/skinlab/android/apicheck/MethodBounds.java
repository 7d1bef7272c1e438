package org.skinlab.android.apicheck;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The SDK_INT bounds of the dex's methods (computed once per method, only for those asked about),
 * and where R8's API outlines are called from. R8 moves each call to an API above the min SDK into
 * a synthetic outline method and leaves the guard, if any, at the call site: a reference inside
 * an outline is judged at the outline's call sites (through outlines calling outlines, if any).
 */
final class MethodBounds {
    /** A call to an outline method: the calling method, the instruction's index and address. */
    record CallSite(String method, int index, int address) {
    }

    /** A call site outside the outlines, with the SDK_INT bound along the way to the outlined call. */
    record Site(String method, int address, int bound) {
    }

    private final Map<String, DexMethod> methods;
    private final Map<String, List<CallSite>> outlineCalls;
    private final int minSdk;
    private final Map<String, int[]> computed = new HashMap<>();

    MethodBounds(Map<String, DexMethod> methods, Map<String, List<CallSite>> outlineCalls, int minSdk) {
        this.methods = methods;
        this.outlineCalls = outlineCalls;
        this.minSdk = minSdk;
    }

    /** The lowest SDK_INT at the method's instruction (entered at the min SDK). */
    int at(String method, int index) {
        return computed.computeIfAbsent(method, key -> {
            DexMethod m = methods.get(key);
            return SdkIntBounds.of(ControlFlow.of(m.code()), m.code().getRegisterCount(), minSdk);
        })[index];
    }

    /** Where an outline method is called from outside the outlines; empty when nowhere. */
    List<Site> sitesOf(String outline) {
        return sitesOf(outline, new HashSet<>(Set.of(outline)));
    }

    private List<Site> sitesOf(String outline, Set<String> visiting) {
        List<Site> sites = new ArrayList<>();
        for (CallSite call : outlineCalls.getOrDefault(outline, List.of())) {
            int here = at(call.method(), call.index());
            boolean nested = methods.get(call.method()).isApiOutline() && visiting.add(call.method());
            List<Site> further = nested ? sitesOf(call.method(), visiting) : List.of();
            if (further.isEmpty()) {
                sites.add(new Site(call.method(), call.address(), here));
            }
            for (Site s : further) {
                sites.add(new Site(s.method(), s.address(), Math.max(here, s.bound())));
            }
            if (nested) {
                visiting.remove(call.method());
            }
        }
        return sites;
    }
}
