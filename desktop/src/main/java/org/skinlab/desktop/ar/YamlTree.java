package org.skinlab.desktop.ar;

import java.io.StringReader;
import java.nio.file.Path;
import java.util.List;

import org.yaml.snakeyaml.LoaderOptions;
import org.yaml.snakeyaml.Yaml;
import org.yaml.snakeyaml.constructor.SafeConstructor;
import org.yaml.snakeyaml.error.YAMLException;
import org.yaml.snakeyaml.nodes.MappingNode;
import org.yaml.snakeyaml.nodes.Node;
import org.yaml.snakeyaml.nodes.NodeTuple;
import org.yaml.snakeyaml.nodes.ScalarNode;
import org.yaml.snakeyaml.nodes.SequenceNode;

/**
 * A calibration file's YAML as SnakeYAML's node tree, and the lookups its readers need, each
 * failing with the file and the field's path. Only composed, never constructed: no Java object is
 * made from the file, so tags such as OpenCV's {@code !!opencv-matrix} are plain labels here and no
 * tag can name a class to instantiate.
 */
final class YamlTree {
    /** OpenCV's {@code !!opencv-matrix}, expanded. */
    private static final String OPENCV_MATRIX = "tag:yaml.org,2002:opencv-matrix";

    private YamlTree() {
    }

    /** The document's root node; IllegalArgumentException naming the file on a YAML error or an empty file. */
    static Node parse(Path file, String text) {
        LoaderOptions options = new LoaderOptions();
        options.setAllowDuplicateKeys(false);
        // A calibration file is a few hundred bytes; aliases have no place in one (billion laughs).
        options.setMaxAliasesForCollections(10);
        options.setCodePointLimit(1 << 20);
        // SnakeYAML refuses global tags unless let through; OpenCV's matrix tag is the only one a
        // calibration has, and composing (no construction) makes it a mere label.
        options.setTagInspector(tag -> OPENCV_MATRIX.equals(tag.getValue()));
        Node root;
        try {
            root = new Yaml(new SafeConstructor(options)).compose(new StringReader(text));
        } catch (YAMLException e) {
            throw new IllegalArgumentException(file + ": not YAML: " + e.getMessage().trim());
        }
        if (root == null) {
            throw new IllegalArgumentException(file + ": empty YAML document");
        }
        return root;
    }

    /** {@code node} as a mapping, else IllegalArgumentException naming {@code path}. */
    static MappingNode mapping(Path file, Node node, String path) {
        if (!(node instanceof MappingNode)) {
            throw new IllegalArgumentException(file + ": " + path + " must be a mapping (key: value lines)");
        }
        return (MappingNode) node;
    }

    /** The value of {@code key} in {@code map}, or null when absent. */
    static Node child(MappingNode map, String key) {
        for (NodeTuple t : map.getValue()) {
            Node k = t.getKeyNode();
            if (k instanceof ScalarNode && key.equals(((ScalarNode) k).getValue())) {
                return t.getValueNode();
            }
        }
        return null;
    }

    /** The value of {@code key}, else IllegalArgumentException "path.key missing". */
    static Node require(Path file, MappingNode map, String key, String path) {
        Node n = child(map, key);
        if (n == null) {
            throw new IllegalArgumentException(file + ": " + join(path, key) + " missing");
        }
        return n;
    }

    /** A scalar's text, else IllegalArgumentException. */
    static String text(Path file, Node node, String path) {
        if (!(node instanceof ScalarNode)) {
            throw new IllegalArgumentException(file + ": " + path + " must be a single value");
        }
        return ((ScalarNode) node).getValue();
    }

    /** A finite number (YAML 1.1's and OpenCV's spellings such as {@code 0.} and {@code 5.2e+02}). */
    static double number(Path file, Node node, String path) {
        return parseNumber(file, text(file, node, path), path);
    }

    /** A sequence of finite numbers. */
    static double[] numbers(Path file, Node node, String path) {
        if (!(node instanceof SequenceNode)) {
            throw new IllegalArgumentException(file + ": " + path + " must be a list of numbers");
        }
        List<Node> items = ((SequenceNode) node).getValue();
        double[] out = new double[items.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = number(file, items.get(i), path + "[" + i + "]");
        }
        return out;
    }

    /** {@code s} as a finite number, else IllegalArgumentException naming {@code path}. */
    static double parseNumber(Path file, String s, String path) {
        double v;
        try {
            v = Double.parseDouble(s.trim());
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(file + ": " + path + " must be a number, is \"" + s + "\"");
        }
        if (!Double.isFinite(v)) {
            throw new IllegalArgumentException(file + ": " + path + " must be finite, is " + s);
        }
        return v;
    }

    /** {@code v} as an image side: a whole number from 1 to {@link IntrinsicsFile#MAX_SIDE}. */
    static int side(Path file, double v, String path) {
        if (v != Math.rint(v) || v < 1 || v > IntrinsicsFile.MAX_SIDE) {
            throw new IllegalArgumentException(file + ": " + path + " must be a whole number of pixels from 1 to "
                    + IntrinsicsFile.MAX_SIDE + ", is " + v);
        }
        return (int) v;
    }

    static String join(String path, String key) {
        return path.isEmpty() ? key : path + "." + key;
    }
}
