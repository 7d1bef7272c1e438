package org.skinlab.desktop.eval;

import java.util.ArrayList;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.MissingNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.skinning.SkinningMethod;

/**
 * The claims table's rows: for each of the thesis' claims, where this run's number for it lives
 * in the other sections' results, copied into the claim's node with its verdict
 * ({@code measure}-side methods), and the row's text from that node alone ({@link #cells}). A
 * claim whose section was not run, or that needs what this machine lacks (a phone, a display),
 * says so and is "cannot be measured here".
 */
final class EvalClaims {
    /** The thesis' requirement: every file loads in under this many seconds (4.2). */
    static final double LOAD_SECONDS = 10;
    /** The thesis' requirement: an animation plays at this many frames per second or more (4.2). */
    static final double PLAYBACK_FPS = 30;
    /** The thesis' Galaxy S7: frames per second skinning on the CPU (from, to) and without deformation. */
    static final double[] PHONE_FPS = {3, 4, 30};
    /** The quality claims' angle (our cylinders reach it; the thesis' bent to about 180). */
    static final double ANGLE = EvalAdviceInputs.QUOTED_DEGREES;

    private EvalClaims() {
    }

    // ---- measuring: copy the numbers and decide

    static void load(JsonNode load, ObjectNode c) {
        c.put("id", "load").put("thesisSeconds", LOAD_SECONDS);
        if (load == null || !load.has("slowestImportMs")) {
            missing(c, load == null ? "the load section was not run" : "no file was imported");
            return;
        }
        int under = 0;
        String file = null;
        double slowest = -1;
        for (JsonNode g : load.get("groups")) {
            under += g.path("underRequirement").asInt();
            if (g.path("slowestImportMs").asDouble(-1) > slowest) {
                slowest = g.get("slowestImportMs").asDouble();
                file = g.get("slowestFile").asText();
            }
        }
        c.put("files", load.get("importedFiles").asInt()).put("under", under)
                .put("slowestMillis", load.get("slowestImportMs").asDouble()).put("slowestFile", file);
        c.put("verdict", load.get("allMeetRequirement").asBoolean() ? EvalClaimsSection.HOLDS : EvalClaimsSection.FAILS);
    }

    static void playback(JsonNode crowds, ObjectNode c) {
        c.put("id", "playback").put("thesisFps", PLAYBACK_FPS);
        JsonNode one = drawnAt(crowds, 1, "cpu", SkinningMethod.DQS);
        if (one == null) {
            missing(c, crowds == null ? "the crowds section was not run" : "nothing was drawn (no display)");
            return;
        }
        c.put("renderer", crowds.at("/render/renderer").asText()).put("software", crowds.at("/render/software")
                .asBoolean());
        c.put("file", crowds.at("/render/file").asText());
        c.put("fps", one.at("/fps/median").asDouble());
        c.put("verdict", one.at("/fps/min").asDouble() >= PLAYBACK_FPS ? EvalClaimsSection.HOLDS
                : EvalClaimsSection.FAILS);
    }

