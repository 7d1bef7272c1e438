package org.skinlab.desktop.app;

import static org.lwjgl.opengl.GL33C.*;

import java.util.List;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.skinlab.desktop.render.DrawSettings;
import org.skinlab.desktop.render.FloorGrid;
import org.skinlab.desktop.render.GlWindow;
import org.skinlab.desktop.render.ModelRenderer;
import org.skinlab.desktop.render.SkinningShader;
import org.skinlab.desktop.render.TextureCache;
import org.skinlab.desktop.ui.SceneArea;
import org.skinlab.desktop.viewer.LoadedModel;
import org.skinlab.desktop.viewer.Viewer;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.Frame;
import org.skinlab.skinning.SkinningGlsl;
import org.skinlab.skinning.SkinningMethod;

/**
 * The scene of one window frame, beside the toolbar: the shown model's GPU side (rebuilt when the
 * viewer shows another model), then from one simulation {@link Frame} the model in one view, the
 * split view's two, or on the marker over the camera image (AR), with the floor, skeleton and
 * difference colours the viewer's switches ask for; the numbers it measures go into the
 * {@link MutableSceneReadout} the interface shows. GL thread only.
 */
final class ScenePainter implements AutoCloseable {
    private final GlWindow window;
    private final Viewer viewer;
    private final AnimationConfig config;
    private final SkinningMethod splitMethod;
    private final MutableSceneReadout info;
    /** The AR mode's camera background and marker placement ({@code skinlab ar}), or null. */
    private final ArPresenter ar;
    private final SkinningShader shader = new SkinningShader();
    private final FloorGrid floor = new FloorGrid();
    private final TextureCache textures = new TextureCache();
    private final DrawSettings draw = new DrawSettings();
    private final Vector3f floorCentre = new Vector3f();
    /** Root motion's placement of the frame drawn, in the model's space. */
    private final Matrix4f placement = new Matrix4f();
    /** The inverse of the shown model's upright matrix, and scratch for the placement in the scene. */
    private final Matrix4f uprightInverse = new Matrix4f();
    private final Matrix4f moved = new Matrix4f();
    /** How far root motion has taken the model's framed centre, in the scene. */
    private final Vector3f travel = new Vector3f();
    private LoadedModel shown;
    private ModelRenderer renderer;
    private DifferenceProbe difference;
    private int width;
    private int height;
    private SceneArea area;

    ScenePainter(GlWindow window, Viewer viewer, AnimationConfig config, SkinningMethod splitMethod, MutableSceneReadout info,
            ArPresenter ar) {
        this.window = window;
        this.viewer = viewer;
        this.config = config;
        this.splitMethod = splitMethod;
        this.info = info;
        this.ar = ar;
    }

    /** The model drawn (the viewer's current one once {@link #paint} has run), or null. */
    LoadedModel shown() {
        return shown;
    }

    /** Copies of the model drawn per frame. */
    int instances() {
        return draw.instances;
    }

    /**
     * Draws the scene into the {@code area} of a framebuffer of {@code width x height} (the rest
     * is the interface's). Returns whether a model frame was drawn.
     */
    boolean paint(int width, int height, SceneArea area) {
        this.width = width;
        this.height = height;
        this.area = area;
        sync();
        if (ar != null) {
            drawArBackground();
        }
        if (renderer == null) {
            return false;
        }
        try (Frame frame = shown.mesh().acquire()) {
            if (frame == null) {
                return false;
            }
            drawScene(frame);
            return true;
        }
    }

    /** Rebuilds the GPU side when the viewer shows another model. */
    private void sync() {
        LoadedModel current = viewer.current();
        if (current == shown) {
            return;
        }
        if (renderer != null) {
            renderer.close();
            renderer = null;
        }
        shown = current;
        difference = null;
        info.maxDifference = Double.NaN;
        info.lbsVolume = Double.NaN;
        info.dqsVolume = Double.NaN;
        info.volumeNote = "";
        info.stats.clear();
        textures.clear();
        if (current != null) {
            current.framing().upright().invert(uprightInverse);
            renderer = new ModelRenderer(shader, current.model(), current.mesh().geometries(), textures::texture);
            window.setTitle("skinlab - " + current.displayName());
            if (!textures.warnings().isEmpty()) {
                List<String> w = textures.warnings();
                viewer.setStatus(viewer.statusMessage() + "; " + w.get(0)
                        + (w.size() > 1 ? " (and " + (w.size() - 1) + " more textures)" : ""));
            }
            info.vertices = renderer.vertexCount();
            info.shaderInfluences = renderer.shaderInfluences();
            info.cappedVertices = renderer.cappedVertices();
        }
    }

