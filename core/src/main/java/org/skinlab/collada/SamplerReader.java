package org.skinlab.collada;

import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;

import org.skinlab.model.Interpolation;
import org.skinlab.model.KeyframeTrack;

/**
 * Reads a {@code <sampler>} (INPUT, OUTPUT, INTERPOLATION, IN_TANGENT, OUT_TANGENT) into a
 * {@link KeyframeTrack} for a target of a given width; the tangents become Bezier control points
 * through {@link CurveTangents}.
 *
 * <p>Lenient (with a warning): CARDINAL and BSPLINE keys and BEZIER/HERMITE keys without tangents
 * are read as LINEAR; a keyed matrix whose bottom row is not (0 0 0 1) keeps its values (the bottom
 * row is ignored when evaluated). Refused: INPUT and OUTPUT that disagree in key count, OUTPUT or
 * tangent widths that do not fit the target, decreasing key times.
 */
final class SamplerReader {
    private final ImportContext ctx;
    private final CurveTangents tangents;
    private final Map<XmlElement, Map<Integer, KeyframeTrack>> tracks = new IdentityHashMap<>();

    SamplerReader(ImportContext ctx, CurveTangents tangents) {
        this.ctx = ctx;
        this.tangents = tangents;
    }

    /**
     * The track of a sampler read for a target of {@code width} values; cached, since several
     * channels (or copies of an instanced node) may share a sampler. {@code blenderAngle}: the
     * target is a rotate's angle in a file Blender wrote, which may change the tangents' reading.
     */
    KeyframeTrack track(XmlElement sampler, int width, boolean matrix, boolean blenderAngle)
            throws ColladaException {
        Map<Integer, KeyframeTrack> byWidth = tracks.computeIfAbsent(sampler, s -> new HashMap<>());
        int key = blenderAngle ? -width : width; // the Blender-angle reading is cached apart from the plain one
        KeyframeTrack track = byWidth.get(key);
        if (track == null) {
            track = readSampler(sampler, width, matrix, blenderAngle);
            byWidth.put(key, track);
        }
        return track;
    }

    private KeyframeTrack readSampler(XmlElement sampler, int width, boolean matrix, boolean blenderAngle)
            throws ColladaException {
        XmlElement inputIn = null;
        XmlElement outputIn = null;
        XmlElement interpolationIn = null;
        XmlElement inTangentIn = null;
        XmlElement outTangentIn = null;
        for (XmlElement input : sampler.children("input")) {
            switch (ctx.attr(input, "semantic")) {
                case "INPUT": inputIn = input; break;
                case "OUTPUT": outputIn = input; break;
                case "INTERPOLATION": interpolationIn = input; break;
                case "IN_TANGENT": inTangentIn = input; break;
                case "OUT_TANGENT": outTangentIn = input; break;
                default: break;
            }
        }
        if (inputIn == null || outputIn == null) {
            throw ctx.error(sampler, "needs an INPUT and an OUTPUT input");
        }
        float[] times = keyTimes(inputIn);
        int keys = times.length;
        float[] values = keyValues(outputIn, keys, width, "OUTPUT");
        if (matrix) {
            for (int k = 0; k < keys; k++) {
                if (!RowMajor.checkBottomRow(ctx, values, 16 * k, outputIn, "keyed matrix " + k)) {
                    break; // one warning per track is enough
                }
            }
        }
        Interpolation[] interpolations = interpolations(interpolationIn, keys);
        float[] inTangents = null;
        float[] outTangents = null;
        if (isCurved(interpolations)) {
            if (inTangentIn == null || outTangentIn == null) {
                ctx.warn(sampler, "BEZIER/HERMITE keys without IN_TANGENT and OUT_TANGENT; read as LINEAR");
                for (int k = 0; k < keys; k++) {
                    if (isCurved(interpolations[k])) {
                        interpolations[k] = Interpolation.LINEAR;
                    }
                }
            } else {
                float[] in = tangentValues(inTangentIn, keys, width);
                float[] out = tangentValues(outTangentIn, keys, width);
                if (blenderAngle) {
                    tangents.convertBlenderRadians(sampler, in, out, values);
                }
                inTangents = CurveTangents.controlPoints(in, times, values, width, interpolations, true);
                outTangents = CurveTangents.controlPoints(out, times, values, width, interpolations, false);
            }
        }
        return new KeyframeTrack(times, values, width, interpolations, inTangents, outTangents);
    }

