package org.skinlab.simulation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.EnumSet;
import java.util.Set;
import java.util.SplittableRandom;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Supplier;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.animation.WrapMode;
import org.skinlab.mixer.Mixer;
import org.skinlab.model.Model;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningGlsl;
import org.skinlab.skinning.SkinningMethod;

/**
 * A reader takes 100,000 snapshots while the simulation steps as fast as it can and another
 * thread flips every switch at random (CPU skinning included, so about half the frames are
 * palette-only); {@link FrameChecker} recomputes each snapshot's palette and mesh from the step
 * it claims to be and demands bit-for-bit equality, so a frame mixing two steps fails the test.
 * The last tests run the same harness against a writer that fills the published buffer in place
 * ({@link InPlaceWriter}: the race the snapshot design prevents) and require the checker to catch
 * it, the palette check and the mesh check each on its own: the checks can fail.
 */
class TornFrameTest {
    private static final int SNAPSHOTS = 100_000;
    /**
     * Distinct frames a clean run must have seen, so that it cannot pass by reading one frame
     * while a starved writer stands still; the reader goes on past {@link #SNAPSHOTS} until it has.
     */
    private static final int MIN_DISTINCT_FRAMES = 500;
    /** The reader gives up after this long even without enough distinct frames (and the test fails). */
    private static final long READ_NANOS = 20_000_000_000L;
    private static final Model RIBBON = TwistRibbon.model();

    /**
     * What one run of the harness saw; {@code skinnedFrames} counts the frames with a CPU-skinned
     * mesh of a method the shader has (one without shader code is CPU-skinned in either mode).
     */
    private record Result(int snapshots, int tornPalettes, int tornMeshes, String firstProblem, long distinctFrames,
            int backwards, Set<SkinningMethod> methods, Set<RotationInterpolation> interpolations, int skinnedFrames,
            int paletteOnlyFrames) {
        int torn() {
            return Math.max(tornPalettes, tornMeshes);
        }
    }

    /**
     * A writer without the snapshot protocol: every step is skinned straight into the one buffer
     * readers are given (the thesis' design without its mutex), with the mesh's clock rule. It
     * spends most of its time inside that write, so readers land in half-written frames, on two
     * cores or one (a writer preempted mid-frame leaves its frame half-written for the whole time
     * slice).
     */
    private static final class InPlaceWriter {
        private final AnimationConfig config;
        private final SkinnedModel skinned = new SkinnedModel(RIBBON, RIBBON.clips().get(0),
                NormalTransform.INVERSE_TRANSPOSE);
        private final Mixer mixer = new Mixer(RIBBON, skinned.skeleton());
        private final FrameWriter writer = new FrameWriter(skinned, mixer);
        /** One buffer, published once: readers lease it while the writer keeps filling it. */
        private final FramePool pool = writer.newPool(1);
        private final Frame shared = pool.claim();
        private double playback;
        private long sequence;

        InPlaceWriter(AnimationConfig config) {
            this.config = config;
            mixer.base().play(RIBBON.clips().get(0).name());
            writer.write(shared, playback, config.settings(), sequence++);
            pool.publish(shared);
        }

        void step() {
            AnimationConfig.Settings s = config.settings();
            if (s.animationRunning()) {
                mixer.base().setWrapMode(s.wrapMode());
                mixer.advance(0.001 * s.speed());
                playback = mixer.base().time();
            }
            writer.write(shared, playback, s, sequence++);
        }

        Frame acquire() {
            return pool.acquire();
        }
    }

    @Test
    @Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void readerNeverSeesATornFrameWhileStepsRunFlatOutOnAnotherThread() throws Exception {
        try (SkeletalAnimatedMesh mesh = new SkeletalAnimatedMesh(RIBBON, RIBBON.clips().get(0), new AnimationConfig())) {
            Result r = hammer(mesh.config(), mesh::acquire, () -> mesh.step(0.001), true, SNAPSHOTS,
                    Integer.MAX_VALUE);
            assertClean(r);
        }
    }

