package org.skinlab.jme;

import java.nio.ByteBuffer;
import java.nio.FloatBuffer;

import com.jme3.renderer.Camera;
import com.jme3.renderer.RenderManager;
import com.jme3.renderer.Renderer;
import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.VertexBuffer;
import com.jme3.texture.FrameBuffer;
import com.jme3.texture.Image;
import com.jme3.util.BufferUtils;

/**
 * Reads the GPU path's skinned positions back: the geometry's vertices drawn as points with the
 * material's SkinlabPositions technique, which puts vertex i's skinned world position into pixel
 * i of an RGBA32F frame buffer, then read with the renderer's readFrameBufferWithFormat. Runs on
 * the render thread.
 */
final class GpuReadback {
    private static final int WIDTH = 256;

    private GpuReadback() {
    }

    /** World positions, 3 floats per vertex, as the GPU skins {@code g} with its current palette. */
    static float[] worldPositions(RenderManager rm, Camera mainCamera, Geometry g) {
        Mesh source = g.getMesh();
        Mesh points = new Mesh();
        for (VertexBuffer vb : source.getBufferList()) {
            if (vb.getBufferType() != VertexBuffer.Type.Index) {
                points.setBuffer(vb);
            }
        }
        points.setMode(Mesh.Mode.Points);
        points.updateCounts();
        Geometry pg = new Geometry("positions of " + g.getName(), points);
        pg.setMaterial(g.getMaterial());
        pg.setLocalTransform(g.getWorldTransform());
        pg.updateGeometricState();
        int n = source.getVertexCount();
        int height = (n + WIDTH - 1) / WIDTH;
        FrameBuffer fb = new FrameBuffer(WIDTH, height, 1);
        fb.addColorTarget(FrameBuffer.FrameBufferTarget.newTarget(Image.Format.RGBA32F));
        Camera camera = new Camera(WIDTH, height);
        Renderer r = rm.getRenderer();
        ByteBuffer bytes = BufferUtils.createByteBuffer(4 * 4 * WIDTH * height);
        try {
            r.setFrameBuffer(fb);
            rm.setCamera(camera, false);
            r.setBackgroundColor(new com.jme3.math.ColorRGBA(Float.NaN, Float.NaN, Float.NaN, 0));
            r.clearBuffers(true, true, true);
            rm.setForcedTechnique("SkinlabPositions");
            rm.renderGeometry(pg);
            r.readFrameBufferWithFormat(fb, bytes, Image.Format.RGBA32F);
        } finally {
            rm.setForcedTechnique(null);
            r.setFrameBuffer(null);
            rm.setCamera(mainCamera, false);
            fb.dispose();
        }
        FloatBuffer f = bytes.asFloatBuffer();
        float[] out = new float[3 * n];
        for (int i = 0; i < n; i++) {
            if (f.get(4 * i + 3) != 1f) {
                throw new IllegalStateException("vertex " + i + " of " + g.getName() + " was not written by the GPU");
            }
            out[3 * i] = f.get(4 * i);
            out[3 * i + 1] = f.get(4 * i + 1);
            out[3 * i + 2] = f.get(4 * i + 2);
        }
        return out;
    }
}
