package org.skinlab.desktop.ar;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.Path;

import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilder;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.parsers.ParserConfigurationException;

import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.LensDistortion;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.xml.sax.SAXException;
import org.xml.sax.SAXParseException;
import org.yaml.snakeyaml.nodes.MappingNode;

/**
 * OpenCV's camera calibration as {@code cv::FileStorage} writes it, in YAML ({@code %YAML:1.0},
 * matrices tagged {@code !!opencv-matrix}) or XML ({@code <opencv_storage>}, matrices with
 * {@code type_id="opencv-matrix"}): the camera matrix ({@code camera_matrix}, or
 * {@code cameraMatrix} as OpenCV's interactive calibration names it), the distortion coefficients
 * ({@code distortion_coefficients}, {@code dist_coeffs}, {@code distCoeffs}) and the image size
 * ({@code image_width} and {@code image_height}, or {@code cameraResolution: [w, h]}).
 *
 * <p>OpenCV's pixel convention is ours: pixel (i, j) has its centre at (i, j) (its corner finder
 * and {@code undistort} work on pixel centres at integers), so cx and cy are taken as they are.
 * Its distortion vector is (k1, k2, p1, p2[, k3[, k4, k5, k6[, s1..s4[, tauX, tauY]]]]): 4 or 5
 * terms are Brown-Conrady; the longer rational, thin-prism and tilted models are accepted only when
 * their extra terms are all zero.
 */
final class OpenCvCalibrationFile {
    private static final String[] MATRIX_KEYS = {"camera_matrix", "cameraMatrix"};
    private static final String[] DISTORTION_KEYS = {"distortion_coefficients", "dist_coeffs", "distCoeffs"};

    private OpenCvCalibrationFile() {
    }

    /** A cv::FileStorage YAML file's calibration. */
    static CameraIntrinsics readYaml(Path file, String text) {
        // "%YAML:1.0" is OpenCV's own spelling of the YAML 1.0 directive, which YAML 1.1 parsers
        // refuse; a comment in its place keeps the line numbers of parse errors right.
        String body = text.startsWith("%YAML:") ? "#" + text : text;
        MappingNode root = YamlTree.mapping(file, YamlTree.parse(file, body), "the document");
        return build(file, new Fields() {
            @Override
            Matrix matrix(String key) {
                org.yaml.snakeyaml.nodes.Node n = YamlTree.child(root, key);
                if (n == null) {
                    return null;
                }
                MappingNode m = YamlTree.mapping(file, n, key + " (an opencv-matrix)");
                int rows = (int) YamlTree.number(file, YamlTree.require(file, m, "rows", key), key + ".rows");
                int cols = (int) YamlTree.number(file, YamlTree.require(file, m, "cols", key), key + ".cols");
                double[] data = YamlTree.numbers(file, YamlTree.require(file, m, "data", key), key + ".data");
                return Matrix.of(file, key, rows, cols, data);
            }

            @Override
            double[] numbers(String key) {
                org.yaml.snakeyaml.nodes.Node n = YamlTree.child(root, key);
                if (n == null) {
                    return null;
                }
                return n instanceof org.yaml.snakeyaml.nodes.ScalarNode
                        ? new double[] {YamlTree.number(file, n, key)} : YamlTree.numbers(file, n, key);
            }
        });
    }

