package org.skinlab.desktop.viewer;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;

import org.skinlab.animation.Skeleton;
import org.skinlab.desktop.render.DrawSettings;
import org.skinlab.importer.ModelImporter;
import org.skinlab.model.ImportException;
import org.skinlab.model.Model;
import org.skinlab.scene.ModelFraming;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.Frame;
import org.skinlab.simulation.SkeletalAnimatedMesh;
import org.skinlab.internal.metrics.LargestDifference;
import org.skinlab.internal.metrics.MethodComparison;
import org.skinlab.internal.metrics.RestPose;

/**
 * The viewer's state and what its actions do, apart from drawing: the model shown (loaded off the
 * window's thread, so a big file never freezes the window, and a bad one leaves the previous model
 * in place with the importer's message), the simulation's switches ({@link AnimationConfig}), the
 * viewer's own ({@link ViewerSettings}), the camera and the status line.
 *
 * <p>Everything but the loading runs on the window's thread. With {@code threaded}, each model's
 * simulation runs on its own thread; without, the caller steps it (headless pictures).
 */
public final class Viewer implements AutoCloseable {
    /** How far the step actions move a paused playback. */
    public static final double STEP_SECONDS = 1.0 / 30.0;

    private final ModelLibrary library;
    private final AnimationConfig config;
    private final boolean threaded;
    private final ViewerSettings settings = new ViewerSettings();
    private final OrbitCamera camera = new OrbitCamera();
    private final ExecutorService loader = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "skinlab-loader");
        t.setDaemon(true);
        return t;
    });
    /** The finished load the window thread has not taken yet: a LoadedModel or an error message. */
    private final AtomicReference<Object> finished = new AtomicReference<>();
    private Future<?> inFlight;
    /** The newest load asked for: older ones still queued are skipped, finished ones dropped. */
    private volatile long newestRequest;
    /** The file of the newest load asked for (previous/next mesh step from it while it loads). */
    private Path requested;
    private LoadedModel current;
    /** The auto difference scale's measure of the model shown, on the loader thread. */
    private final ClipMeasure clipMeasure = new ClipMeasure(loader);
    private String status = "";
    private boolean quit;

    public Viewer(ModelLibrary library, AnimationConfig config, boolean threaded) {
        this.library = library;
        this.config = config;
        this.threaded = threaded;
    }

    public ModelLibrary library() {
        return library;
    }

    public AnimationConfig config() {
        return config;
    }

    public ViewerSettings settings() {
        return settings;
    }

    public OrbitCamera camera() {
        return camera;
    }

    /** The model shown, null before the first load finished. */
    public LoadedModel current() {
        return current;
    }

    public String statusMessage() {
        return status;
    }

    public void setStatus(String message) {
        status = message == null ? "" : message;
    }

    public boolean quitRequested() {
        return quit;
    }

    /** Whether a load is under way. */
    public boolean loading() {
        Future<?> f = inFlight;
        return f != null && !f.isDone();
    }

    // ------------------------------------------------------------------------------ loading

    /** Starts loading {@code file} (its first clip); {@link #update()} shows it when done. */
    public void open(Path file) {
        load(file, null, 0, 0.0);
    }

    /**
     * Loads {@code file} on the loader thread and waits for it (headless use); returns null when
     * it is shown, else the error message.
     */
    public String openAndWait(Path file) {
        open(file);
        try {
            inFlight.get(10, TimeUnit.MINUTES);
        } catch (Exception e) {
            return "loading " + file + " did not finish: " + e;
        }
        update();
        return current != null && current.file().equals(file.toAbsolutePath().normalize()) ? null : status;
    }

    private void load(Path file, Model already, int clip, double time) {
        if (file == null) {
            status = "no model to open (no assets folder found; open a .dae, .gltf or .glb file)";
            return;
        }
        Path path = file.toAbsolutePath().normalize();
        String name = library.displayName(path);
        status = "loading " + name + " ...";
        long request = ++newestRequest;
        requested = path;
        // A measure of the model shown would hold the loader up: the next model is measured if it needs it.
        clipMeasure.cancel();
        inFlight = loader.submit(() -> {
            // Pressing "next mesh" five times shows the fifth model, not all five in turn.
            if (request != newestRequest) {
                return;
            }
            Object result = build(path, name, already, clip, time);
            Object replaced = finished.getAndSet(result);
            if (replaced instanceof LoadedModel) {
                ((LoadedModel) replaced).close();
            }
        });
    }

    /** The file the next previous/next step starts from: the newest asked for, else the one shown. */
    private Path stepBase() {
        return loading() && requested != null ? requested : current == null ? null : current.file();
    }

    /** Imports and prepares a model (loader thread): a LoadedModel, or a one-line error. */
    private Object build(Path path, String name, Model already, int clip, double time) {
        long t0 = System.nanoTime();
        SkeletalAnimatedMesh mesh = null;
        try {
            Model model = already != null ? already : read(path);
            int clipIndex = model.clips().isEmpty() ? -1 : Math.min(clip, model.clips().size() - 1);
            mesh = new SkeletalAnimatedMesh(model, clipIndex < 0 ? null : model.clips().get(clipIndex), config);
            mesh.seek(time);
            mesh.step(0.0);
            ModelFraming framing;
            try (Frame frame = mesh.acquire()) {
                framing = ModelFraming.of(model.asset(), mesh.geometries(), frame);
            }
            // The difference probe's rest pose, closed parts and skinners, here rather than on the window's thread.
            RestPose rest = RestPose.of(Skeleton.of(model), mesh.geometries());
            List<MethodComparison> comparisons = new ArrayList<>();
            for (int g = 0; g < mesh.geometries().size(); g++) {
                comparisons.add(new MethodComparison(rest, g));
            }
            return new LoadedModel(path, name, model, clipIndex, mesh, framing, rest, comparisons,
                    (System.nanoTime() - t0) / 1e6);
        } catch (ImportException e) {
            close(mesh);
            return oneLine(e.getMessage());
        } catch (IOException e) {
            close(mesh);
            return name + ": cannot be read: " + oneLine(String.valueOf(e.getMessage()));
        } catch (OutOfMemoryError e) {
            close(mesh);
            return name + ": too large for the memory Java was given (start with SKINLAB_OPTS=-Xmx4g)";
        } catch (StackOverflowError e) {
            close(mesh);
            return name + ": nested too deeply to load";
        } catch (RuntimeException e) {
            close(mesh);
            return name + ": cannot be shown: " + oneLine(String.valueOf(e.getMessage()));
        }
    }

    private static Model read(Path path) throws IOException, ImportException {
        if (!Files.exists(path)) {
            throw new IOException("file not found");
        }
        if (Files.isDirectory(path)) {
            throw new IOException("a directory, not a model file");
        }
        return ModelImporter.read(path);
    }

    private static void close(SkeletalAnimatedMesh mesh) {
        if (mesh != null) {
            mesh.close();
        }
    }

    private static String oneLine(String s) {
        return s == null ? "" : s.replaceAll("\\s+", " ").trim();
    }

    /**
     * Takes a finished load, if any, and starts or takes the measure the auto difference scale
     * needs (window thread, once per frame; allocates nothing otherwise).
     */
    public void update() {
        takeLoad();
        measureForAutoScale();
    }

    private void takeLoad() {
        Object done = finished.getAndSet(null);
        if (done == null) {
            return;
        }
        if (done instanceof String) {
            status = (String) done;
            return;
        }
        LoadedModel next = (LoadedModel) done;
        LoadedModel previous = current;
        boolean sameFile = previous != null && previous.file().equals(next.file());
        current = next;
        library.add(next.file());
        if (previous != null) {
            previous.close();
        }
        if (threaded) {
            next.mesh().start();
        }
        if (!sameFile) {
            frameCamera();
        }
        settings.selectJoint(settings.selectedJoint(), jointCount());
        status = next.displayName() + " (" + next.clipName() + ", " + Math.round(next.loadMillis()) + " ms)";
    }

    /** The scene node of the weight view's joint (a joint of the first geometry), -1 when none. */
    public int selectedJointNode() {
        int count = jointCount();
        return count == 0 ? -1 : current.mesh().geometries().get(0).jointNode(settings.selectedJoint());
    }

    /** Palette joints of the first geometry (the weight view's joints). */
    public int jointCount() {
        return current == null || current.mesh().geometries().isEmpty() ? 0
                : current.mesh().geometries().get(0).jointCount();
    }

    // ------------------------------------------------------------------------ difference scale

    /** With the auto difference scale, measures the clip of the model shown (once per model), off this thread. */
    private void measureForAutoScale() {
        if (settings.differenceScale().auto()) {
            clipMeasure.update(current, config.interpolation());
        }
    }

    /**
     * The clip's largest LBS-DQS difference of the model shown (relative to its size, and when),
     * as the auto difference scale measured it; null while it is measured, or when the scale is
     * not auto.
     */
    public LargestDifference clipLargestDifference() {
        return settings.differenceScale().auto() ? clipMeasure.result(current) : null;
    }

    /**
     * The top (red) of the difference view's colour scale as a share of the model's size:
     * {@link DifferenceScale#fractionFor} the clip's largest difference where measured.
     */
    public double differenceFull() {
        LargestDifference d = clipLargestDifference();
        return settings.differenceScale().fractionFor(d == null ? Double.NaN : d.relative());
    }

    /** Headless pictures: with the auto scale, waits until the model shown is measured (at most {@code seconds}). */
    public void awaitDifferenceScale(long seconds) {
        measureForAutoScale();
        if (settings.differenceScale().auto()) {
            clipMeasure.await(seconds);
        }
    }

    // ------------------------------------------------------------------------------ actions

    /**
     * Performs an action. {@link ViewerAction#OPEN_FILE} and {@link ViewerAction#SCREENSHOT}
     * need the window (a dialog, the framebuffer): the window handles them and this does nothing.
     */
    public void perform(ViewerAction action) {
        boolean done = animationAction(action) || modelAction(action) || viewAction(action);
        if (done) {
            return;
        }
        switch (action) {
            case QUIT:
                quit = true;
                break;
            case OPEN_FILE:
            case SCREENSHOT:
                break;
            default:
                throw new AssertionError(action);
        }
    }

    /** The animation's switches (the shared {@link AnimationConfig}); false for other actions. */
    private boolean animationAction(ViewerAction action) {
        switch (action) {
            case TOGGLE_ANIMATION:
                config.setAnimationRunning(!config.isAnimationRunning());
                return true;
            case TOGGLE_MESH_UPDATES:
                config.setMeshUpdatesRunning(!config.isMeshUpdatesRunning());
                return true;
            case TOGGLE_FOLLOW_CAMERA:
                config.setFollowCamera(!config.isFollowCamera());
                return true;
            case NEXT_METHOD:
                config.nextMethod();
                return true;
            case NEXT_INTERPOLATION:
                config.nextInterpolation();
                return true;
            case SLOWER:
                config.slower();
                return true;
            case FASTER:
                config.faster();
                return true;
            case TOGGLE_GPU_SKINNING:
                config.setCpuSkinning(!config.isCpuSkinning());
                return true;
            case TOGGLE_BIND_POSE:
                config.setBindPose(!config.isBindPose());
                return true;
            default:
                return false;
        }
    }

    /** The model shown, its clip and its playback; false for other actions. */
    private boolean modelAction(ViewerAction action) {
        switch (action) {
            case PREVIOUS_MESH:
                load(library.neighbour(stepBase(), -1), null, 0, 0.0);
                return true;
            case NEXT_MESH:
                load(library.neighbour(stepBase(), 1), null, 0, 0.0);
                return true;
            case NEXT_CLIP:
                if (current != null && current.model().clips().size() > 1) {
                    playClip((current.clipIndex() + 1) % current.model().clips().size());
                }
                return true;
            case STEP_BACK:
                stepPlayback(-STEP_SECONDS);
                return true;
            case STEP_FORWARD:
                stepPlayback(STEP_SECONDS);
                return true;
            default:
                return false;
        }
    }

    /** How the model is shown: camera, instances and the {@link ViewerSettings}; false for other actions. */
    private boolean viewAction(ViewerAction action) {
        switch (action) {
            case CENTRE_CAMERA:
                frameCamera();
                return true;
            case FEWER_INSTANCES:
                settings.fewerInstances();
                frameCamera();
                return true;
            case MORE_INSTANCES:
                settings.moreInstances();
                frameCamera();
                return true;
            case TOGGLE_SKELETON:
                settings.setSkeleton(!settings.skeleton());
                return true;
            case TOGGLE_WIREFRAME:
                settings.setWireframe(!settings.wireframe());
                return true;
            case VIEW_SHADED:
                settings.setView(DrawSettings.View.SHADED);
                return true;
            case VIEW_WEIGHTS:
                settings.setView(DrawSettings.View.WEIGHTS);
                return true;
            case VIEW_DIFFERENCE:
                settings.setView(DrawSettings.View.DIFFERENCE);
                return true;
            case VIEW_CHECKER:
                settings.setView(DrawSettings.View.CHECKER);
                return true;
            case PREVIOUS_JOINT:
                settings.selectJoint(settings.selectedJoint() - 1, jointCount());
                return true;
            case NEXT_JOINT:
                settings.selectJoint(settings.selectedJoint() + 1, jointCount());
                return true;
            case TOGGLE_SPLIT:
                settings.setSplit(!settings.split());
                return true;
            case TOGGLE_HELP:
                settings.setHelp(!settings.help());
                return true;
            default:
                return false;
        }
    }

    /** Plays clip {@code index} of the model shown (reloaded off the window thread). */
    public void playClip(int index) {
        if (current != null && index >= 0 && index < current.model().clips().size() && index != current.clipIndex()) {
            load(current.file(), current.model(), index, 0.0);
        }
    }

    /** Frames the model, or the grid of its copies. */
    private void frameCamera() {
        if (current != null) {
            camera.frame(current.framing(), settings.instances(), settings.columns());
        }
    }

    /** Moves the playback time; the animation keeps running or paused as it was. */
    public void seek(double seconds) {
        if (current != null) {
            current.mesh().seek(seconds);
        }
    }

    private void stepPlayback(double seconds) {
        if (current != null) {
            config.stopAnimation();
            current.mesh().seek(current.mesh().playbackTime() + seconds);
        }
    }

    @Override
    public void close() {
        loader.shutdownNow();
        try {
            loader.awaitTermination(5, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        Object pending = finished.getAndSet(null);
        if (pending instanceof LoadedModel) {
            ((LoadedModel) pending).close();
        }
        if (current != null) {
            current.close();
            current = null;
        }
    }
}
