package org.skinlab.desktop.eval;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.skinlab.desktop.Cli;
import org.skinlab.importer.ModelImporter;
import org.skinlab.model.Model;

/**
 * The load section's twin check ({@link AssetTwins}) tells a faithful .glb from a broken one. The
 * agreeing side on every asset is in {@link EvalLoadTest}; here the failing side: the bend cylinder's
 * .glb holds the same mesh, joints and clip length as the twist-high cylinder's .dae
 * (assets/README.md: "same mesh as twist-high"), only the animation differs, as after an export
 * that wrote the wrong action; and the pairing by position on hand-made points.
 */
class AssetTwinsTest {
    @Test
    void aTwinWithAnotherAnimationIsCaughtByItsPointsAlone() throws Exception {
        Path cylinders = Cli.root().resolve("assets/cylinders");
        Model twist = ModelImporter.read(cylinders.resolve("cylinder-twist-high.dae"));
        AssetTwins.Comparison same = AssetTwins.compare(twist,
                ModelImporter.read(cylinders.resolve("cylinder-twist-high.glb")));
        assertTrue(same.agrees(), same.toString());
        assertTrue(same.maxDistancePpm() <= AssetTwins.TOLERANCE_PPM, same.toString());

        AssetTwins.Comparison wrong = AssetTwins.compare(twist,
                ModelImporter.read(cylinders.resolve("cylinder-bend.glb")));
        assertArrayEquals(same.triangles(), wrong.triangles());
        assertArrayEquals(same.joints(), wrong.joints());
        assertArrayEquals(same.clipSeconds(), wrong.clipSeconds(), 0);
        assertEquals(0, wrong.unpaired(), "the same bind positions");
        // The upper half bends by 54 degrees at 0.3 of the clip instead of twisting: its tip moves by
        // a sizeable part of the model, five orders of magnitude beyond the tolerance.
        assertTrue(wrong.maxDistancePpm() > 1e5, wrong.toString());
        assertFalse(wrong.agrees());
    }

    @Test
    void pairsEachPointWithTheOneAtItsPositionAndCountsThoseWithNone() {
        float[] dae = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 1, 2, 0, 0};
        // The .dae's points in another order, one moved by 0.01 and one duplicated (a split normal).
        float[] glb = {1, 1, 0, 0, 0, 0, 2, 0, 0.01f, 1, 0, 0, 1, 1, 0};
        int[] pair = new int[5];
        int unpaired = AssetTwins.pairByPosition(glb, dae, 1e-6, pair);
        assertEquals(1, unpaired, "the moved point");
        assertArrayEquals(new int[] {2, 0, 4, 1, 2}, pair, "each with the nearest, the moved one too");
    }
}
