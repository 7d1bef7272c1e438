package org.skinlab.android.logic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.skinlab.animation.LocalPose;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.animation.Skeleton;
import org.skinlab.ar.MarkerScene;
import org.skinlab.importer.ModelImporter;
import org.skinlab.mixer.Mixer;
import org.skinlab.model.Model;
import org.skinlab.scene.ModelFraming;
import org.skinlab.simulation.Frame;
import org.skinlab.simulation.SkeletalAnimatedMesh;

/**
 * The steering that keeps a root-motion walker on the marker: a character pushed forward at a
 * constant speed stays within the circle over many loops, at any heading it starts with; the
 * humanoid's real walk through the mixer does too; a faster clip than the rule can hold leaves
 * the circle by no more than its turning circle allows and comes back; the circle's size from
 * the model and the marker scene.
 */
class MarkerSteeringTest {
    private static final Path CHARACTERS = Path.of(System.getProperty("skinlab.root", "."), "assets", "characters");
    private static final double STEP_SECONDS = 1 / 60.0;
    /** The humanoid's walk on the marker: 1.2 m/s for a 1.8 m tall character, in the area's units. */
    private static final double RADIUS = 0.48;
    private static final double[] Y_UP = {0, 1, 0};

    /** Forward at {@code step} a step along the heading (+z turned about +y, as the mixer turns), steered. */
    private static double[] walk(MarkerSteering steering, double step, double heading, int steps) {
        double x = 0;
        double z = 0;
        double h = heading;
        double farthest = 0;
        double largestTurn = 0;
        double closestAfterLeaving = Double.POSITIVE_INFINITY;
        boolean wentOut = false;
        double[] placement = new double[4];
        for (int i = 0; i < steps; i++) {
            placement[0] = x;
            placement[2] = z;
            placement[3] = h;
            double turn = steering.turn(placement);
            largestTurn = Math.max(largestTurn, Math.abs(turn));
            h += turn;
            x += step * Math.sin(h);
            z += step * Math.cos(h);
            double r = Math.hypot(x, z);
            farthest = Math.max(farthest, r);
            wentOut |= r > RADIUS / 2;
            if (wentOut) {
                closestAfterLeaving = Math.min(closestAfterLeaving, r);
            }
        }
        return new double[] {farthest, largestTurn, closestAfterLeaving};
    }

    @Test
    void aConstantWalkStaysWithinTheCircleOverManyLoops() {
        // The walk (0.02 a step), slower (the Slower button), and the fastest the rule holds.
        double fastest = MarkerSteering.MAX_TURN_RADIANS * MarkerSteering.TURN_RADIUS_OVER_AREA * RADIUS;
        for (double step : new double[] {0.02, 0.01, 0.005, fastest}) {
            for (int start = 0; start < 8; start++) {
                double heading = start * Math.PI / 4 + 0.1;
                MarkerSteering steering = new MarkerSteering(new MarkerArea(Y_UP, RADIUS));
                double[] walked = walk(steering, step, heading, 100 * 60); // 100 one-second walk loops
                assertTrue(walked[0] <= RADIUS * (1 + 1e-6), "step " + step + ", heading " + heading
                        + ": reached " + walked[0] + " of " + RADIUS);
                assertTrue(walked[0] > 0.8 * RADIUS, "it walks across the area, not in a small circle: " + walked[0]);
                assertTrue(walked[1] <= MarkerSteering.MAX_TURN_RADIANS + 1e-12, "a few degrees a step: " + walked[1]);
            }
        }
    }

    @Test
    void aClipTooFastToHoldComesBackWithinItsTurningCircle() {
        double step = 3.5 * STEP_SECONDS; // the run, 3.5 m/s
        double rho = step / MarkerSteering.MAX_TURN_RADIANS;
        MarkerSteering steering = new MarkerSteering(new MarkerArea(Y_UP, RADIUS));
        double[] walked = walk(steering, step, 0.3, 100 * 60);
        assertTrue(walked[0] > RADIUS, "the rule says it cannot hold this speed: " + walked[0]);
        assertTrue(walked[0] <= 2 * rho + step, "at most the turning circle's diameter out: " + walked[0]);
        assertTrue(walked[2] < RADIUS / 2, "and back near the centre: " + walked[2]);
    }

    @Test
    void standingStillOrTheFirstStepTurnsNothing() {
        MarkerSteering steering = new MarkerSteering(new MarkerArea(Y_UP, RADIUS));
        double[] far = {2 * RADIUS, 0, 0, 0};
        assertEquals(0, steering.turn(far), "the first call only measures");
        assertEquals(0, steering.turn(far), "no move, no direction of travel");
        assertTrue(steering.turn(new double[] {2.1 * RADIUS, 0, 0, 0}) != 0, "walking away outside: turns");
        steering.reset();
        assertEquals(0, steering.turn(new double[] {2.2 * RADIUS, 0, 0, 0}), "after a reset it measures again");
    }

