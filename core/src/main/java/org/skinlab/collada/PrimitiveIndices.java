package org.skinlab.collada;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * A primitive's index data, read and checked against its {@code count}, {@code <vcount>} and the
 * number of input offsets: one list for {@code <triangles>} and {@code <polylist>} (every
 * {@code <p>} concatenated), one per polygon, fan or strip for {@code <polygons>} (the outer ring
 * of a {@code <ph>}), {@code <trifans>} and {@code <tristrips>}.
 *
 * <p>A {@code count} attribute that disagrees with data that agree with each other is warned and
 * the data are read (exporters get it wrong); index data that do not fit the offsets are refused.
 */
final class PrimitiveIndices {
    /** The index lists. */
    final List<int[]> lists;
    /** The {@code <p>} of each list, for messages. */
    final List<XmlElement> elements;
    /** Corners per polygon ({@code <polylist>} only), else null. */
    final int[] vcount;

    private PrimitiveIndices(List<int[]> lists, List<XmlElement> elements, int[] vcount) {
        this.lists = lists;
        this.elements = elements;
        this.vcount = vcount;
    }

    /** The indices of a primitive element with {@code stride} index offsets per corner. */
    static PrimitiveIndices read(ImportContext ctx, XmlElement primitive, int count, int stride)
            throws ColladaException {
        switch (primitive.name()) {
            case "triangles":
                return triangles(ctx, primitive, count, stride);
            case "polylist":
                return polylist(ctx, primitive, count, stride);
            default:
                return polygons(ctx, primitive, count, stride);
        }
    }

    /**
     * The smallest and the largest index at each offset ({@code [0][offset]}, {@code [1][offset]}),
     * in one pass; an offset no index uses has min > max.
     */
    int[][] ranges(int stride) {
        int[] min = new int[stride];
        int[] max = new int[stride];
        Arrays.fill(min, Integer.MAX_VALUE);
        Arrays.fill(max, Integer.MIN_VALUE);
        for (int[] p : lists) {
            for (int i = 0, k = 0; i < p.length; i++) {
                int v = p[i];
                if (v < min[k]) {
                    min[k] = v;
                }
                if (v > max[k]) {
                    max[k] = v;
                }
                if (++k == stride) {
                    k = 0;
                }
            }
        }
        return new int[][] {min, max};
    }

    private static PrimitiveIndices triangles(ImportContext ctx, XmlElement primitive, int count, int stride) throws ColladaException {
        List<XmlElement> ps = primitive.children("p");
        int[] p = concatenated(ctx, ps);
        long needed = 3L * count * stride;
        if (p.length != needed) {
            XmlElement where = ps.isEmpty() ? primitive : ps.get(0);
            if (p.length % (3 * stride) != 0) {
                throw ctx.error(where, "count=\"" + count + "\" triangles with " + stride
                        + " index offsets need " + needed + " indices, <p> has " + p.length);
            }
            ctx.warn(primitive, "count=\"" + count + "\" but <p> holds " + p.length / (3 * stride)
                    + " triangles; they are read");
        }
        return new PrimitiveIndices(List.of(p), List.of(ps.isEmpty() ? primitive : ps.get(0)), null);
    }

    private static PrimitiveIndices polylist(ImportContext ctx, XmlElement primitive, int count, int stride) throws ColladaException {
        XmlElement vcountElement = primitive.child("vcount");
        List<XmlElement> ps = primitive.children("p");
        XmlElement where = ps.isEmpty() ? primitive : ps.get(0);
        int[] vcount = vcountElement == null ? new int[0] : NumberParser.ints(ctx, vcountElement, -1);
        long totalCorners = 0;
        for (int n : vcount) {
            if (n < 0) {
                throw ctx.error(vcountElement, "negative corner count " + n);
            }
            totalCorners += n;
        }
        int[] p = concatenated(ctx, ps);
        if (totalCorners * stride != p.length) {
            if (vcount.length != count) {
                throw ctx.error(vcountElement == null ? primitive : vcountElement, "count=\"" + count
                        + "\" polygons but <vcount> has " + vcount.length + " entries");
            }
            throw ctx.error(where, "<vcount> adds up to " + totalCorners + " corners, which with " + stride
                    + " index offsets need " + totalCorners * stride + " indices, <p> has " + p.length);
        }
        if (vcount.length != count) {
            // <vcount> and <p> agree with each other: the count attribute is the odd one out.
            ctx.warn(primitive, "count=\"" + count + "\" but <vcount> and <p> hold " + vcount.length
                    + " polygons; they are read");
        }
        return new PrimitiveIndices(List.of(p), List.of(where), vcount);
    }

    /** {@code <polygons>} (one polygon per {@code <p>} or {@code <ph>}), {@code <trifans>}, {@code <tristrips>}. */
    private static PrimitiveIndices polygons(ImportContext ctx, XmlElement primitive, int count, int stride) throws ColladaException {
        List<XmlElement> rings = new ArrayList<>();
        int holes = 0;
        for (XmlElement c : primitive.children()) {
            if (c.name().equals("p")) {
                rings.add(c);
            } else if (c.name().equals("ph") && primitive.name().equals("polygons")) {
                rings.add(ctx.child(c, "p"));
                holes += c.children("h").size();
            }
        }
        if (rings.size() != count) {
            ctx.warn(primitive, "count=\"" + count + "\" but it holds " + rings.size()
                    + (primitive.name().equals("polygons") ? " polygons" : " <p> elements") + "; they are read");
        }
        if (holes > 0) {
            ctx.warn(primitive, holes + " polygon holes (<h>) ignored; their outer rings are filled");
        }
        List<int[]> lists = new ArrayList<>(rings.size());
        for (XmlElement ring : rings) {
            int[] p = NumberParser.ints(ctx, ring, -1);
            if (p.length % stride != 0) {
                throw ctx.error(ring, p.length + " indices are not a multiple of the " + stride
                        + " index offsets");
            }
            lists.add(p);
        }
        return new PrimitiveIndices(lists, rings, null);
    }

    private static int[] concatenated(ImportContext ctx, List<XmlElement> ps) throws ColladaException {
        if (ps.size() == 1) {
            return NumberParser.ints(ctx, ps.get(0), -1);
        }
        IntList all = new IntList(0);
        for (XmlElement p : ps) {
            all.addAll(NumberParser.ints(ctx, p, -1));
        }
        return all.toArray();
    }
}
