package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.FloatBuffer;
import java.nio.ShortBuffer;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.skinlab.collada.Fixtures;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.model.Skin;

/**
 * {@link InfluenceView}: which influences a cap keeps, in which order, with which weights and
 * padding, and how they are packed. Expected values are worked out by hand in each test.
 */
class InfluenceViewTest {
    /** Renormalised weights are a float division of floats: within one rounding of the exact quotient. */
    private static final float ROUNDING = 1e-7f;
    /** The importer's weights went through one more division (by their sum, in SkinnedGeometry). */
    private static final float ROUNDINGS = 3e-7f;

    /** Identity bind matrices for a palette of {@code joints}. */
    private static float[] identities(int joints) {
        float[] m = new float[16 * joints];
        for (int j = 0; j < joints; j++) {
            m[16 * j] = m[16 * j + 5] = m[16 * j + 10] = m[16 * j + 15] = 1f;
        }
        return m;
    }

    /**
     * Four points of three influences each, given out of order (fromArrays keeps them as given):
     * 0 plain, 1 with a tie, 2 with one influence and padding, 3 with a zero weight on another joint.
     */
    private static SkinnedGeometry handMade() {
        int[] joints = {
            5, 2, 7,
            3, 1, 4,
            6, 6, 6,
            1, 2, 3};
        float[] weights = {
            0.2f, 0.5f, 0.3f,
            0.4f, 0.2f, 0.4f,
            1f, 0f, 0f,
            0.7f, 0f, 0.3f};
        return SkinnedGeometry.fromArrays(new float[12], new float[12], 3, joints, weights, identities(8));
    }

    private static int[] joints(InfluenceView v, int point) {
        int[] j = new int[v.influencesPerPoint()];
        for (int s = 0; s < j.length; s++) {
            j[s] = v.joint(point, s);
        }
        return j;
    }

    private static float[] weights(InfluenceView v, int point) {
        float[] w = new float[v.influencesPerPoint()];
        for (int s = 0; s < w.length; s++) {
            w[s] = v.weight(point, s);
        }
        return w;
    }

    @Test
    void capKeepsTheHeaviestRenormalisedAndTiesInTheGeometrysOrder() {
        InfluenceView v = InfluenceView.of(handMade(), 2);
        assertEquals(2, v.influencesPerPoint());
        assertEquals(3, v.sourceInfluencesPerPoint());
        // 0: 0.5 (joint 2) and 0.3 (joint 7) kept, 0.2 dropped: 0.5/0.8 and 0.3/0.8.
        assertArrayEquals(new int[] {2, 7}, joints(v, 0));
        assertArrayEquals(new float[] {0.625f, 0.375f}, weights(v, 0), ROUNDING);
        // 1: a tie at 0.4 between joints 3 and 4: both kept, 3 (given first) in slot 0.
        assertArrayEquals(new int[] {3, 4}, joints(v, 1));
        assertArrayEquals(new float[] {0.5f, 0.5f}, weights(v, 1), ROUNDING);
        // 2: one influence; nothing dropped, weights as given.
        assertArrayEquals(new int[] {6, 6}, joints(v, 2));
        assertArrayEquals(new float[] {1f, 0f}, weights(v, 2), 0f);
        // 3: 0.7 and 0.3 kept; the dropped influence weighs 0, so the weights stay bit for bit.
        assertArrayEquals(new int[] {1, 3}, joints(v, 3));
        assertArrayEquals(new float[] {0.7f, 0.3f}, weights(v, 3), 0f);
        assertEquals(2, v.cappedPointCount(), "points 0 and 1 lost weight; 2 and 3 lost only zeros");
        assertArrayEquals(new float[] {0.2f, 0.2f, 0f, 0f},
                new float[] {v.droppedWeight(0), v.droppedWeight(1), v.droppedWeight(2), v.droppedWeight(3)}, 0f);
    }