    /** "DQS is faster than LBS" on our assets with one kind of kernels, with normals: the per-round ratios' medians. */
    static void dqsFasterOnAssets(JsonNode time, String kernels, ObjectNode c) {
        c.put("id", "dqs-faster-" + kernels).put("kernels", kernels).put("thesisCowboyDqsMillis", 4.35)
                .put("thesisCowboyLbsMillis", 4.55);
        if (time == null) {
            missing(c, "the time section was not run");
            return;
        }
        double lo = Double.POSITIVE_INFINITY;
        double hi = 0;
        int assets = 0;
        int faster = 0;
        int slower = 0;
        String loFile = null;
        String hiFile = null;
        for (JsonNode a : time.get("assets")) {
            for (JsonNode r : a.get("dqsOverLbs")) {
                if (!r.get("kernels").asText().equals(kernels) || !r.get("influences").asText().equals("all")) {
                    continue;
                }
                double ratio = r.at("/ratio/median").asDouble();
                assets++;
                faster += r.at("/ratio/max").asDouble() < 1 ? 1 : 0;
                slower += r.at("/ratio/min").asDouble() > 1 ? 1 : 0;
                if (ratio < lo) {
                    lo = ratio;
                    loFile = a.get("file").asText();
                }
                if (ratio > hi) {
                    hi = ratio;
                    hiFile = a.get("file").asText();
                }
            }
        }
        c.put("assets", assets).put("fasterOn", faster).put("slowerOn", slower).put("lowestRatio", lo).put("lowestFile", loFile)
                .put("highestRatio", hi).put("highestFile", hiFile);
        c.put("verdict", faster == assets ? EvalClaimsSection.HOLDS : faster == 0 ? EvalClaimsSection.FAILS
                : EvalClaimsSection.MIXED);
    }

    /**
     * "DQS is faster than LBS" in the shared scalar C++ reference (its own data, normals as it
     * computes them): the per-round ratio's range at the smallest size.
     */
    static void dqsFasterInCpp(JsonNode time, ObjectNode c) {
        c.put("id", "dqs-faster-cpp");
        JsonNode row = cppRows(time, c).stream().filter(r -> r.get("kernel").asText().equals("C++ reference"))
                .findFirst().orElse(null);
        if (row == null) {
            return;
        }
        c.put("vertices", row.get("vertices").asInt());
        c.put("lbsNs", row.at("/lbsNs/median").asDouble()).put("dqsNs", row.at("/dqsNs/median").asDouble());
        c.put("ratio", row.at("/dqsOverLbs/median").asDouble()).put("ratioMin", row.at("/dqsOverLbs/min").asDouble())
                .put("ratioMax", row.at("/dqsOverLbs/max").asDouble());
        c.put("verdict", EvalClaimsSection.smaller(row.at("/dqsOverLbs/min").asDouble(), row.at("/dqsOverLbs/max")
                .asDouble(), 1, 1));
        fixWithinSpread(c);
    }

    /**
     * "DQS is faster than LBS" with positions only, where neither pays for normals: our C++ and
     * our scalar and fastest Java kernels on the reference's data, the per-round ratios.
     */
    static void dqsFasterWithoutNormals(JsonNode time, ObjectNode c) {
        c.put("id", "dqs-faster-positions");
        List<JsonNode> rows = cppRows(time, c);
        if (rows.isEmpty()) {
            return;
        }
        int vertices = rows.get(0).get("vertices").asInt();
        ArrayNode kernels = c.putArray("kernels");
        int faster = 0;
        int slower = 0;
        for (JsonNode r : rows) {
            if (r.get("vertices").asInt() == vertices && r.get("normals").asText().equals("none")) {
                kernels.addObject().put("kernel", r.get("kernel").asText()).put("ratio", r.at("/dqsOverLbs/median")
                        .asDouble()).put("ratioMin", r.at("/dqsOverLbs/min").asDouble()).put("ratioMax",
                        r.at("/dqsOverLbs/max").asDouble());
                faster += r.at("/dqsOverLbs/max").asDouble() < 1 ? 1 : 0;
                slower += r.at("/dqsOverLbs/min").asDouble() > 1 ? 1 : 0;
            }
        }
        c.put("vertices", vertices).put("kernelCount", kernels.size()).put("fasterIn", faster).put("slowerIn", slower);
        c.put("verdict", faster == kernels.size() ? EvalClaimsSection.HOLDS : faster == 0 ? EvalClaimsSection.FAILS
                : EvalClaimsSection.MIXED);
    }