    @Test
    @Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void readerNeverSeesATornFrameFromTheSimulationThread() throws Exception {
        try (SkeletalAnimatedMesh mesh = new SkeletalAnimatedMesh(RIBBON, RIBBON.clips().get(0), new AnimationConfig())) {
            mesh.setStepRate(SkeletalAnimatedMesh.MAX_STEP_RATE);
            mesh.start();
            Result r;
            try {
                r = hammer(mesh.config(), mesh::acquire, null, true, SNAPSHOTS, Integer.MAX_VALUE);
            } finally {
                mesh.stop();
            }
            assertClean(r);
            assertTrue(mesh.failure() == null, () -> "simulation failed: " + mesh.failure());
        }
    }

    @Test
    @Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void theCheckCatchesTornFramesWhenTheSimulationWritesIntoThePublishedBuffer() throws Exception {
        InPlaceWriter inPlace = new InPlaceWriter(new AnimationConfig());
        Result r = hammer(inPlace.config, inPlace::acquire, inPlace::step, false, SNAPSHOTS, 20);
        assertTrue(r.tornMeshes() > 0, () -> "no torn mesh detected in " + r.snapshots() + " snapshots of "
                + r.distinctFrames() + " frames written in place: the mesh check would not notice tearing");
        assertTrue(r.tornPalettes() > 0, () -> "no torn palette detected in " + r.snapshots() + " snapshots of "
                + r.distinctFrames() + " frames written in place: the palette check would not notice tearing");
    }

    @Test
    @Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void theCheckCatchesTornPaletteOnlyFramesWrittenIntoThePublishedBuffer() throws Exception {
        // Palette-only frames have no mesh to compare: the palette check alone must see the tearing.
        AnimationConfig config = new AnimationConfig();
        config.setCpuSkinning(false);
        InPlaceWriter inPlace = new InPlaceWriter(config);
        Result r = hammer(config, inPlace::acquire, inPlace::step, false, SNAPSHOTS, 20);
        assertEquals(0, r.skinnedFrames(), "a frame had a mesh although CPU skinning stayed off");
        assertTrue(r.tornPalettes() > 0, () -> "no torn palette detected in " + r.snapshots() + " snapshots of "
                + r.distinctFrames() + " palette-only frames written in place");
    }

    private static void assertClean(Result r) {
        assertEquals(0, r.torn(), () -> r.torn() + " torn frames, first: " + r.firstProblem());
        assertEquals(0, r.backwards(), "sequence numbers went backwards");
        assertTrue(r.snapshots() >= SNAPSHOTS, () -> "only " + r.snapshots() + " snapshots");
        // Not a vacuous pass: the reader saw the simulation move and the switches change.
        assertTrue(r.distinctFrames() >= MIN_DISTINCT_FRAMES,
                () -> "only " + r.distinctFrames() + " distinct frames seen in " + r.snapshots() + " snapshots");
        assertEquals(EnumSet.allOf(SkinningMethod.class), r.methods());
        assertTrue(r.interpolations().size() >= 2, () -> "interpolations seen: " + r.interpolations());
        assertTrue(r.skinnedFrames() > 0 && r.paletteOnlyFrames() > 0, () -> r.skinnedFrames() + " skinned and "
                + r.paletteOnlyFrames() + " palette-only snapshots: CPU skinning was not switched both ways");
    }

