package org.skinlab.desktop.ar;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.ar.CameraIntrinsics;

/**
 * The camera intrinsics file of {@code skinlab track} and {@code skinlab ar}: one JSON object
 * {@code {"width","height","fx","fy","cx","cy"}} (pixels; pixel (i, j) centred at (i, j)). Other
 * fields are ignored. Every problem is reported with the file and the field.
 */
public final class IntrinsicsFile {
    private static final String[] FIELDS = {"width", "height", "fx", "fy", "cx", "cy"};
    /** The largest image side a camera file may name (a 64k-pixel-wide sensor is far beyond any camera's). */
    static final int MAX_SIDE = 65_536;

    private IntrinsicsFile() {
    }

    /** Reads {@code file}; IllegalArgumentException naming the file and field on any problem. */
    public static CameraIntrinsics read(Path file) throws IOException {
        JsonNode root;
        try (InputStream in = Files.newInputStream(file)) {
            // Bytes, not a string: the parser detects the encoding and reports bad bytes as JSON errors.
            root = new ObjectMapper().enable(DeserializationFeature.FAIL_ON_TRAILING_TOKENS).readTree(in);
        } catch (JsonProcessingException e) {
            throw new IllegalArgumentException(file + ": not JSON: " + e.getOriginalMessage());
        }
        if (root == null || !root.isObject()) {
            throw new IllegalArgumentException(file + ": expected one JSON object {\"width\",\"height\",\"fx\",\"fy\",\"cx\",\"cy\"}");
        }
        double[] v = new double[FIELDS.length];
        for (int i = 0; i < FIELDS.length; i++) {
            JsonNode n = root.get(FIELDS[i]);
            if (n == null) {
                throw new IllegalArgumentException(file + ": field \"" + FIELDS[i] + "\" missing");
            }
            if (!n.isNumber() || !Double.isFinite(n.asDouble())) {
                throw new IllegalArgumentException(file + ": field \"" + FIELDS[i] + "\" must be a finite number, is " + n);
            }
            v[i] = n.asDouble();
        }
        for (int i = 0; i < 2; i++) {
            if (v[i] != Math.rint(v[i]) || v[i] < 1 || v[i] > MAX_SIDE) {
                throw new IllegalArgumentException(file + ": field \"" + FIELDS[i] + "\" must be a whole number of pixels"
                        + " from 1 to " + MAX_SIDE + ", is " + v[i]);
            }
        }
        try {
            return new CameraIntrinsics((int) v[0], (int) v[1], v[2], v[3], v[4], v[5]);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(file + ": " + e.getMessage());
        }
    }

    /** Writes {@code k} to {@code file} in the same format, the lens terms k1, k2, k3, p1, p2 when it has a lens. */
    public static void write(CameraIntrinsics k, Path file) throws IOException {
        ObjectMapper mapper = new ObjectMapper();
        ObjectNode o = mapper.createObjectNode();
        o.put("width", k.width());
        o.put("height", k.height());
        o.put("fx", k.fx());
        o.put("fy", k.fy());
        o.put("cx", k.cx());
        o.put("cy", k.cy());
        if (k.isDistorted()) {
            o.put("k1", k.distortion().k1());
            o.put("k2", k.distortion().k2());
            o.put("k3", k.distortion().k3());
            o.put("p1", k.distortion().p1());
            o.put("p2", k.distortion().p2());
        }
        Files.writeString(file, mapper.writerWithDefaultPrettyPrinter().writeValueAsString(o) + "\n");
    }

    /**
     * The intrinsics for images of {@code width x height}: {@code k} itself, or scaled when the
     * image has the same aspect (within 1%: a calibration at full resolution used on a smaller
     * stream); otherwise IllegalArgumentException naming {@code what}.
     */
    public static CameraIntrinsics forImage(CameraIntrinsics k, int width, int height, String what) {
        if (k.width() == width && k.height() == height) {
            return k;
        }
        double a = (double) k.width() / k.height();
        double b = (double) width / height;
        if (Math.abs(a / b - 1) > 0.01) {
            throw new IllegalArgumentException(what + " is " + width + "x" + height + ", the intrinsics are for "
                    + k.width() + "x" + k.height() + " (another aspect ratio)");
        }
        return k.scaledTo(width, height);
    }
}