    /** The time section's C++ comparison rows, or none with the claim marked as not measured. */
    private static List<JsonNode> cppRows(JsonNode time, ObjectNode c) {
        List<JsonNode> rows = new ArrayList<>();
        time = time == null ? MissingNode.getInstance() : time;
        time.path("reference").path("rows").forEach(rows::add);
        if (rows.isEmpty()) {
            missing(c, time.isMissingNode() ? "the time section was not run" : "the C++ reference did not run: "
                    + time.path("reference").path("skipped").asText("no rows"));
        }
        return rows;
    }

    /** The thesis' desktop: copies drawn with CPU skinning, DQS and LBS frames per second. */
    static void meshes(JsonNode crowds, int copies, ObjectNode c) {
        c.put("id", "meshes-" + copies).put("copies", copies);
        for (double[] t : EvalCrowdsThesis.THESIS) {
            if (t[0] == copies) {
                c.put("thesisDqsFps", t[1]).put("thesisLbsFps", t[2]);
            }
        }
        JsonNode dqs = drawnAt(crowds, copies, "cpu", SkinningMethod.DQS);
        JsonNode lbs = drawnAt(crowds, copies, "cpu", SkinningMethod.LBS);
        if (dqs == null || lbs == null) {
            missing(c, crowds == null ? "the crowds section was not run" : "nothing was drawn (no display)");
            return;
        }
        c.put("renderer", crowds.at("/render/renderer").asText()).put("software",
                crowds.at("/render/software").asBoolean());
        c.put("dqsFps", dqs.at("/fps/median").asDouble()).put("lbsFps", lbs.at("/fps/median").asDouble());
        c.put("dqsMinFps", dqs.at("/fps/min").asDouble()).put("dqsMaxFps", dqs.at("/fps/max").asDouble());
        c.put("lbsMinFps", lbs.at("/fps/min").asDouble()).put("lbsMaxFps", lbs.at("/fps/max").asDouble());
        // Which drew faster beyond the runs' spread: "dqs", "lbs" or "neither".
        String faster = dqs.at("/fps/min").asDouble() > lbs.at("/fps/max").asDouble() ? "dqs"
                : lbs.at("/fps/min").asDouble() > dqs.at("/fps/max").asDouble() ? "lbs" : "neither";
        c.put("faster", faster);
        // The thesis: DQS as fast as LBS with one mesh (60 and 60 fps), faster with more (7 and 5 at 12).
        boolean equalClaim = c.get("thesisDqsFps").asDouble() == c.get("thesisLbsFps").asDouble();
        c.put("verdict", equalClaim ? (faster.equals("lbs") ? EvalClaimsSection.FAILS : EvalClaimsSection.HOLDS)
                : faster.equals("dqs") ? EvalClaimsSection.HOLDS : EvalClaimsSection.FAILS);
    }

    static void lbsLosesVolume(JsonNode quality, ObjectNode c) {
        c.put("id", "lbs-volume").put("angleDegrees", ANGLE);
        JsonNode twist = at(quality, "cylinder-twist-high.dae");
        JsonNode bend = at(quality, "cylinder-bend.dae");
        if (twist == null || bend == null) {
            missing(c, "the quality section was not run");
            return;
        }
        c.put("twistVolume", twist.at("/methods/lbs/volume/0").asDouble());
        c.put("twistRing", twist.at("/methods/lbs/ringRadius/0").asDouble());
        c.put("bendVolume", bend.at("/methods/lbs/volume/0").asDouble());
        c.put("verdict", c.get("twistVolume").asDouble() < 1 && c.get("bendVolume").asDouble() < 1
                ? EvalClaimsSection.HOLDS : EvalClaimsSection.FAILS);
    }