    /**
     * Runs a writer ({@code writerStep} over and over on a thread of its own, or nothing when the
     * simulation thread already runs) and a settings flipper (CPU skinning among its switches if
     * {@code flipCpuSkinning}) while this thread takes at least {@code snapshots} snapshots from
     * {@code reader} and checks each, going on until it has seen {@link #MIN_DISTINCT_FRAMES}
     * frames (or {@link #READ_NANOS} passed); stops early once {@code maxTorn} torn palettes and as
     * many torn meshes (if any frame had a mesh) were seen.
     */
    private static Result hammer(AnimationConfig config, Supplier<Frame> reader, Runnable writerStep,
            boolean flipCpuSkinning, int snapshots, int maxTorn) throws InterruptedException {
        AtomicBoolean done = new AtomicBoolean();
        AtomicReference<Throwable> helperFailure = new AtomicReference<>();
        Thread writer = null;
        if (writerStep != null) {
            writer = new Thread(() -> {
                try {
                    while (!done.get()) {
                        writerStep.run();
                    }
                } catch (Throwable t) {
                    helperFailure.compareAndSet(null, t);
                }
            }, "test-writer");
            writer.start();
        }
        Thread flipper = new Thread(() -> {
            SplittableRandom random = new SplittableRandom(42);
            SkinningMethod[] methods = SkinningMethod.values();
            RotationInterpolation[] interpolations = RotationInterpolation.values();
            WrapMode[] wraps = WrapMode.values();
            try {
                while (!done.get()) {
                    switch (random.nextInt(flipCpuSkinning ? 8 : 7)) {
                        case 0 -> config.setMethod(methods[random.nextInt(methods.length)]);
                        case 1 -> config.setInterpolation(interpolations[random.nextInt(interpolations.length)]);
                        case 2 -> config.setSpeed((random.nextBoolean() ? 1 : -1) * random.nextDouble(0.05, 20));
                        case 3 -> config.setAnimationRunning(random.nextInt(5) > 0); // mostly running
                        case 4 -> config.setMeshUpdatesRunning(random.nextInt(10) > 0); // mostly on
                        case 5 -> config.setWrapMode(wraps[random.nextInt(wraps.length)]);
                        case 6 -> config.setFollowCamera(random.nextBoolean());
                        default -> config.setCpuSkinning(random.nextBoolean());
                    }
                    LockSupport.parkNanos(20_000);
                }
            } catch (Throwable t) {
                helperFailure.compareAndSet(null, t);
            }
        }, "test-flipper");
        flipper.start();

        FrameChecker checker = FrameChecker.ribbon(RIBBON);
        int tornPalettes = 0;
        int tornMeshes = 0;
        int skinned = 0;
        int paletteOnly = 0;
        int backwards = 0;
        String first = null;
        long distinct = 0;
        long lastSequence = -1;
        Set<SkinningMethod> methods = EnumSet.noneOf(SkinningMethod.class);
        Set<RotationInterpolation> interpolations = EnumSet.noneOf(RotationInterpolation.class);
        int taken = 0;
        long giveUp = System.nanoTime() + READ_NANOS;
        try {
            while ((taken < snapshots || distinct < MIN_DISTINCT_FRAMES && System.nanoTime() - giveUp < 0)
                    && !(tornPalettes >= maxTorn && (tornMeshes >= maxTorn || skinned == 0))) {
                try (Frame frame = reader.get()) {
                    taken++;
                    if (!frame.hasSkinnedMesh()) {
                        paletteOnly++;
                    } else if (SkinningGlsl.hasCode(frame.method())) {
                        // A method without shader code is skinned on the CPU in either mode.
                        skinned++;
                    }
                    FrameChecker.Verdict verdict = checker.check(frame);
                    if (verdict.palette() != null) {
                        tornPalettes++;
                    }
                    if (verdict.mesh() != null) {
                        tornMeshes++;
                    }
                    if (first == null) {
                        first = verdict.problem();
                    }
                    long s = frame.sequence();
                    if (s < lastSequence) {
                        backwards++;
                    } else if (s > lastSequence) {
                        distinct++;
                    }
                    lastSequence = s;
                    methods.add(frame.method());
                    interpolations.add(frame.interpolation());
                }
            }
        } finally {
            done.set(true);
            flipper.join();
            if (writer != null) {
                writer.join();
            }
        }
        if (helperFailure.get() != null) {
            throw new AssertionError("a helper thread failed", helperFailure.get());
        }
        return new Result(taken, tornPalettes, tornMeshes, first, distinct, backwards, methods, interpolations,
                skinned, paletteOnly);
    }
}