    @Test
    void turnsTowardsTheCentreAboutAnyUpAxis() {
        // Z up: walking along +x at y = -R, the centre lies to the left: a positive turn about +z,
        // as much as keeps the turning circle at 0.4 R for this step length.
        MarkerSteering steering = new MarkerSteering(new MarkerArea(new double[] {0, 0, 2}, RADIUS));
        steering.turn(new double[] {0, -RADIUS, 5, 0});
        double turn = steering.turn(new double[] {0.01, -RADIUS, 7, 0}); // the height is not a move
        assertEquals(0.01 / (MarkerSteering.TURN_RADIUS_OVER_AREA * RADIUS), turn, 1e-12);
        // Walking along -x there, the centre lies to the right: a negative turn.
        steering.turn(new double[] {-0.04, -RADIUS, 0, 0});
        assertEquals(-MarkerSteering.MAX_TURN_RADIANS, steering.turn(new double[] {-0.1, -RADIUS, 0, 0}), 1e-12,
                "capped for a long step");
    }

    /**
     * The humanoid's walk through the real mixer, steered once a step as the app does, 60 loops:
     * within the circle the app computes for it, and truly walking (root motion moves it); the
     * Y-up glTF file and its Z-up COLLADA twin, which walks along another axis.
     */
    @Test
    void theHumanoidsWalkStaysOnTheMarker() throws Exception {
        for (String file : new String[] {"humanoid-moves.glb", "humanoid-moves.dae"}) {
            Model model = read(file);
            Skeleton skeleton = Skeleton.of(model);
            MarkerArea area = area(model, new MarkerScene(0.1));
            Mixer mixer = new Mixer(model, skeleton);
            mixer.base().play("walk");
            mixer.setRootMotion("walk", true);
            MarkerSteering steering = new MarkerSteering(area);
            LocalPose pose = skeleton.newLocalPose();
            double[] p = new double[4];
            double[] last = new double[4];
            double farthest = 0;
            double walked = 0;
            for (int i = 0; i < 60 * 60; i++) {
                steering.steer(mixer);
                mixer.advance(STEP_SECONDS);
                mixer.evaluate(RotationInterpolation.SLERP, pose);
                mixer.placementPosition(p);
                farthest = Math.max(farthest, across(area, p[0], p[1], p[2]));
                walked += across(area, p[0] - last[0], p[1] - last[1], p[2] - last[2]);
                System.arraycopy(p, 0, last, 0, 4);
            }
            assertTrue(walked > 60, file + ": a minute of walking at 1.2 m/s: " + walked);
            assertTrue(farthest <= area.radius() * (1 + 1e-6), file + ": " + farthest + " within " + area.radius());
            assertTrue(farthest > 0.8 * area.radius(), file + ": across the area: " + farthest);
        }
    }

    /**
     * 0.4 marker widths for a model MarkerScene makes 1.5 marker widths tall: the humanoid's 1.8 m
     * give 0.48 m in its own metres, whatever the marker's size; and the Z-up COLLADA twin of the
     * walker gets the same circle as its Y-up glTF twin once its units are counted.
     */
    @Test
    void theCircleIsAFractionOfTheMarkerInTheModelsUnits() throws Exception {
        Model moves = read("humanoid-moves.glb");
        MarkerArea small = area(moves, new MarkerScene(0.05));
        MarkerArea large = area(moves, new MarkerScene(0.2));
        assertEquals(small.radius(), large.radius(), 1e-9, "the model scales with the marker");
        assertEquals(0.4 * 1.805 / 1.5, small.radius(), 0.002);
        assertEquals(1, small.up()[1], 1e-6, "glTF is Y up");

        MarkerArea dae = area(read("humanoid-walk.dae"), new MarkerScene(0.1));
        MarkerArea glb = area(read("humanoid-walk.glb"), new MarkerScene(0.1));
        assertEquals(1, Math.abs(dae.up()[2]), 1e-6, "the COLLADA file is Z up: " + java.util.Arrays.toString(dae.up()));
        assertEquals(glb.radius(), dae.radius(), 0.01 * glb.radius(), "the same character, the same circle");
    }

    /** The length of (x, y, z) across the area's up axis. */
    private static double across(MarkerArea area, double x, double y, double z) {
        double[] u = area.up();
        double h = x * u[0] + y * u[1] + z * u[2];
        return Math.sqrt(x * x + y * y + z * z - h * h);
    }

    private static MarkerArea area(Model model, MarkerScene scene) {
        try (SkeletalAnimatedMesh mesh = SkeletalAnimatedMesh.of(model); Frame f = mesh.acquire()) {
            return MarkerArea.of(model, Skeleton.of(model), ModelFraming.of(model.asset(), mesh.geometries(), f), scene,
                    MarkerArea.RADIUS_OVER_MARKER);
        }
    }

    private static Model read(String name) throws Exception {
        try (InputStream in = Files.newInputStream(CHARACTERS.resolve(name))) {
            return ModelImporter.read(in, name, null);
        }
    }
}