    /** A cv::FileStorage XML file's calibration (a DOM parser with doctypes and external entities off). */
    static CameraIntrinsics readXml(Path file, byte[] bytes) {
        Element root;
        try {
            DocumentBuilderFactory f = DocumentBuilderFactory.newInstance();
            // No DTDs at all: OpenCV never writes one, and they carry entity expansion and external
            // fetches (XXE).
            f.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            f.setFeature("http://xml.org/sax/features/external-general-entities", false);
            f.setFeature("http://xml.org/sax/features/external-parameter-entities", false);
            f.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
            f.setXIncludeAware(false);
            f.setExpandEntityReferences(false);
            DocumentBuilder b = f.newDocumentBuilder();
            b.setErrorHandler(null);
            Document d = b.parse(new ByteArrayInputStream(bytes));
            root = d.getDocumentElement();
        } catch (SAXParseException e) {
            throw new IllegalArgumentException(file + ": not XML (line " + e.getLineNumber() + "): " + e.getMessage());
        } catch (SAXException | IOException e) {
            throw new IllegalArgumentException(file + ": not XML: " + e.getMessage());
        } catch (ParserConfigurationException e) {
            throw new IllegalStateException("the XML parser refuses the safe settings", e);
        }
        if (!"opencv_storage".equals(root.getTagName())) {
            throw new IllegalArgumentException(file + ": root element <" + root.getTagName()
                    + "> (an OpenCV calibration file has <opencv_storage>)");
        }
        return build(file, new Fields() {
            @Override
            Matrix matrix(String key) {
                Element e = childElement(root, key);
                if (e == null) {
                    return null;
                }
                String path = "<" + key + ">";
                int rows = (int) single(file, require(file, e, "rows", path), path + "<rows>");
                int cols = (int) single(file, require(file, e, "cols", path), path + "<cols>");
                double[] data = list(file, require(file, e, "data", path), path + "<data>");
                return Matrix.of(file, path, rows, cols, data);
            }

            @Override
            double[] numbers(String key) {
                Element e = childElement(root, key);
                return e == null ? null : list(file, e, "<" + key + ">");
            }
        });
    }

    private static CameraIntrinsics build(Path file, Fields fields) {
        Matrix k = first(fields, MATRIX_KEYS);
        if (k == null) {
            throw new IllegalArgumentException(file + ": no camera matrix (camera_matrix or cameraMatrix)");
        }
        if (k.rows != 3 || k.cols != 3) {
            throw new IllegalArgumentException(file + ": " + k.name + " is " + k.rows + "x" + k.cols + ", must be 3x3");
        }
        double[] m = k.data;
        if (m[3] != 0 || m[6] != 0 || m[7] != 0 || m[8] != 1) {
            throw new IllegalArgumentException(file + ": " + k.name + " is not a camera matrix [fx 0 cx; 0 fy cy; 0 0 1]");
        }
        if (Math.abs(m[1]) > 1e-9 * Math.max(m[0], m[4])) {
            throw new IllegalArgumentException(file + ": " + k.name + " has skew " + m[1] + " (only skew 0 is supported)");
        }
        Matrix dist = first(fields, DISTORTION_KEYS);
        LensDistortion lens = dist == null ? LensDistortion.NONE : lens(file, dist);
        int[] size = imageSize(file, fields);
        try {
            return new CameraIntrinsics(size[0], size[1], m[0], m[4], m[2], m[5], lens);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(file + ": " + k.name + ": " + e.getMessage());
        }
    }

    private static LensDistortion lens(Path file, Matrix dist) {
        double[] d = dist.data;
        int n = d.length;
        if (n != 4 && n != 5 && n != 8 && n != 12 && n != 14) {
            throw new IllegalArgumentException(file + ": " + dist.name + " has " + n
                    + " terms (OpenCV writes 4, 5, 8, 12 or 14)");
        }
        for (int i = 5; i < n; i++) {
            if (d[i] != 0) {
                throw new IllegalArgumentException(file + ": " + dist.name + " has " + n + " terms, term " + (i + 1)
                        + " is " + d[i] + ": " + extraModel(i) + " is not supported (only k1, k2, p1, p2, k3;"
                        + " calibrate without CALIB_RATIONAL_MODEL, CALIB_THIN_PRISM_MODEL, CALIB_TILTED_MODEL)");
            }
        }
        try {
            return new LensDistortion(d[0], d[1], n > 4 ? d[4] : 0, d[2], d[3]);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(file + ": " + dist.name + ": " + e.getMessage());
        }
    }

