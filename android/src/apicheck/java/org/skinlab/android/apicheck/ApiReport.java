package org.skinlab.android.apicheck;

import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;

/**
 * What the check found in one dex: how much it looked at, what passed only thanks to a guard or
 * an exceptions entry, and what fails.
 *
 * @param what               what was checked ("the APK's dex", "core")
 * @param classes            classes in the dex
 * @param platformReferences instructions and declarations naming the platform's classes and members
 * @param guarded            references above the min SDK under a high enough SDK_INT guard
 * @param allowed            references above the min SDK accepted by the exceptions file
 * @param violations         references above the min SDK without either
 * @param unusedExceptions   exceptions entries nothing in the dex needs (stale: to remove)
 */
record ApiReport(String what, int minSdk, int classes, int platformReferences, int guarded, int allowed,
        String exceptionsName, List<Violation> violations, List<ApiExceptions.Entry> unusedExceptions) {

    boolean passed() {
        return violations.isEmpty() && unusedExceptions.isEmpty();
    }

    /** One line on success; on failure, every violation and stale exception, and what to do. */
    String message() {
        String counts = what + ": " + count(classes, "class", "classes") + ", "
                + count(platformReferences, "reference", "references") + " to the platform";
        if (passed()) {
            String allowedText = allowed == 0 ? "" : String.format(Locale.ROOT, ", %d allowed by %s", allowed, exceptionsName);
            return String.format(Locale.ROOT, "api-check: %s, all at API %d (%d guarded%s)", counts, minSdk, guarded,
                    allowedText);
        }
        StringBuilder s = new StringBuilder("api-check: FAILED: ").append(counts).append('\n');
        if (!violations.isEmpty()) {
            s.append(count(violations.size(), "reference", "references"))
                    .append(String.format(Locale.ROOT, " to classes or members that API %d lacks, not under an SDK_INT guard:%n",
                            minSdk));
            s.append(violations.stream().map(Violation::format).collect(Collectors.joining("\n"))).append('\n');
            s.append(String.format(Locale.ROOT, "Levels are ranges: 'API 27-33' is in the API-33 signature, 'above API 33' "
                    + "in neither (newer, or never in Android's public API).%n"));
            s.append(String.format(Locale.ROOT, "Fix: use what API %d has, or call it only under "
                    + "'if (Build.VERSION.SDK_INT >= N)' in the same method, N at least the level's lower end "
                    + "(docs/ar.md, 'The Android app').%n", minSdk));
        }
        if (!unusedExceptions.isEmpty()) {
            s.append(exceptionsName).append(" allows references the dex no longer makes (remove them):\n");
            unusedExceptions.forEach(e -> s.append("  ").append(e.format()).append('\n'));
        }
        return s.toString().stripTrailing();
    }

    private static String count(int n, String one, String many) {
        return String.format(Locale.ROOT, "%,d %s", n, n == 1 ? one : many);
    }
}
