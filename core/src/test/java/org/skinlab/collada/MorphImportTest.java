package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.skinlab.collada.Snippets.oneWarning;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.model.Morph;

/**
 * Morph controllers ({@code fixtures/quirks/morphs.dae}): NORMALIZED and RELATIVE weights, a morph
 * on a morph, a skin on a morph (it deforms the morph's result) and a morph on a skin (drawn as
 * the skin, warned). Expected positions are worked out by hand in the fixture's comment from the
 * specification's formulas; they are exact in float.
 */
class MorphImportTest {
    private static final Model MODEL = Fixtures.resource("quirks/morphs.dae");

    private static Morph morph(String id) {
        return MODEL.morphs().stream().filter(m -> m.controllerId().equals(id)).findFirst().orElseThrow();
    }

    @Test
    void normalizedMorphBlendsTheBaseWithOneMinusTheWeights() {
        Morph m = morph("normalized");
        assertEquals(Morph.Method.NORMALIZED, m.method());
        assertArrayEquals(new float[] {0, 0, 0.5f, 1.5f, 0, 0.5f, 0, 1.5f, 0.5f}, m.result().positions(), 0f);
    }

    @Test
    void relativeMorphAddsWeightedTargets() {
        assertArrayEquals(new float[] {0, 0, 0.5f, 1, 0, 0.5f, 0, 1, 0.5f}, morph("relative").result().positions(), 0f);
    }

    @Test
    void aMorphOnAMorphMorphsTheInnerResult() {
        Morph chained = morph("chained");
        assertSame(morph("relative").result(), chained.base());
        assertArrayEquals(new float[] {0, 0, 1.5f, 1, 0, 1.5f, 0, 1, 1.5f}, chained.result().positions(), 0f);
    }

    @Test
    void targetsWithMorePositionsGiveTheirFirstOnesAndTargetsWithFewerAreLeftOut() {
        Morph odd = morph("odd");
        assertEquals(1, odd.targets().size());
        assertArrayEquals(new float[] {1f}, odd.weights(), 0f);
        assertArrayEquals(new float[] {2, 0, 0, 3, 0, 0, 2, 1, 0}, odd.result().positions(), 0f);
        oneWarning(MODEL, "morph target \"big\" has 4 positions, the base 3; its first 3 are used");
        oneWarning(MODEL, "morph target \"small\" has 2 positions, the base 3; left out");
    }

    @Test
    void morphResultsAreListedAfterTheGeometriesAndDrawnByTheirInstances() {
        assertEquals(List.of("base", "up", "wide", "big", "small", "lift", "normalized", "relative", "chained", "odd"),
                MODEL.meshes().stream().map(m -> m.id()).collect(java.util.stream.Collectors.toList()));
        assertEquals(3, morph("odd").result().positionCount());
        MeshInstance first = MODEL.instances().get(0);
        assertSame(morph("normalized").result(), first.mesh());
        assertNull(first.skin());
        // The result keeps the base's topology.
        assertArrayEquals(MODEL.mesh("base").orElseThrow().triangles(), first.mesh().triangles());
    }

    @Test
    void aSkinOnAMorphDeformsTheMorphsResult() {
        MeshInstance skinned = MODEL.instances().get(4);
        assertSame(morph("normalized").result(), skinned.skin().mesh());
        assertSame(skinned.skin().mesh(), skinned.mesh());
    }

    @Test
    void aMorphOnASkinIsDrawnAsTheSkinWithAWarning() {
        MeshInstance last = MODEL.instances().get(5);
        assertEquals("skin-on-base", last.skin().controllerId());
        assertSame(MODEL.mesh("base").orElseThrow(), last.mesh());
        oneWarning(MODEL, "morph on skin controller \"skin-on-base\": drawn as that skin, without the morph");
        assertEquals(3, MODEL.warnings().size(), () -> MODEL.warnings().toString());
    }

    @Test
    void applyTakesOtherWeightsWithoutAllocating() {
        Morph m = morph("normalized");
        float[] dest = new float[9];
        m.apply(new float[] {0f, 0f}, dest);
        assertArrayEquals(MODEL.mesh("base").orElseThrow().positions(), dest, 0f);
        m.apply(new float[] {1f, 0f}, dest);
        assertArrayEquals(MODEL.mesh("up").orElseThrow().positions(), dest, 0f);
    }

    @Test
    void aChainOfTooManyMorphsIsRefusedNotAStackOverflow() {
        // Listed last first, so reading the first controller recurses through the whole chain.
        StringBuilder chain = new StringBuilder();
        for (int i = 10_000; i >= 1; i--) {
            chain.append("<controller id=\"m").append(i).append("\"><morph source=\"#")
                    .append(i == 1 ? "g" : "m" + (i - 1)).append("\"><targets/></morph></controller>\n");
        }
        ColladaException e = Fixtures.error("chain.dae", Snippets.collada(
                "<library_geometries>" + Snippets.geometry("g", 3) + "</library_geometries>",
                "<library_controllers>" + chain + "</library_controllers>"));
        assertEquals("more than 64 morphs on morphs", e.problem());
    }

    @Test
    void aMorphCycleIsRefused() {
        String text = Fixtures.text("quirks/morphs.dae").replace("<morph source=\"#relative\" method=\"RELATIVE\">",
                "<morph source=\"#chained\" method=\"RELATIVE\">");
        ColladaException e = Fixtures.error("cycle.dae", text);
        assertEquals("<morph> in <controller id=\"chained\"> at line 134", e.element());
        assertEquals("source=\"#chained\" leads back to this morph (a cycle)", e.problem());
    }
}
