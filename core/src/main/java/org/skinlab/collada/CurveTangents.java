package org.skinlab.collada;

import java.util.ArrayList;
import java.util.List;

import org.skinlab.model.Interpolation;
import org.skinlab.model.KeyframeTrack;

/**
 * A sampler's IN_TANGENT/OUT_TANGENT values, as the file writes them, turned into the control
 * points of the cubic Bezier of each segment ({@link #controlPoints}), whatever form the file uses
 * (2-D or 1-D, BEZIER or HERMITE), so the sampler has one evaluation path. The formulas and their
 * sources are at each method; docs/animation.md ("Curves between keys") checks them against
 * Blender.
 *
 * <p>One exporter habit is repaired here: Blender's exporter writes the tangents of bone rotation
 * angles in radians; such tracks are recognised ({@link #blenderRadians}) and converted, with one
 * warning per file ({@link #warnRadianTangents}).
 */
final class CurveTangents {
    private final ImportContext ctx;
    /** True when {@code <asset>} names Blender as the authoring tool (see {@link #blenderRadians}). */
    private final boolean fromBlender;
    /** Samplers whose tangent values were converted from radians to degrees (one warning for all). */
    private final List<XmlElement> radianTangentSamplers = new ArrayList<>();

    /**
     * @param authoringTool the document's authoring tool as {@code ColladaImporter} read it from
     *                      {@code <asset>} ({@code AssetInfo.authoringTool()}), or null
     */
    CurveTangents(ImportContext ctx, String authoringTool) {
        this.ctx = ctx;
        this.fromBlender = authoringTool != null && authoringTool.startsWith("Blender");
    }

    /** Whether the file is Blender's, whose angle tracks may hold radian tangents. */
    boolean fromBlender() {
        return fromBlender;
    }

    /**
     * The in- and out-tangents of a Blender angle track, converted in place from radians to
     * degrees when {@link #blenderRadians} says they hold radians.
     */
    void convertBlenderRadians(XmlElement sampler, float[] in, float[] out, float[] values) {
        if (blenderRadians(in, out, values)) {
            for (int i = 1; i < in.length; i += 2) {
                in[i] = (float) Math.toDegrees(in[i]);
                out[i] = (float) Math.toDegrees(out[i]);
            }
            radianTangentSamplers.add(sampler);
        }
    }

    /** The one warning for every sampler {@link #convertBlenderRadians} converted, if any. */
    void warnRadianTangents() {
        if (!radianTangentSamplers.isEmpty()) {
            ctx.warn(radianTangentSamplers.get(0), radianTangentSamplers.size() + " BEZIER track(s) of <rotate> angles"
                    + " have tangent values in radians while their OUTPUT is in degrees (Blender's exporter writes"
                    + " bone rotation tangents so); the tangent values were converted to degrees, as Blender plays"
                    + " them. Rule: authoring tool \"Blender...\", channel on a rotate's ANGLE, 2-D tangents whose"
                    + " values lie nearer OUTPUT * pi/180 than OUTPUT (docs/importer.md)");
        }
    }

    /**
     * Whether the 2-D tangents of a one-value angle track from Blender hold radians. Blender's
     * COLLADA exporter (verified on 3.4.1; the same code is in the newest exporter source we read,
     * see docs/importer.md) writes the OUTPUT of a bone's rotation in degrees but the value
     * coordinate of its Bezier handles in radians: {@code AnimationExporter::collada_tangent_from_curve}
     * converts only when the channel name starts with "rotation", and for bone curves that name is
     * {@code ["Bone"].rotation_euler}. Handles sit near their keys, so the values say which unit
     * they are in: radians when {@code sum |h - v pi/180| <= sum |h - v|} over every handle h and
     * its key's value v. A file whose tangents are already in degrees (an object's rotation, which
     * Blender converts, or a fixed exporter) fails that test and is left alone. A tie (every key
     * value 0, where the file cannot tell) goes to radians, as the exporter's code writes them.
     * 1-D tangents (Blender never writes them) are never converted.
     */
    private static boolean blenderRadians(float[] in, float[] out, float[] values) {
        if (in.length != 2 * values.length || out.length != 2 * values.length) {
            return false;
        }
        double radians = 0;
        double degrees = 0;
        for (int k = 0; k < values.length; k++) {
            double v = values[k];
            double r = Math.toRadians(v);
            radians += Math.abs(in[2 * k + 1] - r) + Math.abs(out[2 * k + 1] - r);
            degrees += Math.abs(in[2 * k + 1] - v) + Math.abs(out[2 * k + 1] - v);
        }
        return radians <= degrees;
    }

