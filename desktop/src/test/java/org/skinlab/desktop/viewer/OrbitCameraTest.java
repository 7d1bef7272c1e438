package org.skinlab.desktop.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;

class OrbitCameraTest {
    /** After framing, the sphere's extreme points project inside the view, for wide and tall views. */
    @Test
    void theFramedSphereIsInView() {
        for (float aspect : new float[] {0.5f, 1f, 1.6f, 3f}) {
            OrbitCamera c = new OrbitCamera();
            Vector3f centre = new Vector3f(0.2f, 0.9f, -0.1f);
            float r = 0.95f;
            c.frame(centre, r);
            Matrix4f vp = c.projection(aspect, new Matrix4f());
            c.viewTimesInto(vp);
            for (Vector3f d : new Vector3f[] {new Vector3f(1, 0, 0), new Vector3f(-1, 0, 0), new Vector3f(0, 1, 0),
                    new Vector3f(0, -1, 0), new Vector3f(0, 0, 1), new Vector3f(0, 0, -1)}) {
                Vector4f p = new Vector4f(new Vector3f(d).mul(r).add(centre), 1f).mul(vp);
                p.div(p.w);
                assertTrue(Math.abs(p.x) <= 1 && Math.abs(p.y) <= 1 && p.z > -1 && p.z < 1,
                        "aspect " + aspect + " direction " + d + " projects to " + p);
            }
        }
    }

    /** {@code skinlab view --yaw}: every framing looks from the home yaw; 90 degrees puts the eye on +x. */
    @Test
    void framingLooksFromTheHomeYaw() {
        OrbitCamera c = new OrbitCamera();
        c.setHomeYaw((float) Math.toRadians(90));
        c.frame(new Vector3f(), 1f);
        c.orbit(300, 0);
        c.frame(new Vector3f(), 1f);
        Vector3f eye = c.eye(new Vector3f());
        assertTrue(eye.x > 1f && Math.abs(eye.z) < 1e-5f, eye.toString());
    }

    /**
     * {@code skinlab view --pitch}: framing looks from the home pitch, 90 degrees of yaw and 60 of
     * pitch put the eye at elevation 60 degrees over +x (sin 60 = 0.866 of the distance up);
     * the pole is refused.
     */
    @Test
    void framingLooksFromTheHomePitch() {
        OrbitCamera c = new OrbitCamera();
        c.setHomeYaw((float) Math.toRadians(90));
        c.setHomePitch((float) Math.toRadians(60));
        c.frame(new Vector3f(), 1f);
        c.orbit(0, 200);
        c.frame(new Vector3f(), 1f);
        Vector3f eye = c.eye(new Vector3f());
        float d = c.distance();
        assertEquals(Math.sin(Math.toRadians(60)) * d, eye.y, 1e-4 * d);
        assertEquals(Math.cos(Math.toRadians(60)) * d, eye.x, 1e-4 * d);
        assertEquals(0, eye.z, 1e-4 * d);
        c.setHomePitch((float) Math.toRadians(90));
        c.frame(new Vector3f(), 1f);
        assertEquals(Math.sin(OrbitCamera.MAX_PITCH) * c.distance(), c.eye(new Vector3f()).y, 1e-4 * c.distance());
    }

    @Test
    void zoomAndOrbitStayBounded() {
        OrbitCamera c = new OrbitCamera();
        c.frame(new Vector3f(), 1f);
        for (int i = 0; i < 200; i++) {
            c.zoom(5);
            c.orbit(0, 1000);
        }
        assertTrue(c.distance() >= 0.01f - 1e-6f);
        Vector3f eye = c.eye(new Vector3f());
        // Never over the pole: the view keeps an up direction.
        assertTrue(Math.abs(eye.y) < c.distance(), "eye " + eye);
        for (int i = 0; i < 200; i++) {
            c.zoom(-5);
        }
        assertTrue(c.distance() <= 100f + 1e-3f);
    }
}
