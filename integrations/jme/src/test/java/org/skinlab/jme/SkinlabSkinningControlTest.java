package org.skinlab.jme;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.nio.FloatBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import com.jme3.anim.AnimClip;
import com.jme3.anim.AnimComposer;
import com.jme3.anim.AnimTrack;
import com.jme3.anim.TransformTrack;
import com.jme3.anim.tween.action.BlendableAction;
import com.jme3.math.Vector3f;
import com.jme3.scene.Geometry;
import com.jme3.scene.Spatial;
import com.jme3.scene.VertexBuffer;
import org.junit.AfterClass;
import org.junit.BeforeClass;
import org.junit.Test;
import org.skinlab.skinning.SkinningGlsl;
import org.skinlab.skinning.SkinningMethod;

/**
 * The control's CPU path (the mesh's Position buffer) and GPU path (positions read back from the
 * GPU, {@link GpuReadback}) against skinlab's own CLI ({@code skinlab pose}) on every bundled glb
 * and every skinlab-exported glb (-Pexported=DIR), for LBS, DQS and CoR, at three key times of the
 * file's first clip (about 0.2, 0.45 and 0.85 through, {@link #keyTimes}): world positions agree within 1e-5 of the model's size (its bounding box
 * diagonal at that time). Times on keys, so that jME's and skinlab's interpolation between keys
 * (nlerp against slerp) does not enter: the test is about the skinning.
 */
public class SkinlabSkinningControlTest {
    private static final double TOLERANCE = 1e-5;
    private static final SkinningMethod[] METHODS = {SkinningMethod.LBS, SkinningMethod.DQS, SkinningMethod.COR};
    private static OffscreenApp app;
    private static Path repository;
    private static final List<String> report = new ArrayList<>();

    @BeforeClass
    public static void start() {
        repository = Paths.get(System.getProperty("skinlab.repository", "../..")).toAbsolutePath().normalize();
        app = OffscreenApp.shared();
    }

    @AfterClass
    public static void stop() throws IOException {
        Path out = Paths.get("build/reports/skinning-errors.txt");
        Files.createDirectories(out.getParent());
        Files.write(out, report);
    }

    @Test
    public void bundledAssetsAgreeWithSkinlabPose() throws Exception {
        List<Path> files = GlbFiles.under(repository.resolve("assets"));
        assertFalse("no glb under " + repository.resolve("assets"), files.isEmpty());
        // -Ponly=TEXT: only the files whose path contains TEXT (while investigating one).
        files.removeIf(f -> !f.toString().contains(System.getProperty("skinlab.only", "")));
        List<String> failures = new ArrayList<>();
        for (Path f : files) {
            checkFile(f, failures);
        }
        assertTrue("over the tolerance:\n" + String.join("\n", failures), failures.isEmpty());
    }

    @Test
    public void theOtherMethodsAgreeWithSkinlabPoseToo() throws Exception {
        // Beyond the three the issue asks for: bulge-free DQS and STBS on both paths, spline on
        // the CPU (it has no shader code), on the assets made for them and the walking character.
        List<String> failures = new ArrayList<>();
        for (String asset : new String[] {"characters/humanoid-walk.glb", "twist/arm-twist.glb",
                "stretch/limb-stretch.glb", "cylinders/cylinder-bend.glb"}) {
            Path f = repository.resolve("assets").resolve(asset);
            if (f.toString().contains(System.getProperty("skinlab.only", ""))) {
                checkFile(f, failures, new SkinningMethod[] {SkinningMethod.BFDQS, SkinningMethod.STBS_LBS,
                        SkinningMethod.STBS_DQS, SkinningMethod.SPLINE});
            }
        }
        assertTrue("over the tolerance:\n" + String.join("\n", failures), failures.isEmpty());
    }