    static void dqsKeepsVolume(JsonNode quality, ObjectNode c) {
        c.put("id", "dqs-volume").put("angleDegrees", ANGLE);
        JsonNode high = at(quality, "cylinder-twist-high.dae");
        JsonNode low = at(quality, "cylinder-twist-low.dae");
        if (high == null || low == null) {
            missing(c, "the quality section was not run");
            return;
        }
        c.put("highVolume", high.at("/methods/dqs/volume/0").asDouble());
        c.put("lowVolume", low.at("/methods/dqs/volume/0").asDouble());
        c.put("lbsHighVolume", high.at("/methods/lbs/volume/0").asDouble());
        c.put("verdict", c.get("highVolume").asDouble() >= c.get("lowVolume").asDouble()
                && c.get("highVolume").asDouble() > c.get("lbsHighVolume").asDouble() ? EvalClaimsSection.HOLDS
                : EvalClaimsSection.FAILS);
    }

    static void dqsBulges(JsonNode quality, ObjectNode c) {
        c.put("id", "dqs-bulge").put("angleDegrees", ANGLE);
        JsonNode bend = at(quality, "cylinder-bend.dae");
        if (bend == null) {
            missing(c, "the quality section was not run");
            return;
        }
        c.put("dqsBulge", bend.at("/methods/dqs/bulge/0").asDouble());
        c.put("lbsBulge", bend.at("/methods/lbs/bulge/0").asDouble());
        c.put("verdict", c.get("dqsBulge").asDouble() > c.get("lbsBulge").asDouble() ? EvalClaimsSection.HOLDS
                : EvalClaimsSection.FAILS);
    }

    /** The thesis' Galaxy S7 against the phones added to the report (section "phone"), or none yet. */
    static void phone(JsonNode phone, ObjectNode c) {
        c.put("id", "phone").put("thesisCpuFpsLow", PHONE_FPS[0]).put("thesisCpuFpsHigh", PHONE_FPS[1])
                .put("thesisUndeformedFps", PHONE_FPS[2]);
        JsonNode devices = phone == null ? null : phone.path("devices");
        if (devices == null || devices.size() == 0) {
            missing(c, "no phone has run the app's measure action for this report yet (docs/ar.md)");
            return;
        }
        c.put("devices", devices.size());
        c.put("verdict", EvalClaimsSection.UNMEASURED);
    }

    /**
     * Why DQS against LBS flips with the influences: the fastest kernels' lines through ns per vertex
     * against influences (the advice section's), when both hold: LBS's cost per influence is above
     * DQS's, its fixed cost below, so they cross at (fixed DQS - fixed LBS) / (per influence LBS -
     * per influence DQS) influences.
     */
    static void whyItFlips(JsonNode advice, ObjectNode f) {
        // Counted in the scalar kernels (SkinningSteps): floating-point operations per influence and per vertex.
        f.put("lbsBlendFloats", 12).put("dqsBlendFloats", 8).put("lbsOpsPerInfluence", 24).put("dqsOpsPerInfluence", 24)
                .put("lbsOpsPerVertex", 18).put("dqsOpsPerVertex", 72);
        JsonNode lbs = null;
        JsonNode dqs = null;
        for (JsonNode s : advice == null ? MissingNode.getInstance()
                : advice.path("influences").path("series")) {
            lbs = s.get("method").asText().equals("lbs") ? s : lbs;
            dqs = s.get("method").asText().equals("dqs") ? s : dqs;
        }
        if (lbs == null || dqs == null) {
            f.put("missing", "the advice section (the influences sweep) was not run");
            return;
        }
        f.put("holds", lbs.at("/fit/holds").asBoolean() && dqs.at("/fit/holds").asBoolean()
                && lbs.at("/fit/model").asText().equals("line") && dqs.at("/fit/model").asText().equals("line"));
        f.put("kernel", lbs.get("kernel").asText());
        f.put("lbsFixed", lbs.at("/fit/intercept").asDouble()).put("lbsPerInfluence", lbs.at("/fit/slope").asDouble());
        f.put("dqsFixed", dqs.at("/fit/intercept").asDouble()).put("dqsPerInfluence", dqs.at("/fit/slope").asDouble());
        double denominator = lbs.at("/fit/slope").asDouble() - dqs.at("/fit/slope").asDouble();
        if (denominator > 0) {
            f.put("crossing", EvalReport.round((dqs.at("/fit/intercept").asDouble() - lbs.at("/fit/intercept")
                    .asDouble()) / denominator));
        }
    }

