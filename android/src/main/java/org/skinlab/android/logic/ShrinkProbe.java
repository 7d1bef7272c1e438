package org.skinlab.android.logic;

import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.skinlab.ar.ArSession;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.FiducialTracker;
import org.skinlab.ar.GrayImage;
import org.skinlab.ar.MarkerScene;
import org.skinlab.ar.MarkerDictionary;
import org.skinlab.ar.MarkerPattern;
import org.skinlab.ar.TrackerConfig;
import org.skinlab.internal.synthetic.PlacedMarker;
import org.skinlab.internal.synthetic.SceneOptions;
import org.skinlab.internal.synthetic.SyntheticCamera;
import org.skinlab.internal.bench.DeviceResults;
import org.skinlab.internal.bench.DeviceResultsReader;
import org.skinlab.internal.bench.FrameTimes;
import org.skinlab.internal.bench.Rounds;
import org.skinlab.importer.ModelImporter;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.Frame;
import org.skinlab.simulation.SkeletalAnimatedMesh;
import org.skinlab.skinning.CentresOfRotation;
import org.skinlab.skinning.SkinningMethod;

/**
 * Runs the app's core paths (import, simulation, CoR's centres and their cache, the mixer's
 * buttons on a model with several clips, the skinning shader's text with core's formulas, marker
 * tracking, the measurement and its file) on a desktop JVM after R8 has shrunk them
 * with the APK's rules ({@code gradle :android:checkShrunk}): the APK cannot be run here, but this
 * shows that shrinking left BoofCV, JOML and core working (nothing they reach by reflection or as
 * a resource was removed). Exits 0 and prints "shrunk app paths work" on success.
 */
public final class ShrinkProbe {
    private ShrinkProbe() {
    }

    /**
     * {@code ShrinkProbe MODEL...}: every model (a .dae, a .glb) through the app's paths (the mixer's
     * buttons on those with several clips), then the tracker.
     */
    public static void main(String[] args) throws Exception {
        for (String model : args) {
            probeModel(Path.of(model));
        }
        // The skinning shader as the renderer builds it: core's formulas, a resource beside the classes.
        if (!GlesShaders.skinnedVertex().contains("void cor(")) {
            throw new IllegalStateException("the shrunk app's skinning shader lacks the shared formulas");
        }
        probeTracker();
        if (args.length > 0) {
            probeMeasurement(Path.of(args[0]));
        }
        System.out.println("shrunk app paths work");
    }

    /** Import, simulation, the GPU palette, the mixer's buttons and CoR's centres with their cache, as the app runs them. */
    private static void probeModel(Path model) throws Exception {
        Path cache = Files.createTempDirectory("skinlab-centres");
        CentresOfRotation.setCacheDirectory(cache);
        try (InputStream in = Files.newInputStream(model);
                SkeletalAnimatedMesh mesh = SkeletalAnimatedMesh.of(ModelImporter.read(in,
                        model.getFileName().toString(), null), new AnimationConfig(AnimationConfig.Settings.DEFAULT
                        .withCpuSkinning(false)))) {
            mesh.step(0.1);
            try (Frame f = mesh.acquire()) {
                float[] palette = new float[PaletteTexture.floats(f.palette(0).jointCount())];
                PaletteTexture.pack(f, 0, palette);
            }
            probeMixer(mesh);
            // CoR's centres were bound with the mesh, as on the Activity's loader: the cache below holds them.
            if (!mesh.geometries().get(0).hasCentresOfRotation()) {
                throw new IllegalStateException(model.getFileName() + ": the mesh was built without CoR's centres");
            }
        }
        try (Stream<Path> cached = Files.list(cache)) {
            List<Path> files = cached.collect(Collectors.toList());
            if (files.size() != 1) {
                throw new IllegalStateException(model.getFileName() + ": the shrunk centres' cache holds " + files);
            }
            Files.delete(files.get(0));
        }
        Files.delete(cache);
    }

    /** The cross-fade and root motion buttons as the app directs them, on a model with several clips. */
    private static void probeMixer(SkeletalAnimatedMesh mesh) {
        MixerControl control = new MixerControl(() -> new MarkerScene(0.1));
        control.show(mesh);
        mesh.step(0.1);
        mesh.step(0.1);
        if (!control.canCrossFade()) {
            return; // one clip: nothing to direct
        }
        control.toggleRootMotion();
        double moved = 0;
        // Through the clips until one with root motion walks.
        for (int clip = 0; clip < 10 && moved == 0; clip++) {
            control.crossFadeToNext();
            for (int i = 0; i < 60; i++) {
                mesh.step(1 / 60.0);
            }
            try (Frame f = mesh.acquire()) {
                moved = f.placement(new Matrix4f()).getTranslation(new Vector3f()).length();
            }
        }
        if (!control.status().endsWith("| root motion") || moved == 0) {
            throw new IllegalStateException(mesh.model().source() + ": the shrunk mixer did not fade or walk: "
                    + control.status());
        }
    }

    /**
     * "Measure" on one model, briefly and without a GL thread: the frame timings, the device file
     * written by jackson-core's generator, and read back.
     */
    private static void probeMeasurement(Path model) throws Exception {
        Path folder = Files.createTempDirectory("skinlab-measure");
        MeasureProtocol brief = new MeasureProtocol("probe", new FrameTimes.Protocol(Rounds.MIN_RUNS, 0.01, 0.001,
                0.001), 0.01, 1, 1);
        DeviceMeasurement m = new DeviceMeasurement(name -> Files.newInputStream(model.resolveSibling(name)),
                List.of(model.getFileName().toString()), brief, new DrawnCopies(0.05),
                new DeviceResults.App("org.skinlab.android", "probe", 1), () -> new DeviceResults.Device("probe",
                        "probe", "probe", "0", 26, List.of("probe"), new DeviceResults.Cpu(1, null, null), 60),
                folder.toFile());
        m.start();
        while (m.running()) {
            Thread.sleep(10);
        }
        if (m.written() == null) {
            throw new IllegalStateException("the shrunk measurement wrote nothing: " + m.status());
        }
        DeviceResults r = DeviceResultsReader.read(Files.readAllBytes(m.written().toPath()), "probe");
        if (r.models().size() != 1 || r.models().get(0).methods().size() != SkinningMethod.values().length) {
            throw new IllegalStateException("the shrunk measurement's file lacks timings: " + r);
        }
        Files.delete(m.written().toPath());
        Files.delete(folder);
    }

    /** A calibrated camera with a lens: the tracker's lens path as it ships. */
    private static void probeTracker() {
        int[] array = {0, 0, 4000, 3000};
        CameraReport camera = new CameraReport(28, array, array, new float[] {3200, 3200, 2000, 1500, 0},
                new float[] {-0.05f, 0.01f, 0, 0, 0}, null, null, Double.NaN, Double.NaN);
        CameraIntrinsics k = IntrinsicsEstimate.of(camera, 640, 480).intrinsics();
        if (!k.isDistorted()) {
            throw new IllegalStateException("the shrunk intrinsics lost the lens: " + k);
        }
        GrayImage image = new SyntheticCamera(k).render(List.of(PlacedMarker.of(MarkerPattern.of(MarkerDictionary.DEFAULT,
                0), 0.1, PlacedMarker.facingCamera(30, 10, 20), new double[] {0.02, 0.01, 0.5})), SceneOptions.camera(1));
        ArSession session = ArSession.of(new FiducialTracker(TrackerConfig.defaults(0.1), k));
        if (!session.onCameraFrame(image, 1).visible()) {
            throw new IllegalStateException("the shrunk tracker did not find the marker");
        }
    }
}
