package org.skinlab.desktop.ar;

import java.nio.file.Path;

import boofcv.struct.calib.CameraPinholeBrown;
import org.skinlab.ar.BoofCameras;
import org.skinlab.ar.CameraIntrinsics;
import org.yaml.snakeyaml.nodes.MappingNode;
import org.yaml.snakeyaml.nodes.Node;

/**
 * BoofCV's {@code intrinsic.yaml} as its {@code CalibrationIO} writes it: {@code model:
 * pinhole_radial_tangential} (or {@code pinhole}), {@code pinhole: {fx, fy, cx, cy, skew, width,
 * height}} and {@code radial_tangential: {radial: [k1, k2, k3], t1, t2}}. BoofCV's principal point
 * is ours plus 0.5 ({@link BoofCameras#fromBoof} converts); a skew or more than three radial terms
 * are refused.
 */
final class BoofCvCalibrationFile {
    static final String PINHOLE = "pinhole";
    static final String BROWN = "pinhole_radial_tangential";

    private BoofCvCalibrationFile() {
    }

    /** Whether {@code root} looks like BoofCV's file (it has a {@code model}). */
    static boolean isBoof(MappingNode root) {
        return YamlTree.child(root, "model") != null;
    }

    static CameraIntrinsics read(Path file, MappingNode root) {
        String model = YamlTree.text(file, YamlTree.require(file, root, "model", ""), "model");
        if (!model.equals(PINHOLE) && !model.equals(BROWN)) {
            throw new IllegalArgumentException(file + ": model \"" + model + "\" is not supported (only " + BROWN
                    + " and " + PINHOLE + ")");
        }
        MappingNode p = YamlTree.mapping(file, YamlTree.require(file, root, "pinhole", ""), "pinhole");
        CameraPinholeBrown c = new CameraPinholeBrown();
        c.fx = number(file, p, "fx");
        c.fy = number(file, p, "fy");
        c.cx = number(file, p, "cx");
        c.cy = number(file, p, "cy");
        Node skew = YamlTree.child(p, "skew");
        c.skew = skew == null ? 0 : YamlTree.number(file, skew, "pinhole.skew");
        c.width = YamlTree.side(file, number(file, p, "width"), "pinhole.width");
        c.height = YamlTree.side(file, number(file, p, "height"), "pinhole.height");
        if (model.equals(BROWN)) {
            MappingNode d = YamlTree.mapping(file, YamlTree.require(file, root, "radial_tangential", ""),
                    "radial_tangential");
            Node radial = YamlTree.child(d, "radial");
            c.radial = radial == null ? new double[0] : YamlTree.numbers(file, radial, "radial_tangential.radial");
            if (c.radial.length > 3) {
                throw new IllegalArgumentException(file + ": radial_tangential.radial has " + c.radial.length
                        + " terms (at most 3 are supported: k1, k2, k3)");
            }
            Node t1 = YamlTree.child(d, "t1");
            Node t2 = YamlTree.child(d, "t2");
            c.t1 = t1 == null ? 0 : YamlTree.number(file, t1, "radial_tangential.t1");
            c.t2 = t2 == null ? 0 : YamlTree.number(file, t2, "radial_tangential.t2");
        }
        try {
            return BoofCameras.fromBoof(c);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(file + ": " + e.getMessage());
        }
    }

    private static double number(Path file, MappingNode map, String key) {
        return YamlTree.number(file, YamlTree.require(file, map, key, PINHOLE), PINHOLE + "." + key);
    }
}
