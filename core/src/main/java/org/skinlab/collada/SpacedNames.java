package org.skinlab.collada;

import java.util.Arrays;
import java.util.Set;

/**
 * Names with spaces in a {@code Name_array} or {@code IDREF_array}: the FBX COLLADA exporter writes
 * 3ds Max Biped joints as they are named ("Bip01 L Calf"), so the array's whitespace-separated
 * tokens outnumber its {@code count}, and reading the tokens as names would leave every joint
 * unmatched. The names are recovered by splitting the tokens into runs that are each the id, sid
 * or name of a node of the document, preferring longer runs (Biped names such as "Bip01" and
 * "Bip01 Spine" are prefixes of each other), and accepted only when there are exactly
 * {@code count} of them.
 */
final class SpacedNames {
    /** No node name of a real file has more words than this. */
    private static final int MAX_WORDS = 8;

    private SpacedNames() {
    }

    /**
     * The names rejoined to {@code count} node names (warned), or the tokens unchanged when no
     * such split exists (the count mismatch is then warned by the caller).
     */
    static String[] rejoin(ImportContext ctx, XmlElement array, String[] tokens, int count) {
        Set<String> known = ctx.nodeNames();
        int n = tokens.length;
        // From the end (dynamic programming over positions): next[i] is the length of the longest
        // run at i after which the rest splits too, remaining[i] the names of that split (-1: none).
        int[] remaining = new int[n + 1];
        Arrays.fill(remaining, -1);
        remaining[n] = 0;
        int[] next = new int[n + 1];
        for (int i = n - 1; i >= 0; i--) {
            StringBuilder run = new StringBuilder();
            int best = -1;
            for (int k = 1; k <= MAX_WORDS && i + k <= n; k++) {
                run.append(k == 1 ? "" : " ").append(tokens[i + k - 1]);
                if (remaining[i + k] >= 0 && known.contains(run.toString())) {
                    best = k; // longest run wins
                }
            }
            if (best > 0) {
                next[i] = best;
                remaining[i] = remaining[i + best] + 1;
            }
        }
        if (remaining[0] != count) {
            return tokens;
        }
        String[] names = new String[count];
        for (int i = 0, j = 0; i < n; i += next[i]) {
            names[j++] = String.join(" ", Arrays.copyOfRange(tokens, i, i + next[i]));
        }
        ctx.warn(array, "count=\"" + count + "\" but " + n + " words: the names have spaces in them (3ds Max Biped"
                + " through the FBX exporter); split into " + count + " by the scene's node names");
        return names;
    }
}