    private void drawScene(Frame frame) {
        renderer.upload(frame);
        info.skinningNanos = frame.skinningNanos();
        info.clipTime = frame.clipTime();
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        // Root motion's placement is in the model's space: it comes after the upright fix.
        draw.model.set(shown.framing().upright()).mul(frame.placement(placement));
        if (ar == null) {
            follow();
        }
        // Both methods' volumes are live numbers in every view; the difference view adds the distance.
        if (difference == null) {
            difference = new DifferenceProbe(shown.rest(), shown.comparisons());
            info.volumeNote = difference.volumeNote();
        }
        difference.measure(frame);
        info.maxDifference = difference.maxRelative();
        info.differenceFull = viewer.differenceFull();
        info.lbsVolume = difference.lbsVolume();
        info.dqsVolume = difference.dqsVolume();
        boolean cpuFrame = frame.hasSkinnedMesh();
        // A palette-only frame draws the configured method at once, if the shader has it; a method
        // without shader code shows from its first CPU-skinned frame on.
        SkinningMethod first = cpuFrame || !SkinningGlsl.hasCode(config.method()) ? frame.method() : config.method();
        boolean split = viewer.settings().split();
        int left = area.x();
        int w = area.width();
        info.views = split && ar == null ? 2 : 1;
        info.viewMethods[0] = first;
        info.viewOnCpu[0] = cpuFrame;
        if (ar != null) {
            drawArModel(first, cpuFrame);
        } else if (split) {
            drawView(first, cpuFrame, left, w / 2);
            drawView(other(first), false, left + w / 2, w - w / 2);
            info.viewMethods[1] = other(first);
            info.viewOnCpu[1] = false;
        } else {
            drawView(first, cpuFrame, left, w);
        }
        info.gpuSkinned = !cpuFrame;
        glViewport(0, 0, width, height);
    }

    /**
     * Keeps a model that root motion moves in view: the camera's target goes with its framed centre
     * (the placement conjugated into the scene: upright * placement * upright^-1).
     */
    private void follow() {
        Vector3f centre = shown.framing().centre();
        moved.set(draw.model).mul(uprightInverse).transformPosition(centre, travel).sub(centre);
        viewer.camera().follow(travel);
    }

    /**
     * The method the split view draws beside {@code first}, on the GPU: --split's, else the method
     * {@code first} builds on (LBS and DQS face each other, stretchable bones on LBS face LBS, the
     * rest face DQS).
     */
    private SkinningMethod other(SkinningMethod first) {
        if (splitMethod != null && splitMethod != first) {
            return splitMethod;
        }
        return first == SkinningMethod.DQS || first == SkinningMethod.STBS_LBS ? SkinningMethod.LBS : SkinningMethod.DQS;
    }

    private void drawView(SkinningMethod method, boolean cpuPositions, int x, int viewWidth) {
        glViewport(x, area.y(), viewWidth, area.height());
        viewer.camera().projection(viewWidth / (float) area.height(), draw.viewProjection);
        viewer.camera().viewTimesInto(draw.viewProjection);
        viewer.camera().eye(draw.eye);
        drawModel(method, cpuPositions, viewer.settings().instances(), viewer.settings().columns(), true);
    }

    /**
     * The model with the viewer's switches, on the camera (and model matrix) already in
     * {@link #draw}: {@code instances} copies in rows of {@code columns}, on the floor grid or not.
     */
    private void drawModel(SkinningMethod method, boolean cpuPositions, int instances, int columns, boolean withFloor) {
        draw.gpuSkinning = !cpuPositions;
        draw.method = method;
        draw.view = viewer.settings().drawView();
        draw.selectedNode = viewer.selectedJointNode();
        // Distances in the shader are in the document's units, as the probe's size is; so is the checker.
        draw.scalarFull = draw.view == DrawSettings.View.DIFFERENCE ? (float) (info.differenceFull * difference.size())
                : 1f;
        draw.checkerCell = (float) Math.max(1e-9, difference.size() / DrawSettings.CHECKER_SQUARES);
        draw.instances = instances;
        draw.gridColumns = columns;
        draw.spacing = shown.framing().gridSpacing();
        draw.wireframe = viewer.settings().wireframe();
        if (withFloor) {
            // The floor reaches a little beyond the model, or the grid of its copies, and goes where
            // root motion takes them by whole lines, so its lines stay where they are on the ground.
            float extent = 1.3f * shown.framing().gridSphere(draw.instances, draw.gridColumns, floorCentre);
            float line = FloorGrid.lineSpacing(extent);
            floorCentre.add(line * Math.round(travel.x / line), 0f, line * Math.round(travel.z / line));
            floor.draw(draw, floorCentre.x, floorCentre.z, extent);
        }
        glEnable(GL_DEPTH_TEST);
        renderer.draw(draw);
        if (viewer.settings().skeleton()) {
            renderer.drawSkeleton(draw);
        }
    }

    /** AR: the newest camera frame across the scene area; the tracking state in the status line when it changes. */
    private void drawArBackground() {
        glViewport(area.x(), area.y(), area.width(), area.height());
        ar.drawBackground(area.width(), area.height());
        String change = ar.statusChange();
        if (change != null) {
            viewer.setStatus(change);
        }
        glViewport(0, 0, width, height);
    }

    /** AR: the model on the marker, or nothing while the marker is not shown. */
    private void drawArModel(SkinningMethod method, boolean cpuPositions) {
        glViewport(area.x(), area.y(), area.width(), area.height());
        if (ar.placeModel(shown.framing(), config, draw, area.width(), area.height())) {
            drawModel(method, cpuPositions, 1, 1, false);
        }
    }

    @Override
    public void close() {
        if (ar != null) {
            ar.close();
        }
        if (renderer != null) {
            renderer.close();
        }
        textures.close();
        shader.close();
        floor.close();
    }
}