    /** The OpenCV model a distortion term past the fifth (0-based {@code index}) belongs to. */
    private static String extraModel(int index) {
        return index < 8 ? "the rational model (k4, k5, k6)"
                : index < 12 ? "the thin-prism model (s1, s2, s3, s4)" : "the tilted-sensor model (tauX, tauY)";
    }

    private static int[] imageSize(Path file, Fields fields) {
        double[] w = fields.numbers("image_width");
        double[] h = fields.numbers("image_height");
        if (w != null || h != null) {
            if (w == null || h == null) {
                throw new IllegalArgumentException(file + ": " + (w == null ? "image_width" : "image_height")
                        + " missing (the image size is needed: the camera matrix holds for that resolution)");
            }
            if (w.length != 1 || h.length != 1) {
                throw new IllegalArgumentException(file + ": image_width and image_height must be single numbers");
            }
            return new int[] {YamlTree.side(file, w[0], "image_width"), YamlTree.side(file, h[0], "image_height")};
        }
        double[] r = fields.numbers("cameraResolution");
        if (r == null) {
            throw new IllegalArgumentException(file + ": no image size (image_width and image_height, or"
                    + " cameraResolution): it is needed, the camera matrix holds for the resolution it was calibrated at");
        }
        if (r.length != 2) {
            throw new IllegalArgumentException(file + ": cameraResolution must be [width, height], has " + r.length
                    + " numbers");
        }
        return new int[] {YamlTree.side(file, r[0], "cameraResolution[0]"),
            YamlTree.side(file, r[1], "cameraResolution[1]")};
    }

    private static Matrix first(Fields fields, String[] keys) {
        for (String key : keys) {
            Matrix m = fields.matrix(key);
            if (m != null) {
                return m;
            }
        }
        return null;
    }

    private static Element childElement(Element parent, String name) {
        for (Node n = parent.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element && name.equals(((Element) n).getTagName())) {
                return (Element) n;
            }
        }
        return null;
    }

    private static Element require(Path file, Element parent, String name, String path) {
        Element e = childElement(parent, name);
        if (e == null) {
            throw new IllegalArgumentException(file + ": " + path + "<" + name + "> missing");
        }
        return e;
    }

    private static double single(Path file, Element e, String path) {
        double[] v = list(file, e, path);
        if (v.length != 1) {
            throw new IllegalArgumentException(file + ": " + path + " must be one number, has " + v.length);
        }
        return v[0];
    }

    /** An element's text as whitespace-separated numbers (how cv::FileStorage writes XML sequences). */
    private static double[] list(Path file, Element e, String path) {
        String text = e.getTextContent().trim();
        if (text.isEmpty()) {
            return new double[0];
        }
        String[] parts = text.split("\\s+");
        double[] out = new double[parts.length];
        for (int i = 0; i < parts.length; i++) {
            out[i] = YamlTree.parseNumber(file, parts[i], parts.length == 1 ? path : path + "[" + i + "]");
        }
        return out;
    }

    /** A file's top-level fields, YAML's or XML's; null when a key is absent. */
    private abstract static class Fields {
        abstract Matrix matrix(String key);

        abstract double[] numbers(String key);
    }

    /** An opencv-matrix: rows x cols, row-major data. */
    private static final class Matrix {
        final String name;
        final int rows;
        final int cols;
        final double[] data;

        private Matrix(String name, int rows, int cols, double[] data) {
            this.name = name;
            this.rows = rows;
            this.cols = cols;
            this.data = data;
        }

        static Matrix of(Path file, String name, int rows, int cols, double[] data) {
            if (rows < 1 || cols < 1 || (long) rows * cols != data.length) {
                throw new IllegalArgumentException(file + ": " + name + " is " + rows + "x" + cols + " but its data has "
                        + data.length + " numbers");
            }
            return new Matrix(name, rows, cols, data);
        }
    }

}