    @Test
    void aCapOfOneKeepsTheDominantJointWithWeightOne() {
        InfluenceView v = InfluenceView.of(handMade(), 1);
        int[] expected = {2, 3, 6, 1};
        for (int i = 0; i < 4; i++) {
            assertEquals(expected[i], v.joint(i, 0), "point " + i);
            assertEquals(1f, v.weight(i, 0), ROUNDING, "point " + i);
        }
        assertEquals(3, v.cappedPointCount());
    }

    @Test
    void aCapAboveTheWidthPadsWithZeroOnTheFirstJointAndKeepsWeightsBitForBit() {
        SkinnedGeometry g = handMade();
        InfluenceView v = InfluenceView.of(g, 5);
        // Sorted by decreasing weight, ties in given order; every zero-weight slot on slot 0's joint.
        assertArrayEquals(new int[] {2, 7, 5, 2, 2}, joints(v, 0));
        assertArrayEquals(new float[] {0.5f, 0.3f, 0.2f, 0f, 0f}, weights(v, 0), 0f);
        assertArrayEquals(new int[] {3, 4, 1, 3, 3}, joints(v, 1));
        assertArrayEquals(new float[] {0.4f, 0.4f, 0.2f, 0f, 0f}, weights(v, 1), 0f);
        assertArrayEquals(new int[] {6, 6, 6, 6, 6}, joints(v, 2));
        assertArrayEquals(new int[] {1, 3, 1, 1, 1}, joints(v, 3), "the zero weight on joint 2 moves to joint 1");
        assertArrayEquals(new float[] {0.7f, 0.3f, 0f, 0f, 0f}, weights(v, 3), 0f);
        assertEquals(0, v.cappedPointCount());
    }

    @Test
    void renormalisedWeightsSumToOne() {
        // Five influences 0.3 0.25 0.2 0.15 0.1, capped to 3: 0.3/0.75, 0.25/0.75, 0.2/0.75.
        SkinnedGeometry g = SkinnedGeometry.fromArrays(new float[3], new float[3], 5, new int[] {0, 1, 2, 3, 4},
                new float[] {0.1f, 0.15f, 0.3f, 0.25f, 0.2f}, identities(5));
        InfluenceView v = InfluenceView.of(g, 3);
        assertArrayEquals(new int[] {2, 3, 4}, joints(v, 0));
        assertArrayEquals(new float[] {0.4f, 1f / 3f, 0.8f / 3f}, weights(v, 0), ROUNDING);
        double sum = 0;
        for (float w : weights(v, 0)) {
            sum += w;
        }
        assertEquals(1.0, sum, 3 * ROUNDING);
    }

    @Test
    void importedGeometryKeepsTheFilesHeaviestInfluencesPerPosition() {
        // An independent reading of the fixture's raw influences: for every position, the k
        // heaviest (file order among equals), divided by their sum.
        Model model = Fixtures.resource("skin/capped-chain.dae");
        MeshInstance instance = model.instances().get(0);
        Skin skin = instance.skin();
        SkinnedGeometry g = SkinnedGeometry.of(instance);
        assertEquals(5, g.influencesPerPoint());
        for (int k = 1; k <= 6; k++) {
            InfluenceView v = InfluenceView.of(g, k);
            int capped = 0;
            for (int p = 0; p < skin.mesh().positionCount(); p++) {
                List<Integer> entries = new ArrayList<>();
                for (int e = skin.influenceStart(p); e < skin.influenceStart(p + 1); e++) {
                    entries.add(e);
                }
                entries.sort((a, b) -> Float.compare(skin.influenceWeight(b), skin.influenceWeight(a))); // stable
                double kept = 0;
                double dropped = 0;
                boolean lost = false;
                for (int s = 0; s < entries.size(); s++) {
                    float w = skin.influenceWeight(entries.get(s));
                    if (s < k) {
                        kept += w;
                    } else {
                        dropped += w;
                        lost |= w != 0f;
                    }
                }
                capped += lost ? 1 : 0;
                int point = g.pointOfPosition(p);
                assertEquals(1 - kept / (kept + dropped), v.droppedWeight(point), ROUNDINGS, "k " + k + ", position " + p);
                for (int s = 0; s < k; s++) {
                    String where = "k " + k + ", position " + p + ", slot " + s;
                    if (s < entries.size() && skin.influenceWeight(entries.get(s)) != 0f) {
                        assertEquals(skin.influenceJoint(entries.get(s)), v.joint(point, s), where);
                        assertEquals(skin.influenceWeight(entries.get(s)) / kept, v.weight(point, s), ROUNDINGS, where);
                    } else {
                        assertEquals(skin.influenceJoint(entries.get(0)), v.joint(point, s), where);
                        assertEquals(0f, v.weight(point, s), 0f, where);
                    }
                }
            }
            assertEquals(capped, v.cappedPointCount(), "k " + k);
        }
        // The fixture's header: positions 3 and 7 have five influences, 2, 4, 5 (one of weight 0) and 6 four.
        assertEquals(2, InfluenceView.of(g, 4).cappedPointCount());
        assertEquals(0, InfluenceView.of(g, 5).cappedPointCount());
    }

