package org.skinlab.desktop.ar;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.LensDistortion;
import org.yaml.snakeyaml.nodes.MappingNode;

/**
 * The camera intrinsics file of {@code skinlab track} and {@code skinlab ar}. Ours is one JSON
 * object {@code {"width","height","fx","fy","cx","cy"}} (pixels; pixel (i, j) centred at (i, j))
 * with the lens' Brown-Conrady terms {@code "k1","k2","k3","p1","p2"} optional (absent: 0; written
 * when any is not zero); other fields are ignored. {@link #read} also takes OpenCV's calibration
 * files, YAML or XML ({@link OpenCvCalibrationFile}), and BoofCV's {@code intrinsic.yaml}
 * ({@link BoofCvCalibrationFile}), told apart by the extension ({@code .json}, {@code .xml},
 * {@code .yaml}/{@code .yml}) or, for any other name, by the content. Every problem is reported
 * with the file and the field.
 */
public final class IntrinsicsFile {
    private static final String[] FIELDS = {"width", "height", "fx", "fy", "cx", "cy"};
    private static final String[] LENS = {"k1", "k2", "k3", "p1", "p2"};
    /** The largest image side a camera file may name (a 64k-pixel-wide sensor is far beyond any camera's). */
    static final int MAX_SIDE = 65_536;
    /** Larger than any calibration file: a wrong path to a video is refused before it is read whole. */
    private static final long MAX_BYTES = 1 << 20;

    private IntrinsicsFile() {
    }

    /** Reads {@code file} in any of the formats above; IllegalArgumentException naming the file and field on any problem. */
    public static CameraIntrinsics read(Path file) throws IOException {
        long size = Files.size(file);
        if (size > MAX_BYTES) {
            throw new IllegalArgumentException(file + ": " + size + " bytes, too large for a calibration file");
        }
        byte[] bytes = Files.readAllBytes(file);
        String name = file.getFileName() == null ? "" : file.getFileName().toString().toLowerCase(Locale.ROOT);
        String text = new String(bytes, StandardCharsets.UTF_8);
        String start = text.replaceFirst("^\\uFEFF", "").stripLeading();
        if (name.endsWith(".json") || (!name.endsWith(".xml") && !isYamlName(name) && start.startsWith("{"))) {
            return readJson(file, bytes);
        }
        if (name.endsWith(".xml") || (!isYamlName(name) && start.startsWith("<"))) {
            return OpenCvCalibrationFile.readXml(file, bytes);
        }
        if (start.startsWith("%YAML:")) {
            return OpenCvCalibrationFile.readYaml(file, start);
        }
        MappingNode root = YamlTree.mapping(file, YamlTree.parse(file, text), "the document");
        if (BoofCvCalibrationFile.isBoof(root)) {
            return BoofCvCalibrationFile.read(file, root);
        }
        if (YamlTree.child(root, "camera_matrix") != null || YamlTree.child(root, "cameraMatrix") != null) {
            return OpenCvCalibrationFile.readYaml(file, text);
        }
        throw new IllegalArgumentException(file + ": not a camera calibration this program reads (our JSON,"
                + " OpenCV's YAML or XML with camera_matrix, BoofCV's YAML with model: pinhole_radial_tangential)");
    }

    private static boolean isYamlName(String name) {
        return name.endsWith(".yaml") || name.endsWith(".yml");
    }

    /** Our JSON format. */
    private static CameraIntrinsics readJson(Path file, byte[] bytes) throws IOException {
        JsonNode root;
        try {
            // Bytes, not a string: the parser detects the encoding and reports bad bytes as JSON errors.
            root = new ObjectMapper().enable(DeserializationFeature.FAIL_ON_TRAILING_TOKENS).readTree(bytes);
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
            v[i] = jsonNumber(file, FIELDS[i], n);
        }
        for (int i = 0; i < 2; i++) {
            if (v[i] != Math.rint(v[i]) || v[i] < 1 || v[i] > MAX_SIDE) {
                throw new IllegalArgumentException(file + ": field \"" + FIELDS[i] + "\" must be a whole number of pixels"
                        + " from 1 to " + MAX_SIDE + ", is " + v[i]);
            }
        }
        double[] d = new double[LENS.length];
        for (int i = 0; i < LENS.length; i++) {
            JsonNode n = root.get(LENS[i]);
            d[i] = n == null ? 0 : jsonNumber(file, LENS[i], n);
        }
        try {
            return new CameraIntrinsics((int) v[0], (int) v[1], v[2], v[3], v[4], v[5],
                    new LensDistortion(d[0], d[1], d[2], d[3], d[4]));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(file + ": " + e.getMessage());
        }
    }

    private static double jsonNumber(Path file, String field, JsonNode n) {
        if (!n.isNumber() || !Double.isFinite(n.asDouble())) {
            throw new IllegalArgumentException(file + ": field \"" + field + "\" must be a finite number, is " + n);
        }
        return n.asDouble();
    }

    /** Writes {@code k} to {@code file} in our JSON format (the lens' terms when it has any). */
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
            LensDistortion d = k.distortion();
            o.put("k1", d.k1());
            o.put("k2", d.k2());
            o.put("k3", d.k3());
            o.put("p1", d.p1());
            o.put("p2", d.p2());
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