    /** A verdict of {@link EvalClaimsSection#smaller} that found no difference beyond the spread is a failed claim. */
    private static void fixWithinSpread(ObjectNode c) {
        if (c.get("verdict").asText().equals("within the spread")) {
            c.put("verdict", EvalClaimsSection.FAILS);
            c.put("withinSpread", true);
        }
    }

    /** The drawn point of {@code copies} copies with {@code skinning} ("cpu" or "gpu") and a method, or null. */
    static JsonNode drawnAt(JsonNode crowds, int copies, String skinning, SkinningMethod method) {
        if (crowds == null) {
            return null;
        }
        for (JsonNode p : crowds.path("render").path("points")) {
            if (p.path("instances").asInt(-1) == copies && p.path("skinning").asText().equals(skinning)
                    && p.path("method").asText().equals(method.key())) {
                return p;
            }
        }
        return null;
    }

    /** The quality section's values at the claims' angle on {@code file}, or null. */
    private static JsonNode at(JsonNode quality, String file) {
        if (quality == null) {
            return null;
        }
        for (JsonNode a : quality.get("assets")) {
            if (a.get("file").asText().equals(file)) {
                return EvalAdviceInputs.atAngle(a, ANGLE);
            }
        }
        return null;
    }

    private static void missing(ObjectNode c, String why) {
        c.put("missing", why);
        c.put("verdict", EvalClaimsSection.UNMEASURED);
    }

    // ---- writing: one row per claim, every number from the claim's node

    /** The claim's text (with the thesis' numbers) and this run's sentence, for row {@code i}. */
    static String[] cells(JsonNode results, int i) {
        String p = "/claims/" + i;
        JsonNode c = results.at(p);
        String id = c.get("id").asText();
        String thesis = switch (id) {
            case "load" -> "Every file loads in under " + num(results, p, "thesisSeconds") + " s (requirement).";
            case "playback" -> "An animated model plays at " + num(results, p, "thesisFps") + " fps or more"
                    + " (requirement).";
            case "dqs-faster-scalar", "dqs-faster-fastest" -> "DQS is faster than LBS (the cowboy: DQS "
                    + num(results, p, "thesisCowboyDqsMillis") + " ms, LBS " + num(results, p, "thesisCowboyLbsMillis")
                    + " ms per deformation); here: " + c.get("kernels").asText() + " Java kernels, with normals.";
            case "dqs-faster-cpp" -> "DQS is faster than LBS; here: the shared scalar C++ reference, with normals.";
            case "dqs-faster-positions" -> "DQS is faster than LBS; here: positions only, our C++ and our scalar and"
                    + " fastest Java kernels.";
            case "meshes-1", "meshes-12" -> num(results, p, "copies") + (c.get("copies").asInt() == 1 ? " mesh"
                    : " meshes") + " drawn at " + num(results, p, "thesisDqsFps") + " fps with DQS and "
                    + num(results, p, "thesisLbsFps") + " with LBS (CPU skinning): DQS draws "
                    + (c.get("thesisDqsFps").asDouble() == c.get("thesisLbsFps").asDouble() ? "as fast as LBS."
                            : "faster than LBS.");
            case "lbs-volume" -> "LBS loses volume at a twisted or bent joint (the candy wrapper).";
            case "dqs-volume" -> "DQS keeps the volume when the joint has enough vertices.";
            case "dqs-bulge" -> "DQS bulges at an extreme bend.";
            case "phone" -> "A Galaxy S7 skins on the CPU at " + num(results, p, "thesisCpuFpsLow") + " to "
                    + num(results, p, "thesisCpuFpsHigh") + " fps, and draws " + num(results, p, "thesisUndeformedFps")
                    + " fps without deformation.";
            default -> id;
        };
        return new String[] {thesis, c.has("missing") ? "Not measured: " + c.get("missing").asText() + "." : ours(
                results, p, id)};
    }