    /** The INPUT's key times, refused where they decrease. */
    private float[] keyTimes(XmlElement inputIn) throws ColladaException {
        Source timeSource = ctx.inputSource(inputIn);
        float[] times = timeSource.floats(ctx, inputIn, 1, "INPUT");
        for (int k = 1; k < times.length; k++) {
            if (times[k] < times[k - 1]) {
                throw ctx.error(timeSource.element, "key times decrease at key " + k + " (" + times[k - 1] + " then "
                        + times[k] + ")");
            }
        }
        return times;
    }

    /** Each key's interpolation: LINEAR without an INTERPOLATION input, and for names we do not support. */
    private Interpolation[] interpolations(XmlElement interpolationIn, int keys) throws ColladaException {
        Interpolation[] interpolations = new Interpolation[keys];
        java.util.Arrays.fill(interpolations, Interpolation.LINEAR);
        if (interpolationIn == null) {
            return interpolations;
        }
        Source s = ctx.inputSource(interpolationIn);
        String[] names = s.names(ctx, interpolationIn, "INTERPOLATION");
        if (names.length != keys) {
            throw ctx.error(interpolationIn, "INTERPOLATION has " + names.length + " entries for " + keys + " keys");
        }
        // One warning per sampler, not per key: a long CARDINAL track would otherwise fill
        // the warning list (ImportContext.MAX_WARNINGS) and hide everything else.
        Set<String> unsupported = null;
        for (int k = 0; k < keys; k++) {
            Interpolation i = interpolation(names[k]);
            if (i == null) {
                if (unsupported == null) {
                    unsupported = new LinkedHashSet<>();
                }
                unsupported.add(names[k]);
                i = Interpolation.LINEAR;
            }
            interpolations[k] = i;
        }
        if (unsupported != null) {
            ctx.warn(interpolationIn, "interpolation " + String.join(", ", unsupported)
                    + " is not supported; read as LINEAR");
        }
        return interpolations;
    }

    private static boolean isCurved(Interpolation[] interpolations) {
        boolean curved = false;
        for (Interpolation i : interpolations) {
            curved |= isCurved(i);
        }
        return curved;
    }

    /** Whether a key's curve needs tangents. */
    private static boolean isCurved(Interpolation i) {
        return i == Interpolation.BEZIER || i == Interpolation.HERMITE;
    }

    /** The interpolation of that name, or null when it is not supported (CARDINAL, BSPLINE, ...). */
    private static Interpolation interpolation(String name) {
        switch (name) {
            case "LINEAR": return Interpolation.LINEAR;
            case "STEP": return Interpolation.STEP;
            case "BEZIER": return Interpolation.BEZIER;
            case "HERMITE": return Interpolation.HERMITE;
            default: return null;
        }
    }

    /** {@code keys * width} values of an OUTPUT-like input, checked against the key count. */
    private float[] keyValues(XmlElement input, int keys, int width, String what) throws ColladaException {
        Source s = ctx.inputSource(input);
        s.requireFloats(ctx, input, what);
        if (s.count() != keys) {
            throw ctx.error(input, what + " source \"" + s.id() + "\" has " + s.count() + " entries for " + keys
                    + " keys");
        }
        if (s.width() != width) {
            throw ctx.error(input, what + " source \"" + s.id() + "\" has " + s.width()
                    + " values per key, but the channel's target takes " + width);
        }
        return s.floats(ctx, input, width, what);
    }

    /**
     * The values of an IN_TANGENT/OUT_TANGENT input as written: {@code 2 * width} per key for 2-D
     * (time, value) tangents, {@code width} per key for 1-D (value only) tangents.
     */
    private float[] tangentValues(XmlElement input, int keys, int width) throws ColladaException {
        Source s = ctx.inputSource(input);
        String semantic = input.attr("semantic");
        s.requireFloats(ctx, input, semantic);
        if (s.count() != keys) {
            throw ctx.error(input, semantic + " source \"" + s.id() + "\" has " + s.count() + " entries for " + keys
                    + " keys");
        }
        if (s.width() != 2 * width && s.width() != width) {
            throw ctx.error(input, semantic + " source \"" + s.id() + "\" has " + s.width()
                    + " values per key; expected " + (2 * width) + " (time, value per component) or " + width);
        }
        return s.floats(ctx, input, s.width(), semantic);
    }
}
