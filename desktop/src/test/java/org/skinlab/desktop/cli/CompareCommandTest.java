package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.skinlab.desktop.Cli;

/**
 * {@code skinlab compare} on a character of many parts with node scales (core's
 * {@code gltf/scaled-parts.gltf}; its {@code ScaledPartsMeasuresTest} derives every number): the
 * spine of a body column and of an open cloak, both half on the spine at their joint ring, under
 * an armature scaled by 0.01 and a node of scale 2, so the body's ring corners stand 25 sqrt 2 cm
 * from the bone at rest (the cloak's 30 sqrt 2), and the placed model's size is 3.9408 m. Before
 * the measures took the rest in the meshes' own centimetres, this printed at rest a volume of
 * 0.0000 (8e-6), a ring of 0.0200 and a bulge of -17.32 for the body, and no word on the cloak's
 * missing volume.
 */
class CompareCommandTest {
    private static final double SIZE = Math.sqrt(260.0 * 260 + 60 * 60 + 290 * 290) * 0.01;
    private static final double BODY_RING = 25 * Math.sqrt(2) * 0.01;
    private static final double CLOAK_RING = 30 * Math.sqrt(2) * 0.01;
    /** Numbers printed to 4 decimals. */
    private static final double PRINTED = 1.5e-4;

    /** The cells of a method's row in the table at time t under the part whose header starts so. */
    private static String[] row(String out, String part, String time, String method) {
        List<String> lines = out.lines().toList();
        int at = -1;
        for (int i = 0; i < lines.size(); i++) {
            if (lines.get(i).startsWith(part)) {
                at = i;
            } else if (at >= 0 && lines.get(i).startsWith("| t = " + time + " s |")) {
                for (int k = i + 2; k < lines.size() && lines.get(k).startsWith("| "); k++) {
                    if (lines.get(k).startsWith("| " + method + " |")) {
                        String[] cells = lines.get(k).split("\\|");
                        for (int c = 0; c < cells.length; c++) {
                            cells[c] = cells[c].trim();
                        }
                        return cells;
                    }
                }
            }
        }
        fail("no " + method + " row at t = " + time + " under " + part + "\n" + out);
        return null;
    }

    /** Cells: "", method, volume, ring, bulge, distance to LBS, distance to DQS. */
    private static void assertRow(double volume, double ring, double bulge, double distance, String[] cells) {
        String what = String.join(" | ", cells);
        if (Double.isNaN(volume)) {
            assertEquals("-", cells[2], what);
        } else {
            assertEquals(volume, Double.parseDouble(cells[2]), PRINTED, what);
        }
        assertEquals(ring, Double.parseDouble(cells[3]), PRINTED, what);
        assertEquals(bulge, Double.parseDouble(cells[4]), PRINTED, what);
        String other = cells[1].equals("LBS") ? cells[6] : cells[5];
        assertEquals(distance, Double.parseDouble(other), PRINTED, what);
    }

    @Test
    void aCharacterOfScaledPartsIsMeasuredAgainstItsRestPose() {
        Cli r = Cli.run("compare", Cli.root().resolve("core/src/test/resources/gltf/scaled-parts.gltf").toString(),
                "--joint", "spine", "--time", "0,1,2", "--method", "lbs,dqs");
        assertEquals(0, r.status, r::toString);
        String body = "scaled-parts.gltf, mesh body: joint spine with parent hips, 4 points in the joint region";
        String cloak = "scaled-parts.gltf, mesh cloak: joint spine with parent hips, 4 points in the joint region";
        assertTrue(r.out.contains(body + "\nvolume: the part's, against its own rest; distances over the model's size,"
                + " 3.941 (its rest pose's bounds)\n"), r::toString);
        assertTrue(r.out.contains(cloak + "\nvolume: - (the part is not closed); distances over the model's size,"
                + " 3.941"), r::toString);
        assertTrue(r.out.endsWith("\nno point of mesh boot-upper, mesh boot-lower, mesh helmet, mesh helmet"
                + " (node badge) is weighted on both spine and hips: no joint region\n"), r::toString);
        double cos85 = Math.cos(Math.toRadians(85));
        for (String m : new String[] {"LBS", "DQS"}) {
            // At rest: neutral.
            assertRow(1, 1, 0, 0, row(r.out, body, "0.000", m));
            assertRow(Double.NaN, 1, 0, 0, row(r.out, cloak, "0.000", m));
            // The spine scaled by 1.25: the ring moves out to 1.125 of its radius, and the body
            // keeps 1.4619 of its volume (ScaledPartsMeasuresTest's frustums).
            assertRow(1.4619140625, 1.125, 0.125 * BODY_RING, 0, row(r.out, body, "1.000", m));
            assertRow(Double.NaN, 1.125, 0.125 * CLOAK_RING, 0, row(r.out, cloak, "1.000", m));
        }
        // Twisted by 170 degrees: LBS's ring falls to cos 85 of its radius, DQS's stays; the two
        // stand r (1 - cos 85) apart, over the model's size.
        String[] lbs = row(r.out, body, "2.000", "LBS");
        assertEquals(cos85, Double.parseDouble(lbs[3]), PRINTED);
        assertEquals(BODY_RING * (1 - cos85) / SIZE, Double.parseDouble(lbs[6]), PRINTED);
        assertEquals(1.0, Double.parseDouble(row(r.out, body, "2.000", "DQS")[3]), PRINTED);
        assertEquals(CLOAK_RING * (1 - cos85) / SIZE, Double.parseDouble(row(r.out, cloak, "2.000", "DQS")[5]),
                PRINTED);
    }
}
