package org.skinlab.model;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

/** {@link AssetInfo#toYUpMeters}: each convention's (right, up, in) axes land on (+X, +Y, +Z). */
class AssetInfoTest {
    private static final float EPS = 1e-6f;

    private static Vector3f convert(UpAxis up, double meter, float x, float y, float z) {
        Matrix4f m = new AssetInfo(up, meter, "unit", null, true).toYUpMeters(new Matrix4f());
        return m.transformPosition(new Vector3f(x, y, z));
    }

    private static void assertVector(float x, float y, float z, Vector3f v) {
        assertEquals(x, v.x, EPS, v::toString);
        assertEquals(y, v.y, EPS, v::toString);
        assertEquals(z, v.z, EPS, v::toString);
    }

    @Test
    void zUpRightUpInBecomeXYZ() {
        assertVector(1, 0, 0, convert(UpAxis.Z_UP, 1, 1, 0, 0));   // right +X
        assertVector(0, 1, 0, convert(UpAxis.Z_UP, 1, 0, 0, 1));   // up +Z
        assertVector(0, 0, 1, convert(UpAxis.Z_UP, 1, 0, -1, 0));  // in -Y
    }

    @Test
    void xUpRightUpInBecomeXYZ() {
        assertVector(1, 0, 0, convert(UpAxis.X_UP, 1, 0, -1, 0));  // right -Y
        assertVector(0, 1, 0, convert(UpAxis.X_UP, 1, 1, 0, 0));   // up +X
        assertVector(0, 0, 1, convert(UpAxis.X_UP, 1, 0, 0, 1));   // in +Z
    }

    @Test
    void yUpIsOnlyScaledToMetres() {
        assertVector(1, 2, 3, convert(UpAxis.Y_UP, 1, 1, 2, 3));
        assertVector(0.01f, 0.02f, 0.03f, convert(UpAxis.Y_UP, 0.01, 1, 2, 3));
        // Centimetres and Z up together: 100 units up is one metre up.
        assertVector(0, 1, 0, convert(UpAxis.Z_UP, 0.01, 0, 0, 100));
    }
}
