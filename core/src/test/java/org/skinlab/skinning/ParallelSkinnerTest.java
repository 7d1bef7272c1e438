package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Random;

import org.joml.Matrix4f;
import org.joml.Quaternionf;
import org.junit.jupiter.api.Test;

/** {@link ParallelSkinner}: the same output as one thread, every point once, aligned parts. */
class ParallelSkinnerTest {
    private static SkinnedGeometry geometry(int points) {
        Random r = new Random(points);
        float[] pos = new float[3 * points];
        float[] nrm = new float[3 * points];
        int[] joints = new int[4 * points];
        float[] weights = new float[4 * points];
        for (int i = 0; i < 3 * points; i++) {
            pos[i] = r.nextFloat() * 2 - 1;
            nrm[i] = r.nextFloat() * 2 - 1;
        }
        for (int i = 0; i < 4 * points; i++) {
            joints[i] = r.nextInt(6);
            weights[i] = 0.25f;
        }
        float[] bind = new float[16 * 6];
        for (int j = 0; j < 6; j++) {
            new Matrix4f().get(bind, 16 * j);
        }
        // A chain 0 <- 1 <- ... <- 5, so that the bone methods have bones with parents.
        return SkinnedGeometry.fromArrays(pos, nrm, 4, joints, weights, bind, new int[] {-1, 0, 1, 2, 3, 4}).withCentresOfRotation();
    }

    /** Random rigid joints, prepared for every method. */
    private static JointPalette palette(SkinnedGeometry g) {
        JointPalette p = g.newPalette();
        Random r = new Random(3);
        for (int j = 0; j < 6; j++) {
            p.setMatrix(j, new Matrix4f().translationRotate(r.nextFloat(), r.nextFloat(), r.nextFloat(),
                    new Quaternionf().rotateXYZ(r.nextFloat() * 3, r.nextFloat() * 3, r.nextFloat() * 3)));
        }
        p.prepareAll();
        return p;
    }

    @Test
    void givesBitIdenticalResultsToOneThreadForEveryMethodAndThreadCount() {
        // Each point is computed by the same kernel code whichever thread runs it: equal bits.
        // 10007 points: chunks of at least 2048 points, so 2 to 4 threads really split it.
        int points = 10007;
        SkinnedGeometry g = geometry(points);
        JointPalette palette = palette(g);
        for (SkinningMethod m : SkinningMethod.values()) {
            Skinner kernel = Skinners.scalar(m, g, NormalTransform.INVERSE_TRANSPOSE);
            float[] p1 = new float[3 * points];
            float[] n1 = new float[3 * points];
            kernel.skinAll(palette, p1, n1);
            for (int threads = 1; threads <= 4; threads++) {
                try (ParallelSkinner parallel = new ParallelSkinner(kernel, threads)) {
                    for (int frame = 0; frame < 50; frame++) { // many handoffs: spin and park paths
                        float[] p = new float[3 * points];
                        float[] n = new float[3 * points];
                        parallel.skinAll(palette, p, n);
                        assertArrayEquals(p1, p, m + ", " + threads + " threads, frame " + frame);
                        assertArrayEquals(n1, n, m + ", " + threads + " threads, frame " + frame);
                    }
                }
            }
        }
    }

    /** A kernel that records the ranges it is given. */
    private static class Recorder implements Skinner {
        final List<int[]> ranges = Collections.synchronizedList(new ArrayList<>());
        final List<int[]> deformationRanges = Collections.synchronizedList(new ArrayList<>());
        final SkinnedGeometry geometry;
        final int alignment;
        int throwAt = -1;

        Recorder(SkinnedGeometry geometry, int alignment) {
            this.geometry = geometry;
            this.alignment = alignment;
        }

        @Override
        public SkinningMethod method() {
            return SkinningMethod.LBS;
        }

        @Override
        public NormalTransform normalTransform() {
            return NormalTransform.BLENDED_MATRIX;
        }

        @Override
        public SkinnedGeometry geometry() {
            return geometry;
        }

        @Override
        public void skin(JointPalette palette, float[] outPositions, float[] outNormals, int from, int to) {
            ranges.add(new int[] {from, to});
            if (from <= throwAt && throwAt < to) {
                throw new IllegalStateException("point 50000");
            }
        }

        @Override
        public void skinDeformations(JointPalette palette, float[] outDeformations, int from, int to) {
            deformationRanges.add(new int[] {from, to});
        }

        @Override
        public int rangeAlignment() {
            return alignment;
        }

        @Override
        public String implementation() {
            return "recorder";
        }
    }

    @Test
    void deformationsAreSplitLikePoints() {
        SkinnedGeometry g = geometry(10);
        Recorder k = new Recorder(g, 8);
        try (ParallelSkinner parallel = new ParallelSkinner(k, 2)) {
            parallel.skinDeformations(null, null, 3, 99_997);
        }
        assertTrue(k.ranges.isEmpty(), "skinDeformations must not call skin");
        assertTrue(k.deformationRanges.size() > 1, "the range is split");
        List<int[]> sorted = new ArrayList<>(k.deformationRanges);
        sorted.sort((a, b) -> Integer.compare(a[0], b[0]));
        int next = 3;
        for (int[] r : sorted) {
            assertEquals(next, r[0], "chunks are contiguous and disjoint");
            next = r[1];
        }
        assertEquals(99_997, next);
    }

