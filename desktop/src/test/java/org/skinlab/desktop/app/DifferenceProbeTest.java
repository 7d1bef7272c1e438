package org.skinlab.desktop.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.viewer.LoadedModel;
import org.skinlab.desktop.viewer.ModelLibrary;
import org.skinlab.desktop.viewer.Viewer;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.Frame;

/**
 * The numbers panel's measures as the viewer makes them (a model loaded by {@link Viewer}, its
 * simulation's frames), on core's {@code gltf/scaled-parts.gltf}: a character exported with a
 * 0.01 armature, parts under uniform, non-uniform and mirroring node scales, an open cloak, a boot
 * closed only across two meshes, a static crate (core's {@code ScaledPartsMeasuresTest} derives
 * the numbers in full; here the ones the panel shows). Before this probe measured the rest in the
 * meshes' own centimetres, the panel said "LBS volume 0.0000 of rest" for this character at rest
 * (8e-6: the body's 0.02 scale cubed) and put the twist's largest distance at 0.36 % of a size of
 * 108.6 centimetres instead of 9.8 % of 3.94 metres.
 */
class DifferenceProbeTest {
    private static final Path SCALED_PARTS = Cli.root().resolve("core/src/test/resources/gltf/scaled-parts.gltf");
    /** The rest bounds over every part, in centimetres: x -165..95, y -30..30, z -15..275; times 0.01. */
    private static final double SIZE = Math.sqrt(260.0 * 260 + 60 * 60 + 290 * 290) * 0.01;
    /** DQS's float rounding with every joint scaled (core's test says why); LBS is exact at rest. */
    private static final double ROUNDING = 1e-5;

    /** The probe on the frame at clip time t, from the model as the viewer loaded it. */
    private static DifferenceProbe measured(LoadedModel shown, double t) {
        shown.mesh().seek(t);
        shown.mesh().step(0.0);
        DifferenceProbe probe = new DifferenceProbe(shown.rest(), shown.comparisons());
        try (Frame frame = shown.mesh().acquire()) {
            assertEquals(t, frame.clipTime(), 1e-6);
            probe.measure(frame);
        }
        return probe;
    }

    @Test
    void theNumbersAreTheWholePlacedModelsInTheDocumentsUnits() throws Exception {
        try (Viewer v = new Viewer(ModelLibrary.find(), new AnimationConfig(), false)) {
            assertNull(v.openAndWait(SCALED_PARTS));
            LoadedModel shown = v.current();
            shown.mesh().stop();

            DifferenceProbe rest = measured(shown, 0);
            assertEquals(SIZE, rest.size(), 1e-6 * SIZE, "the size the shader's colours and the distances share");
            assertEquals(1.0, rest.lbsVolume(), 1e-12);
            assertEquals(1.0, rest.dqsVolume(), ROUNDING);
            assertEquals(0.0, rest.maxRelative(), ROUNDING);
            assertEquals("volume: 5 of 6 skinned parts (2 closed only together); 1 open, 1 static part: not counted",
                    rest.volumeNote());

            // The spine scaled by 1.25: the helmet and the badge it carries keep 1.25^3 of their
            // volume, the body 1.4619 (its rings scaled about the spine by 1, 1, 1.125, 1.25,
            // 1.25), the boot 1. Rest volumes in cm^3: body 500,000, boot 64,000, helmet 60,000,
            // badge 7,500 (mirrored; counted by its magnitude).
            DifferenceProbe grown = measured(shown, 1);
            double cube = 1.25 * 1.25 * 1.25;
            double whole = (500_000 * 1.4619140625 + 64_000 + 67_500 * cube) / 631_500;
            assertEquals(whole, grown.lbsVolume(), ROUNDING);
            assertEquals(whole, grown.dqsVolume(), ROUNDING);

            // Twisted by 170 degrees: the cloak's joint ring (corners 30 sqrt 2 cm from the bone)
            // is where LBS and DQS part most, r (1 - cos 85 degrees) apart.
            DifferenceProbe twisted = measured(shown, 2);
            double r = 30 * Math.sqrt(2) * 0.01;
            assertEquals(r * (1 - Math.cos(Math.toRadians(85))) / SIZE, twisted.maxRelative(), ROUNDING);
            assertTrue(twisted.maxRelative() > 0.09, "about a tenth of the model: " + twisted.maxRelative());
        }
    }

    @Test
    void withoutAClosedSkinnedPartThePanelSaysWhy() throws Exception {
        try (Viewer v = new Viewer(ModelLibrary.find(), new AnimationConfig(), false)) {
            // A skinned strip: one open part.
            assertNull(v.openAndWait(Cli.root().resolve("core/src/test/resources/gltf/skin-textured.glb")));
            v.current().mesh().stop();
            DifferenceProbe strip = measured(v.current(), 0);
            assertTrue(Double.isNaN(strip.lbsVolume()));
            assertEquals("volume: the mesh is not closed", strip.volumeNote());
            // Quads placed by their nodes, none skinned.
            assertNull(v.openAndWait(Cli.root().resolve("core/src/test/resources/gltf/materials.glb")));
            v.current().mesh().stop();
            DifferenceProbe quads = measured(v.current(), 0);
            assertTrue(Double.isNaN(quads.dqsVolume()));
            assertEquals("volume: no skinned part", quads.volumeNote());
        }
    }

    @Test
    void aSingleClosedMeshNeedsNoNote() throws Exception {
        try (Viewer v = new Viewer(ModelLibrary.find(), new AnimationConfig(), false)) {
            assertNull(v.openAndWait(Cli.root().resolve("assets/cylinders/cylinder-twist-high.dae")));
            v.current().mesh().stop();
            // 135 degrees of twist (3 s; the clip's end, 172 degrees, loops back to its start).
            DifferenceProbe twisted = measured(v.current(), 3);
            assertEquals("", twisted.volumeNote());
            assertTrue(twisted.lbsVolume() < 0.95, "the candy wrapper: LBS " + twisted.lbsVolume());
            assertEquals(1.0, twisted.dqsVolume(), 0.01);
        }
    }
}
