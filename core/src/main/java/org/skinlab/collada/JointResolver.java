package org.skinlab.collada;

import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.skinlab.model.Skin;

/**
 * Resolves an {@code <instance_controller>}'s {@code <skeleton>} roots and its skin's joints to
 * nodes of the instantiated scene (COLLADA 1.4.1, skin and instance_controller): a Name_array
 * joint is the first node under the roots (roots in file order, depth-first) whose sid matches;
 * failing that, or without roots, a node whose id, then name, then sid matches, preferring the
 * copy nearest the instance when {@code <instance_node>} made several. IDREF_array joints match
 * ids. Works on the scene's flat node index: nodes depth-first, parents before children.
 */
final class JointResolver {
    private final ImportContext ctx;
    private final Map<String, IntList> byId;
    private final Map<String, IntList> bySid;
    private final Map<String, IntList> byName;
    private final int[] parents;
    private final int[] subtreeEnd;
    private final Map<String, RootScope> scopes = new HashMap<>();

    /**
     * @param byId       node indices by id (ascending), likewise {@code bySid} and {@code byName}
     * @param parents    each node's parent, or -1
     * @param subtreeEnd each node's subtree is [node, subtreeEnd[node])
     */
    JointResolver(ImportContext ctx, Map<String, IntList> byId, Map<String, IntList> bySid,
            Map<String, IntList> byName, int[] parents, int[] subtreeEnd) {
        this.ctx = ctx;
        this.byId = byId;
        this.bySid = bySid;
        this.byName = byName;
        this.parents = parents;
        this.subtreeEnd = subtreeEnd;
    }

    /** The nodes an instance's {@code <skeleton>}s name (the copy nearest the instance), in file order. */
    int[] skeletonRoots(XmlElement inst, int node) {
        IntList roots = new IntList(2);
        for (XmlElement s : inst.children("skeleton")) {
            String ref = s.text().trim();
            String id = ImportContext.idPart(ref);
            int root = nearest(byId.get(id), node);
            if (root < 0) {
                ctx.warn(s, "skeleton root \"" + ref + "\" is not a node of the scene; ignored");
            } else {
                roots.add(root);
            }
        }
        return roots.toArray();
    }

    /** The node of each joint of the skin, for the instance at {@code node} with these roots. */
    int[] joints(XmlElement inst, XmlElement controller, Skin skin, int node, int[] roots) throws ColladaException {
        RootScope scope = roots.length == 0 ? null
                : scopes.computeIfAbsent(Arrays.toString(roots), k -> new RootScope(roots));
        int[] joints = new int[skin.jointCount()];
        boolean outsideRoots = false;
        Map<String, Integer> resolved = new HashMap<>(); // joints of one skin may repeat a name
        for (int j = 0; j < joints.length; j++) {
            String name = skin.jointNames().get(j);
            Integer known = resolved.get(name);
            int found;
            if (known != null) {
                found = known;
            } else {
                found = scope == null ? -1 : scope.firstUnder((skin.jointsAreIdrefs() ? byId : bySid).get(name));
                if (found < 0) {
                    found = byIdOrName(name, skin.jointsAreIdrefs(), scope, node);
                    outsideRoots |= found >= 0 && scope != null;
                }
                resolved.put(name, found);
            }
            if (found < 0) {
                throw ctx.error(inst, "joint \"" + name + "\" of controller \"" + controller.id() + "\" matches no node"
                        + " in the scene (by " + (skin.jointsAreIdrefs() ? "id" : "sid, id or name") + ")");
            }
            joints[j] = found;
        }
        if (outsideRoots) {
            ctx.warn(inst, "some joints matched no " + (skin.jointsAreIdrefs() ? "id" : "sid")
                    + " under the <skeleton> roots and were found by id or name instead");
        }
        return joints;
    }

    /**
     * Fallback joint lookup: by id, then (for Name_array joints) by name and by sid; under the
     * skeleton roots first (when there are any), then anywhere, preferring the copy nearest the
     * instance.
     */
    private int byIdOrName(String name, boolean idrefs, RootScope scope, int node) {
        List<Map<String, IntList>> maps = idrefs ? List.of(byId) : List.of(byId, byName, bySid);
        if (scope != null) {
            for (Map<String, IntList> map : maps) {
                int found = scope.firstUnder(map.get(name));
                if (found >= 0) {
                    return found;
                }
            }
        }
        for (Map<String, IntList> map : maps) {
            int found = nearest(map.get(name), node);
            if (found >= 0) {
                return found;
            }
        }
        return -1;
    }

    /**
     * The {@code <skeleton>} roots of an instance, as a rank per node: the file-order position of
     * the first root whose subtree holds the node. "The first candidate under the first root that
     * has one" is then the candidate of lowest rank (lowest index on ties), found in one pass over
     * the candidates, whatever the number of roots: a file with many roots and many joints must
     * not cost roots x joints steps. Built once per distinct root list, in one forward pass
     * (parents come before children).
     */
    private final class RootScope {
        private final int[] rank;

        RootScope(int[] roots) {
            int n = parents.length;
            int[] own = new int[n];
            Arrays.fill(own, Integer.MAX_VALUE);
            for (int k = roots.length - 1; k >= 0; k--) {
                own[roots[k]] = k; // the first occurrence of a root wins
            }
            rank = new int[n];
            for (int i = 0; i < n; i++) {
                int inherited = parents[i] < 0 ? Integer.MAX_VALUE : rank[parents[i]];
                rank[i] = Math.min(own[i], inherited);
            }
        }

        /** The candidate under the first root that holds one (lowest index), or -1. */
        int firstUnder(IntList candidates) {
            if (candidates == null) {
                return -1;
            }
            int best = -1;
            int bestRank = Integer.MAX_VALUE;
            for (int i = 0; i < candidates.size(); i++) {
                int c = candidates.get(i);
                if (rank[c] < bestRank) {
                    best = c;
                    bestRank = rank[c];
                }
            }
            return best;
        }
    }

    /** The smallest candidate in [from, to), or -1 (binary search over the ascending list). */
    private static int firstInRange(IntList candidates, int from, int to) {
        int lo = 0;
        int hi = candidates.size();
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (candidates.get(mid) < from) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        return lo < candidates.size() && candidates.get(lo) < to ? candidates.get(lo) : -1;
    }

    /**
     * Of several nodes with the same id (copies made by instance_node), the one that shares the
     * deepest ancestor with {@code from}; the first one on ties. -1 when there is none.
     *
     * <p>Walks up from {@code from}: the first ancestor whose subtree holds a candidate is the
     * deepest common ancestor any candidate can share, and every candidate in that subtree shares
     * exactly it, so the first of them is the answer; when no ancestor holds one, all tie and the
     * first candidate wins. Cost: depth x log(candidates), not candidates x depth.
     */
    private int nearest(IntList candidates, int from) {
        if (candidates == null || candidates.size() == 0) {
            return -1;
        }
        if (candidates.size() == 1) {
            return candidates.get(0);
        }
        for (int a = from; a >= 0; a = parents[a]) {
            int c = firstInRange(candidates, a, subtreeEnd[a]);
            if (c >= 0) {
                return c;
            }
        }
        return candidates.get(0);
    }
}