    private static String ours(JsonNode r, String p, String id) {
        JsonNode c = r.at(p);
        return switch (id) {
            case "load" -> num(r, p, "under") + " of " + num(r, p, "files") + " files load in under that; the slowest"
                    + " single import of any run, `" + c.get("slowestFile").asText() + "`, took "
                    + num(r, p, "slowestMillis") + " ms.";
            case "playback" -> "One copy of `" + c.get("file").asText() + "` drawn with CPU skinning (DQS) at "
                    + num(r, p, "fps") + " fps (the median run) on `" + c.get("renderer").asText() + "`" + software(c)
                    + ".";
            case "dqs-faster-scalar", "dqs-faster-fastest" -> "DQS takes " + num(r, p, "lowestRatio") + " (`"
                    + c.get("lowestFile").asText() + "`) to " + num(r, p, "highestRatio") + " (`"
                    + c.get("highestFile").asText() + "`) times LBS's time per frame (medians of per-round ratios);"
                    + " DQS was the faster in every round on " + num(r, p, "fasterOn") + " of " + num(r, p, "assets")
                    + " assets, the slower in every round on " + num(r, p, "slowerOn") + ".";
            case "dqs-faster-cpp" -> "At " + num(r, p, "vertices") + " vertices DQS takes " + num(r, p, "dqsNs")
                    + " ns per vertex, LBS " + num(r, p, "lbsNs") + ": " + num(r, p, "ratio") + " times (rounds "
                    + num(r, p, "ratioMin") + " to " + num(r, p, "ratioMax") + ")"
                    + (c.path("withinSpread").asBoolean() ? ", within the runs' spread." : ".");
            case "dqs-faster-positions" -> positions(r, p);
            case "meshes-1", "meshes-12" -> num(r, p, "copies") + (c.get("copies").asInt() == 1 ? " copy" : " copies")
                    + " drawn with CPU skinning at " + num(r, p, "dqsFps") + " fps with DQS (runs " + num(r, p, "dqsMinFps")
                    + " to " + num(r, p, "dqsMaxFps") + ") and " + num(r, p, "lbsFps") + " with LBS (" + num(r, p,
                    "lbsMinFps") + " to " + num(r, p, "lbsMaxFps") + ") on `" + c.get("renderer").asText() + "`"
                    + software(c) + ": " + (c.get("faster").asText().equals("neither") ? "neither is faster beyond"
                    + " the runs' spread." : c.get("faster").asText().toUpperCase(java.util.Locale.ROOT)
                    + " is faster beyond the runs' spread.");
            case "lbs-volume" -> "At " + num(r, p, "angleDegrees") + " degrees LBS keeps " + num(r, p, "twistVolume")
                    + " of the twist cylinder's volume (its joint ring " + num(r, p, "twistRing") + " of its radius) and "
                    + num(r, p, "bendVolume") + " of the bend cylinder's.";
            case "dqs-volume" -> "At " + num(r, p, "angleDegrees") + " degrees of twist DQS keeps "
                    + num(r, p, "highVolume") + " of the volume with the rings close at the joint (twist-high), "
                    + num(r, p, "lowVolume") + " with few rings there (twist-low); LBS " + num(r, p, "lbsHighVolume")
                    + ".";
            case "dqs-bulge" -> "At " + num(r, p, "angleDegrees") + " degrees of bend the joint stands out "
                    + num(r, p, "dqsBulge") + " % of the model's size beyond its rest distance with DQS, "
                    + num(r, p, "lbsBulge") + " % with LBS.";
            case "phone" -> num(r, p, "devices") + " phone(s) added: section \"phone\".";
            default -> "";
        };
    }

