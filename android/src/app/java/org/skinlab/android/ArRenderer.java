package org.skinlab.android;

import static android.opengl.GLES30.*;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.FloatBuffer;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

import javax.microedition.khronos.egl.EGLConfig;
import javax.microedition.khronos.opengles.GL10;

import android.graphics.SurfaceTexture;
import android.opengl.GLES11Ext;
import android.opengl.GLSurfaceView;

import org.joml.Matrix4f;
import org.skinlab.android.logic.DrawnCopies;
import org.skinlab.android.logic.FpsCounter;
import org.skinlab.android.logic.GlesShaders;
import org.skinlab.android.logic.ModelLoader;
import org.skinlab.android.logic.ModelTextures;
import org.skinlab.android.logic.PreviewOrientation;
import org.skinlab.ar.ArCamera;
import org.skinlab.ar.ArPose;
import org.skinlab.ar.ArSession;
import org.skinlab.ar.CameraFollow;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.LensGlsl;
import org.skinlab.ar.MarkerScene;
import org.skinlab.scene.ModelFraming;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.Frame;
import org.skinlab.simulation.SkeletalAnimatedMesh;

/**
 * Draws one AR frame on the GL thread: the camera image (the preview's SurfaceTexture) across the
 * view, turned to the display as the projection is ({@link PreviewOrientation}), and the skinned model on the marker with the pose the tracking
 * thread published last ({@link ArSession#current()}); the joint palette of the simulation's latest
 * frame is skinned in the vertex shader, moved by the frame's root motion placement. Everything it
 * reads from other threads is one volatile reference each (the session, the mesh, the intrinsics): a frame never mixes two of them.
 */
final class ArRenderer implements GLSurfaceView.Renderer {
    private final AnimationConfig config;
    private final Consumer<SurfaceTexture> onSurfaceReady;
    private final DrawnCopies copies;
    private final FpsCounter fps = new FpsCounter();
    private final CameraFollow follow = new CameraFollow();
    private final Matrix4f projection = new Matrix4f();
    private final Matrix4f imageToViewport = new Matrix4f();
    private final Matrix4f markerView = new Matrix4f();
    private final Matrix4f model = new Matrix4f();
    private final Matrix4f placement = new Matrix4f();
    private final Matrix4f modelView = new Matrix4f();
    private final float[] matrix = new float[16];
    private final float[] textureTransform = new float[16];
    private final float[] sensorToNatural = new float[16];
    private final float[] lens = new float[11];
    private volatile ArSession session;
    private volatile CameraIntrinsics intrinsics;
    private volatile int imageRotation;
    private volatile int sensorOrientation = 90;
    /** Why nothing can be drawn (the driver refused our shaders), or null. */
    private volatile String glProblem;
    /** The model to draw: its simulation and decoded pictures, swapped as one. */
    private volatile ModelLoader.Loaded loaded;
    private volatile MarkerScene scene = new MarkerScene(0.1);
    private SkeletalAnimatedMesh meshOnGpu;
    private List<ModelGl> models = new ArrayList<>();
    private TexturesGl textures = new TexturesGl(ModelTextures.NONE);
    /** Draws the AR model, and the measurement's copies; made with the program, in each new context. */
    private SkinnedModelDraw modelDraw;
    private CopiesDrawer copiesDrawer;
    private ModelFraming framing;
    private SurfaceTexture preview;
    private int previewTexture;
    private int background;
    private int skinned;
    private int quad;
    private int width = 1;
    private int height = 1;

    /**
     * {@code onSurfaceReady} hears, on the GL thread, each time the view's surface is ready (at
     * start, after every resume, after a lost context), the camera preview's texture of the current
     * context: the camera may stream into it from then on. A new context makes a new texture; the
     * listener releases the old one once the camera has let go of it. While a measurement asks
     * for copies ({@code copies}), frames draw them instead of the camera image and the model.
     */
    ArRenderer(AnimationConfig config, Consumer<SurfaceTexture> onSurfaceReady, DrawnCopies copies) {
        this.config = config;
        this.onSurfaceReady = onSurfaceReady;
        this.copies = copies;
    }

    void setSession(ArSession session, CameraIntrinsics intrinsics, int imageRotationDegrees,
            int sensorOrientationDegrees) {
        this.intrinsics = intrinsics;
        this.imageRotation = imageRotationDegrees;
        this.sensorOrientation = sensorOrientationDegrees;
        this.session = session;
    }

    void setImageRotation(int imageRotationDegrees) {
        this.imageRotation = imageRotationDegrees;
    }

    void setMarkerScene(MarkerScene scene) {
        this.scene = scene;
    }

    void setModel(ModelLoader.Loaded model) {
        this.loaded = model;
    }

    double fps() {
        return fps.fps();
    }

    /** Why the GL view shows nothing (the driver's log of a shader that did not build), or null. */
    String problem() {
        return glProblem;
    }