    @Test
    public void exportedAssetsAgreeWithSkinlabPose() throws Exception {
        String dir = System.getProperty("skinlab.exported", "");
        if (dir.isEmpty()) {
            // Nothing to check without -Pexported: the bundled test above runs regardless.
            return;
        }
        List<Path> files = GlbFiles.under(Paths.get(dir));
        assertFalse("no glb under " + dir, files.isEmpty());
        files.removeIf(f -> !f.toString().contains(System.getProperty("skinlab.only", "")));
        List<String> failures = new ArrayList<>();
        for (Path f : files) {
            assertTrue(f + " carries no SKINLAB_skinning", GlbFiles.hasCentres(f));
            // The centres the control uses are the file's: jME's loader kept them (SkinlabGltfExtension).
            int withCentres = app.call(() -> {
                app.getAssetManager().clearCache();
                Spatial model = app.getAssetManager().loadModel(f.toString());
                int[] count = {0};
                model.depthFirstTraversal(s -> {
                    if (s instanceof Geometry && ((Geometry) s).getMesh().getBuffer(MeshBinding.CENTRES) != null) {
                        count[0]++;
                    }
                });
                return count[0];
            });
            assertTrue(f + ": no mesh got the file's _COR_CENTER", withCentres > 0);
            checkFile(f, failures);
        }
        assertTrue("over the tolerance:\n" + String.join("\n", failures), failures.isEmpty());
    }

    private void checkFile(Path file, List<String> failures) throws Exception {
        checkFile(file, failures, METHODS);
    }

    private void checkFile(Path file, List<String> failures, SkinningMethod[] methods) throws Exception {
        Path cli = SkinlabPose.cli(repository);
        String clip = GlbFiles.firstClip(file);
        double[] times = keyTimes(file, clip);
        for (SkinningMethod method : methods) {
            SkinlabPose reference = SkinlabPose.run(cli, file, method.key(), times);
            assertEquals(file + ": skinlab's clip", clip, reference.clip);
            for (int i = 0; i < times.length; i++) {
                assertEquals(file + ": skinlab's time " + i, (float) times[i], (float) reference.times[i], 0f);
            }
            for (SkinlabSkinningControl.Mode mode : SkinlabSkinningControl.Mode.values()) {
                if (mode == SkinlabSkinningControl.Mode.GPU && !SkinningGlsl.hasCode(method)) {
                    continue;
                }
                double worst = compare(file, clip, times, method, mode, reference);
                String line = String.format(Locale.ROOT, "%-8s %-3s %-45s worst %.3e of size (tolerance %.0e)",
                        method.key(), mode, repository.relativize(file.toAbsolutePath()).toString().startsWith("..")
                                ? file.toString() : repository.relativize(file.toAbsolutePath()).toString(),
                        worst, TOLERANCE);
                System.out.println(line);
                report.add(line);
                if (!(worst <= TOLERANCE)) {
                    failures.add(line);
                }
            }
        }
    }

    /**
     * Three key times of the clip's first track with keys, about 0.2, 0.45 and 0.85 through (as the
     * three.js add-on's test). Not the middle: the "full" cylinders bend and twist by 180 degrees
     * there, where DQS and CoR jump (two rotations half a turn apart tie for the hemisphere test,
     * Kavan et al. 2008) and float noise decides the side.
     */
    private double[] keyTimes(Path file, String clip) {
        return app.call(() -> {
            app.getAssetManager().clearCache();
            Spatial model = app.getAssetManager().loadModel(file.toString());
            AnimClip c = composer(model).getAnimClip(clip);
            float[] keys = null;
            for (AnimTrack<?> t : c.getTracks()) {
                if (t instanceof TransformTrack && ((TransformTrack) t).getTimes().length >= 4) {
                    keys = ((TransformTrack) t).getTimes();
                    break;
                }
            }
            if (keys == null) {
                throw new IllegalStateException(file + ": clip " + clip + " has no track with 4 keys");
            }
            int n = keys.length;
            // Never the last key: jME's composer wraps a looping clip's end to its start.
            return new double[] {keys[Math.max(1, n / 5)], keys[9 * n / 20], keys[Math.min(n - 2, 17 * n / 20)]};
        });
    }

    private static AnimComposer composer(Spatial model) {
        List<AnimComposer> found = new ArrayList<>();
        model.depthFirstTraversal(s -> {
            if (s.getControl(AnimComposer.class) != null) {
                found.add(s.getControl(AnimComposer.class));
            }
        });
        if (found.size() != 1) {
            throw new IllegalStateException(model.getName() + ": " + found.size() + " AnimComposers");
        }
        return found.get(0);
    }