    private static String positions(JsonNode r, String p) {
        StringBuilder t = new StringBuilder("At " + num(r, p, "vertices") + " vertices DQS takes");
        JsonNode kernels = r.at(p + "/kernels");
        for (int k = 0; k < kernels.size(); k++) {
            String q = p + "/kernels/" + k;
            t.append(k == 0 ? " " : k == kernels.size() - 1 ? " and " : ", ").append(num(r, q, "ratio"))
                    .append(" (rounds ").append(num(r, q, "ratioMin")).append(" to ").append(num(r, q, "ratioMax"))
                    .append(") ").append(k == 0 ? "times LBS's time in " : "in ").append(kernels.get(k).get("kernel")
                    .asText());
        }
        return t.append(": faster in every round in ").append(num(r, p, "fasterIn")).append(" of ")
                .append(num(r, p, "kernelCount")).append(", slower in every round in ").append(num(r, p, "slowerIn"))
                .append(".").toString();
    }

    private static String software(JsonNode c) {
        return c.path("software").asBoolean() ? ", a software rasteriser on the CPU, not a GPU" : "";
    }

    /** The paragraph under the table: why DQS against LBS depends on the kernels and the influences. */
    static void flipParagraph(JsonNode results, EvalReport report) {
        JsonNode f = results.get("flip");
        if (f.has("missing")) {
            report.paragraph("Why DQS against LBS flips: not shown, " + f.get("missing").asText() + ".");
            return;
        }
        StringBuilder t = new StringBuilder("**Why it flips.** Per influence, LBS adds a weighted 3x4 matrix ("
                + num(results, "", "flip/lbsBlendFloats") + " multiply-adds, " + num(results, "", "flip/lbsOpsPerInfluence")
                + " operations), DQS a weighted dual quaternion (" + num(results, "", "flip/dqsBlendFloats")
                + " multiply-adds and the hemisphere test against the first influence, "
                + num(results, "", "flip/dqsOpsPerInfluence") + " operations): about the same. Per vertex, LBS"
                + " multiplies the point by the blended matrix (" + num(results, "", "flip/lbsOpsPerVertex")
                + " operations); DQS normalises the blend (a square root and a division) and turns the point by the"
                + " quaternion and adds the translation (" + num(results, "", "flip/dqsOpsPerVertex")
                + " operations in all). So with positions only, DQS costs more per vertex and the same per influence,"
                + " in C++ and in Java alike. Normals change the balance: the exact normal costs LBS the blended"
                + " matrix's cofactors and a renormalisation, DQS one more turn by the quaternion it already has; the"
                + " reference's blended-matrix normal costs LBS little and DQS the same turn. The vector kernels load"
                + " one lane group per dual quaternion and two per matrix, which tips the per-influence cost DQS's way."
                + " Measured with the fastest kernels here (`" + f.get("kernel").asText() + "`, exact normals) LBS costs "
                + num(results, "", "flip/lbsFixed") + " ns per vertex plus " + num(results, "", "flip/lbsPerInfluence")
                + " per influence, DQS " + num(results, "", "flip/dqsFixed") + " plus "
                + num(results, "", "flip/dqsPerInfluence"));
        if (f.has("crossing") && f.get("holds").asBoolean()) {
            t.append(", so DQS is the cheaper from about ").append(num(results, "", "flip/crossing"))
                    .append(" influences per vertex on.");
        } else {
            t.append(" (lines that do not describe every point, so no crossing is quoted: the advice section's table"
                    + " has the points).");
        }
        t.append(" The thesis' loop converted each joint to a dual quaternion per vertex and influence and used"
                + " objects per vertex (its chapter " + num(results, "", "deformationChapter") + "), which weighs on both methods differently than flat arrays"
                + " do; the time section's table per asset shows where each kernel lands.");
        report.paragraph(t.toString());
    }

    private static String num(JsonNode results, String claim, String key) {
        return EvalReport.num(results, claim + "/" + key);
    }
}
