package org.skinlab.collada;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

/**
 * What {@code <instance_node>} makes of the scene before anything is built: each instance's
 * target (resolved once), and the size the scene would expand to, so that cycles and instancing
 * bombs are refused up front (see {@link #checkExpandedSize}).
 */
final class InstanceExpansion {
    private final ImportContext ctx;
    /** Expanded subtree sizes, memoized across calls of {@link #checkExpandedSize}. */
    private final Map<XmlElement, Long> expandedSizes = new IdentityHashMap<>();
    /** The target of each {@code <instance_node>}. */
    private final Map<XmlElement, XmlElement> instanceTargets = new IdentityHashMap<>();

    InstanceExpansion(ImportContext ctx) {
        this.ctx = ctx;
    }

    /** The node an {@code <instance_node>} instantiates. */
    XmlElement instanceTarget(XmlElement instanceNode) throws ColladaException {
        XmlElement target = instanceTargets.get(instanceNode);
        if (target == null) {
            target = ctx.resolve(instanceNode, "url", "node");
            instanceTargets.put(instanceNode, target);
        }
        return target;
    }

    /** The error for an {@code <instance_node>} that instantiates a node containing it. */
    ColladaException cycle(XmlElement instanceNode) {
        return ctx.error(instanceNode, "instance_node url=\"" + instanceNode.attr("url")
                + "\" instantiates a node that contains it (a cycle)");
    }

    /** A node whose expanded size is being computed: its edges and the sizes summed so far. */
    private static final class SizeFrame {
        final XmlElement node;
        final List<XmlElement> edges = new ArrayList<>(4);   // child nodes and instance targets
        final List<XmlElement> via = new ArrayList<>(4);     // the <instance_node>, or null for a child
        int next;
        long size = 1;

        SizeFrame(XmlElement node) {
            this.node = node;
        }
    }

    /**
     * Refuses an instancing bomb before anything is built. Library nodes that each instance the
     * previous one ten times make a 2 KB file that expands to 10^8 nodes; building drafts up to
     * {@link SceneLoader#MAX_NODES} would cost half a second and hundreds of megabytes (an OutOfMemoryError
     * on a 128 MB heap, common on phones). So each node's expanded size is computed first, once
     * per element (memoized; iterative, since nesting and instancing depth are the file's to
     * choose), saturating above the limit, and the first node found to exceed it is named.
     * Instance cycles show up here as an edge back to a node on the current path. Called for the
     * visual scene's nodes and again for each library node the scene adds; {@code total} carries
     * the size so far, and the new total is returned.
     */
    long checkExpandedSize(List<XmlElement> tops, XmlElement scope, long total) throws ColladaException {
        Map<XmlElement, Long> sizes = expandedSizes;
        Map<XmlElement, Boolean> onPath = new IdentityHashMap<>();
        Deque<SizeFrame> path = new ArrayDeque<>();
        for (XmlElement top : tops) {
            path.push(sizeFrame(top, onPath));
            while (!path.isEmpty()) {
                SizeFrame f = path.peek();
                if (f.next < f.edges.size()) {
                    XmlElement target = f.edges.get(f.next);
                    XmlElement via = f.via.get(f.next);
                    f.next++;
                    Long known = sizes.get(target);
                    if (known != null) {
                        f.size = Math.min(SceneLoader.MAX_NODES + 1L, f.size + known);
                    } else if (onPath.containsKey(target)) {
                        throw cycle(via);
                    } else {
                        path.push(sizeFrame(target, onPath));
                    }
                    continue;
                }
                path.pop();
                onPath.remove(f.node);
                if (f.size > SceneLoader.MAX_NODES) {
                    throw ctx.error(f.node, "with its <instance_node>s it would expand to more than " + SceneLoader.MAX_NODES
                            + " nodes");
                }
                sizes.put(f.node, f.size);
                if (!path.isEmpty()) {
                    path.peek().size = Math.min(SceneLoader.MAX_NODES + 1L, path.peek().size + f.size);
                }
            }
            total += sizes.get(top);
            if (total > SceneLoader.MAX_NODES) {
                throw ctx.error(scope, "the scene's nodes would expand to more than " + SceneLoader.MAX_NODES + " nodes");
            }
        }
        return total;
    }

    private SizeFrame sizeFrame(XmlElement node, Map<XmlElement, Boolean> onPath) throws ColladaException {
        SizeFrame f = new SizeFrame(node);
        onPath.put(node, Boolean.TRUE);
        for (XmlElement c : node.children()) {
            if (c.name().equals("node")) {
                f.edges.add(c);
                f.via.add(null);
            } else if (c.name().equals("instance_node")) {
                f.edges.add(instanceTarget(c));
                f.via.add(c);
            }
        }
        return f;
    }
}