    /** The worst distance to skinlab's position over every vertex and time, divided by the model's size. */
    private double compare(Path file, String clip, double[] times, SkinningMethod method,
            SkinlabSkinningControl.Mode mode, SkinlabPose reference) {
        SkinlabSkinningControl control = app.call(() -> {
            app.getAssetManager().clearCache();
            Spatial model = app.getAssetManager().loadModel(file.toString());
            SkinlabSkinningControl c = SkinlabSkinningControl.replace(model, method, mode, app.getAssetManager());
            AnimComposer composer = composer(model);
            // No cross-fade from the rest pose when the clip starts (jME's BlendableAction blends over
            // its first 0.4 s by default): the pose at each time is the clip's own.
            ((BlendableAction) composer.action(clip)).setTransitionLength(0);
            composer.setCurrentAction(clip);
            composer.setGlobalSpeed(0);
            app.getRootNode().attachChild(model);
            return c;
        });
        List<Geometry> geometries = control.geometries();
        assertEquals(file + ": meshes", reference.meshes.size(), geometries.size());
        double worst = 0;
        try {
            for (int t = 0; t < times.length; t++) {
                double time = times[t];
                app.call(() -> {
                    composer(app.getRootNode().getChild(0)).setTime(time);
                    return null;
                });
                app.frames(2);
                for (int g = 0; g < geometries.size(); g++) {
                    Geometry geometry = geometries.get(g);
                    float[] jme = app.call(() -> mode == SkinlabSkinningControl.Mode.CPU ? cpuWorld(geometry)
                            : GpuReadback.worldPositions(app.getRenderManager(), app.getCamera(), geometry));
                    int[] order = PositionOrder.positionOfVertex(geometry.getMesh());
                    float[] expected = reference.meshes.get(g)[t];
                    assertEquals(file + ": skinlab's positions against the welded jME vertices",
                            expected.length / 3, order[order.length - 1]);
                    worst = Math.max(worst, worstError(jme, order, expected));
                }
            }
        } finally {
            app.call(() -> {
                app.getRootNode().detachAllChildren();
                return null;
            });
        }
        return worst;
    }

    private static float[] cpuWorld(Geometry g) {
        FloatBuffer p = (FloatBuffer) g.getMesh().getBuffer(VertexBuffer.Type.Position).getData();
        int n = g.getMesh().getVertexCount();
        float[] out = new float[3 * n];
        Vector3f v = new Vector3f();
        for (int i = 0; i < n; i++) {
            v.set(p.get(3 * i), p.get(3 * i + 1), p.get(3 * i + 2));
            g.getWorldTransform().transformVector(v, v);
            out[3 * i] = v.x;
            out[3 * i + 1] = v.y;
            out[3 * i + 2] = v.z;
        }
        return out;
    }

    private static double worstError(float[] jme, int[] positionOfVertex, float[] expected) {
        double[] min = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE};
        double[] max = {-Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        for (int i = 0; i < expected.length; i++) {
            min[i % 3] = Math.min(min[i % 3], expected[i]);
            max[i % 3] = Math.max(max[i % 3], expected[i]);
        }
        double size = Math.sqrt(sq(max[0] - min[0]) + sq(max[1] - min[1]) + sq(max[2] - min[2]));
        double worst = 0;
        for (int v = 0; v < jme.length / 3; v++) {
            int p = positionOfVertex[v];
            double d = Math.sqrt(sq(jme[3 * v] - expected[3 * p]) + sq(jme[3 * v + 1] - expected[3 * p + 1])
                    + sq(jme[3 * v + 2] - expected[3 * p + 2]));
            if (d / size > worst && System.getProperty("skinlab.debug") != null) {
                System.out.println("vertex " + v + " position " + p + " jme " + jme[3 * v] + "," + jme[3 * v + 1] + "," + jme[3 * v + 2]
                        + " skinlab " + expected[3 * p] + "," + expected[3 * p + 1] + "," + expected[3 * p + 2] + " size " + size);
            }
            worst = Math.max(worst, d / size);
        }
        return worst;
    }

    private static double sq(double x) {
        return x * x;
    }
}