    @Override
    public void onSurfaceCreated(GL10 unused, EGLConfig eglConfig) {
        copies.glStrings(glGetString(GL_RENDERER), glGetString(GL_VENDOR), glGetString(GL_VERSION));
        // The EGL context is new: whatever was on the GPU is gone, the drawers' buffers too.
        modelDraw = null;
        copiesDrawer = null;
        try {
            background = GlProgram.link(GlesShaders.BACKGROUND_VERTEX, GlesShaders.backgroundFragment());
            skinned = GlProgram.link(GlesShaders.skinnedVertex(), GlesShaders.skinnedFragment());
            glUseProgram(skinned);
            MaterialUniforms materials = new MaterialUniforms(skinned);
            glUseProgram(0);
            modelDraw = new SkinnedModelDraw(skinned, materials);
            copiesDrawer = new CopiesDrawer(new SkinnedModelDraw(skinned, materials));
            glProblem = null;
        } catch (IllegalStateException e) {
            // A driver that refuses our GLSL ES: say why in the status line instead of crashing.
            glProblem = e.getMessage();
        }
        int[] t = new int[1];
        glGenTextures(1, t, 0);
        previewTexture = t[0];
        glBindTexture(GLES11Ext.GL_TEXTURE_EXTERNAL_OES, previewTexture);
        glTexParameteri(GLES11Ext.GL_TEXTURE_EXTERNAL_OES, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GLES11Ext.GL_TEXTURE_EXTERNAL_OES, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        preview = new SurfaceTexture(previewTexture);
        FloatBuffer corners = ByteBuffer.allocateDirect(32).order(ByteOrder.nativeOrder()).asFloatBuffer();
        corners.put(new float[] {-1, -1, 1, -1, -1, 1, 1, 1}).flip();
        int[] vao = new int[1];
        glGenVertexArrays(1, vao, 0);
        quad = vao[0];
        glBindVertexArray(quad);
        int[] vbo = new int[1];
        glGenBuffers(1, vbo, 0);
        glBindBuffer(GL_ARRAY_BUFFER, vbo[0]);
        glBufferData(GL_ARRAY_BUFFER, 32, corners, GL_STATIC_DRAW);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 2, GL_FLOAT, false, 8, 0);
        glBindVertexArray(0);
        // The EGL context is new: whatever was on the GPU is gone.
        models = new ArrayList<>();
        textures = new TexturesGl(ModelTextures.NONE);
        meshOnGpu = null;
    }

    @Override
    public void onSurfaceChanged(GL10 unused, int w, int h) {
        width = Math.max(1, w);
        height = Math.max(1, h);
        glViewport(0, 0, width, height);
        // Called after onSurfaceCreated and after every resume (GLSurfaceView remakes its surface).
        onSurfaceReady.accept(preview);
    }

    @Override
    public void onDrawFrame(GL10 unused) {
        fps.frame(System.nanoTime());
        DrawnCopies.Request request = copies.current();
        if (request != null) {
            if (glProblem != null) {
                copies.undrawable(request, "the GL driver refused the app's shaders: " + glProblem);
                return;
            }
            copiesDrawer.draw(request, width, height);
            copies.drawn(request, System.nanoTime());
            return;
        }
        if (copiesDrawer != null && !copies.measuring()) {
            copiesDrawer.release();
        }
        glClearColor(0.1f, 0.1f, 0.12f, 1f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        CameraIntrinsics k = intrinsics;
        ArSession s = session;
        if (k == null || s == null || glProblem != null) {
            return;
        }
        preview.updateTexImage();
        preview.getTransformMatrix(textureTransform);
        ArCamera.imageToViewport(k.width(), k.height(), width, height, imageRotation, false, imageToViewport);
        glDisable(GL_DEPTH_TEST);
        glUseProgram(background);
        glUniformMatrix4fv(glGetUniformLocation(background, "uImageToViewport"), 1, false, imageToViewport.get(matrix), 0);
        glUniformMatrix4fv(glGetUniformLocation(background, "uSensorToNatural"), 1, false,
                PreviewOrientation.sensorToNatural(sensorOrientation, sensorToNatural), 0);
        glUniformMatrix4fv(glGetUniformLocation(background, "uTexture"), 1, false, textureTransform, 0);
        // The background as the pinhole image the model is projected into (lens.glsl).
        LensGlsl.uniforms(k, lens);
        glUniform2f(glGetUniformLocation(background, "uSize"), lens[0], lens[1]);
        glUniform4f(glGetUniformLocation(background, "uPinhole"), lens[2], lens[3], lens[4], lens[5]);
        glUniform3f(glGetUniformLocation(background, "uRadial"), lens[6], lens[7], lens[8]);
        glUniform2f(glGetUniformLocation(background, "uTangential"), lens[9], lens[10]);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GLES11Ext.GL_TEXTURE_EXTERNAL_OES, previewTexture);
        glUniform1i(glGetUniformLocation(background, "uCamera"), 0);
        glBindVertexArray(quad);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        glBindVertexArray(0);

        ArPose pose = s.current();
        ModelLoader.Loaded shown = loaded;
        SkeletalAnimatedMesh m = shown == null ? null : shown.mesh();
        if (!pose.visible() || m == null || m.isClosed()) {
            return;
        }
        try (Frame frame = m.acquire()) {
            if (m != meshOnGpu) {
                upload(shown, frame);
            }
            scene.place(pose, follow, config.isFollowCamera(), framing, markerView, model);
            // Root motion walks the model across the marker: its placement, in the model's space.
            model.mul(frame.placement(placement));
            markerView.mul(model, modelView);
            ArCamera.projection(k, 0.01f, 20f, width, height, imageRotation, false, projection);
            modelDraw.draw(models, frame, projection, modelView);
        }
    }

    /** Replaces what is on the GPU with {@code shown}'s geometries and textures (GL thread). */
    private void upload(ModelLoader.Loaded shown, Frame frame) {
        SkeletalAnimatedMesh m = shown.mesh();
        for (ModelGl g : models) {
            g.release();
        }
        textures.release();
        textures = new TexturesGl(shown.textures());
        models = new ArrayList<>();
        int blended = 0;
        for (int g = 0; g < m.geometries().size(); g++) {
            ModelGl gl = new ModelGl(m.geometries().get(g), textures::texture);
            models.add(gl);
            for (ModelGl.Part p : gl.parts()) {
                blended += p.material().blended() ? 1 : 0;
            }
        }
        modelDraw.blendedParts(blended);
        framing = ModelFraming.of(m.model().asset(), m.geometries(), frame);
        meshOnGpu = m;
        follow.reset();
    }
}