    /**
     * Tangents as written, turned into the control points of the cubic Bezier of the segment that
     * uses them: {@code (time, value)}, 2 * width floats per key, the layout of
     * {@link KeyframeTrack}. Key k's out-tangent belongs to segment [k, k+1] and is read by key
     * k's interpolation; key k's in-tangent belongs to segment [k-1, k] and is read by key k-1's
     * interpolation (key 0's in-tangent, used by no segment, by key 0's). Per the COLLADA 1.4.1
     * release notes and the 1.5 specification ("Curve Interpolation", animation curves), with
     * P = (INPUT, OUTPUT) of a key:
     * <ul>
     * <li><b>BEZIER, 2-D</b>: the tangent is the control point: C0 = OUT_TANGENT[k],
     *     C1 = IN_TANGENT[k+1]. Kept as written.</li>
     * <li><b>HERMITE, 2-D</b>: the tangent T = (dt/ds, dv/ds) is the derivative of the segment's
     *     curve P(s), s in [0, 1], at its end. The Hermite cubic with P0, T0, P1, T1 is exactly the
     *     Bezier with C0 = P0 + T0/3 and C1 = P1 - T1/3 (both have the same end points and end
     *     derivatives, B'(0) = 3 (C0 - P0), B'(1) = 3 (P1 - C1)): one rounding in float.</li>
     * <li><b>1-D</b> (value only; older exporters, ColladaMaya/FCollada 1.x): time is linear in s,
     *     the control times sit a third of the way to the neighbouring key. HERMITE: T = dv/ds as
     *     above, so the values are P0 + T0/3 and P1 - T1/3. BEZIER: the tangent is the control
     *     value relative to its key, v0 + OUT_TANGENT[k] and v1 - IN_TANGENT[k+1], as FCollada 1.x,
     *     the library that wrote these files, evaluates them ({@code FCDAnimationCurve::Evaluate}).
     *     Reading them as absolute control values would turn the zero tangents of a peak (the CTS
     *     files' keys "0 50" with tangents "0 0") into spikes.</li>
     * </ul>
     * The end keys' unused tangents get a time offset of 0.
     */
    static float[] controlPoints(float[] tangents, float[] times, float[] values, int width,
            Interpolation[] interpolations, boolean in) {
        int keys = times.length;
        boolean twoD = tangents.length == 2 * keys * width;
        float[] out = new float[2 * keys * width];
        float sign = in ? -1f : 1f;
        for (int k = 0; k < keys; k++) {
            int segment = in ? Math.max(k - 1, 0) : k;
            boolean hermite = interpolations[segment] == Interpolation.HERMITE;
            // 1-D: the neighbouring interval (0 at the ends, where the tangent is unused).
            float span = in ? (k > 0 ? times[k] - times[k - 1] : 0f) : (k + 1 < keys ? times[k + 1] - times[k] : 0f);
            for (int c = 0; c < width; c++) {
                int o = 2 * (k * width + c);
                float v = values[k * width + c];
                if (twoD) {
                    float tt = tangents[o];
                    float tv = tangents[o + 1];
                    out[o] = hermite ? times[k] + sign * tt / 3f : tt;
                    out[o + 1] = hermite ? v + sign * tv / 3f : tv;
                } else {
                    float t = tangents[k * width + c];
                    out[o] = times[k] + sign * span / 3f;
                    out[o + 1] = v + sign * (hermite ? t / 3f : t);
                }
            }
        }
        return out;
    }
}