    @Test
    void jointIndicesAreUnsigned16BitAndPackTightly() {
        int joints = 40000;
        int[] j = {39999, 32768, 7, 0};
        float[] w = {0.5f, 0.25f, 0.25f, 0f};
        SkinnedGeometry g = SkinnedGeometry.fromArrays(new float[6], new float[6], 2, j, w, identities(joints));
        InfluenceView v = InfluenceView.of(g, 3);
        assertEquals(joints, v.jointCount());
        assertEquals(39999, v.joint(0, 0));
        assertEquals(32768, v.joint(0, 1));
        short[] packed = v.jointIndices();
        assertArrayEquals(new short[] {(short) 39999, (short) 32768, (short) 39999, 7, 7, 7}, packed);
        assertTrue(packed[0] < 0, "39999 reads negative as a Java short: it is unsigned");
        assertArrayEquals(new int[] {39999, 32768, 39999, 7, 7, 7}, v.jointIndicesAsInts());
        assertArrayEquals(new float[] {0.5f, 0.25f, 0f, 0.25f, 0f, 0f}, v.weights(), 0f);

        // Into direct buffers, as a renderer uploads them: relative puts, k values per point.
        ShortBuffer jb = ByteBuffer.allocateDirect(2 * 8).order(ByteOrder.nativeOrder()).asShortBuffer();
        jb.put((short) -1);
        v.putJointIndices(jb, 2);
        assertEquals(7, jb.position());
        assertEquals((short) 39999, jb.get(1));
        assertEquals(7, jb.get(6));
        FloatBuffer wb = ByteBuffer.allocateDirect(4 * 3).order(ByteOrder.nativeOrder()).asFloatBuffer();
        v.putWeights(wb, 1);
        assertEquals(3, wb.position());
        assertEquals(0.25f, wb.get(1), 0f);
        assertThrows(IndexOutOfBoundsException.class, () -> v.putWeights(wb, 3));

        // The view is immutable: the arrays handed out are copies.
        packed[0] = 0;
        v.weights()[0] = 9f;
        assertEquals(39999, v.joint(0, 0));
        assertEquals(0.5f, v.weight(0, 0), 0f);
    }

    @Test
    void refusesCapsBelowOneAndPalettesBeyondSixteenBits() {
        assertThrows(IllegalArgumentException.class, () -> InfluenceView.of(handMade(), 0));
        SkinnedGeometry huge = SkinnedGeometry.fromArrays(new float[3], new float[3], 1, new int[] {65536},
                new float[] {1f}, identities(65537));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> InfluenceView.of(huge, 4));
        assertTrue(e.getMessage().contains("65537 joints"), e::getMessage);
        SkinnedGeometry largest = SkinnedGeometry.fromArrays(new float[3], new float[3], 1, new int[] {65535},
                new float[] {1f}, identities(65536));
        assertEquals(65535, InfluenceView.of(largest, 4).joint(0, 0));
        assertThrows(IndexOutOfBoundsException.class, () -> InfluenceView.of(largest, 4).weight(0, 4));
    }
}