    @Test
    void partsCoverTheRangeOnceAndStartOnTheKernelsAlignment() {
        SkinnedGeometry g = geometry(10);
        for (int threads = 2; threads <= 3; threads++) {
            for (int[] range : new int[][] {{0, 100_000}, {3, 99_997}, {5, 9000}, {0, 17}, {8, 9}, {4095, 8193}}) {
                Recorder k = new Recorder(g, 8);
                try (ParallelSkinner parallel = new ParallelSkinner(k, threads)) {
                    parallel.skin(null, null, null, range[0], range[1]);
                }
                List<int[]> parts = new ArrayList<>(k.ranges);
                parts.sort((a, b) -> Integer.compare(a[0], b[0]));
                int next = range[0];
                for (int[] p : parts) {
                    assertEquals(next, p[0], "parts are contiguous: " + describe(parts));
                    assertTrue(p[0] == range[0] || p[0] % 8 == 0, "inner boundaries are aligned: " + describe(parts));
                    assertTrue(p[1] > p[0], "no empty parts: " + describe(parts));
                    next = p[1];
                }
                assertEquals(range[1], next, describe(parts));
                assertEquals(range[1] - range[0] >= 2 * 2048 ? Math.min(4 * threads, (range[1] - range[0]) / 2048) : 1,
                        parts.size(), "chunks: " + describe(parts));
            }
        }
    }

    @Test
    void anExceptionInAnyChunkReachesTheCaller() {
        Recorder k = new Recorder(geometry(10), 1);
        k.throwAt = 50_000;
        try (ParallelSkinner parallel = new ParallelSkinner(k, 2)) {
            // Whichever thread runs the chunk holding point 50000, the call throws its exception.
            for (int i = 0; i < 20; i++) {
                IllegalStateException e = assertThrows(IllegalStateException.class,
                        () -> parallel.skin(null, null, null, 0, 100_000));
                assertEquals("point 50000", e.getMessage());
            }
            parallel.skin(null, null, null, 60_000, 100_000); // the pool still works afterwards
        }
    }

    /**
     * Ranges that grow and shrink from frame to frame (2, then 16 chunks on 4 threads): every call
     * returns with its whole range written. A worker still leaving frame g must not take a chunk
     * of frame g + 1 under g's claim once the caller has written g + 1's larger chunk count, or
     * the caller could count it and return early. A stress test: the fault needs a worker
     * preempted in that window; with more threads than the project's 2 cores it showed within
     * 100,000 frames in one run of three before the claim was closed at the end of each frame.
     */
    @Test
    void everyCallReturnsWithItsWholeRangeWrittenWhenRangesChange() {
        Stamper k = new Stamper(geometry(10));
        float[] positions = new float[16 * 2048];
        try (ParallelSkinner parallel = new ParallelSkinner(k, 4)) {
            for (int frame = 1; frame <= 100_000; frame++) {
                int end = (frame % 2 == 0 ? 16 : 2) * 2048;
                parallel.skin(null, positions, new float[] {frame}, 0, end);
                for (int i = 0; i < end; i++) {
                    if (positions[i] != frame) {
                        throw new AssertionError("frame " + frame + ": point " + i + " holds " + positions[i]);
                    }
                }
            }
        }
    }

    /** Writes the call's stamp (its normals array's first value) to every position of its range. */
    private static final class Stamper extends Recorder {
        Stamper(SkinnedGeometry geometry) {
            super(geometry, 1);
        }

        @Override
        public void skin(JointPalette palette, float[] outPositions, float[] stamp, int from, int to) {
            Arrays.fill(outPositions, from, to, stamp[0]);
        }
    }

    @Test
    void closeStopsTheDaemonWorkers() throws Exception {
        Skinner kernel = Skinners.scalar(SkinningMethod.LBS, geometry(100), NormalTransform.BLENDED_MATRIX);
        ParallelSkinner parallel = new ParallelSkinner(kernel, 3);
        assertEquals(3, parallel.threads());
        assertSame(kernel.geometry(), parallel.geometry());
        long before = Thread.getAllStackTraces().keySet().stream()
                .filter(t -> t.getName().startsWith("skinlab-skinning-") && t.isAlive()).count();
        assertTrue(Thread.getAllStackTraces().keySet().stream()
                .filter(t -> t.getName().startsWith("skinlab-skinning-")).allMatch(Thread::isDaemon));
        assertTrue(before >= 2);
        parallel.close();
        Thread.sleep(50);
        long after = Thread.getAllStackTraces().keySet().stream()
                .filter(t -> t.getName().startsWith("skinlab-skinning-") && t.isAlive()).count();
        assertEquals(before - 2, after);
        assertThrows(IllegalStateException.class,
                () -> parallel.skinAll(palette(geometry(100)), new float[300], new float[300]));
        assertFalse(parallel.implementation().isEmpty());
    }

    private static String describe(List<int[]> parts) {
        StringBuilder sb = new StringBuilder();
        for (int[] p : parts) {
            sb.append(Arrays.toString(p));
        }
        return sb.toString();
    }
}
