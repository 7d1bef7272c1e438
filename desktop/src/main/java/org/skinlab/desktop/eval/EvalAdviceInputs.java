package org.skinlab.desktop.eval;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.skinning.SkinningMethod;

/**
 * The numbers of the earlier sections that the advice argues with, copied into its own results
 * (so that its text prints only numbers of results.json), with the ratios derived from them; a
 * section that was not run leaves its inputs out, and the advice says so.
 */
final class EvalAdviceInputs {
    /** The bend and twist angle the close-up and twist advice quote (our cylinders reach it). */
    static final double QUOTED_DEGREES = 170;
    /** The angles either side of a half turn the twist advice compares. */
    static final double BEFORE_HALF_TURN = 179;
    static final double AFTER_HALF_TURN = 181;
    /** A crowd member's height on screen, in pixels, for the crowd advice. */
    static final double CROWD_PIXELS = 100;

    private EvalAdviceInputs() {
    }

    static void collect(EvalContext context, ObjectNode in) {
        JsonNode time = context.measured("time");
        if (time != null) {
            character(time, in);
        }
        JsonNode quality = context.measured("quality");
        if (quality != null) {
            quality(quality, in);
        }
        crowds(context.measured("crowds"), in);
        tracking(context.measured("tracking"), in);
    }

    /** The bundled character's frame per method and kernels, and the methods' cost ratios. */
    private static void character(JsonNode time, ObjectNode in) {
        JsonNode asset = EvalTimeSection.asset(time, EvalAdviceSection.CHARACTER);
        if (asset == null) {
            return;
        }
        ObjectNode c = in.putObject("character");
        c.put("file", EvalAdviceSection.CHARACTER);
        c.put("vertices", asset.get("renderVertices").asInt());
        c.put("joints", asset.get("joints").asInt());
        for (String kernels : new String[] {"fastest", "scalar"}) {
            ObjectNode k = c.putObject(kernels);
            for (SkinningMethod m : new SkinningMethod[] {SkinningMethod.LBS, SkinningMethod.DQS, SkinningMethod.COR}) {
                JsonNode run = EvalTimeSection.run(asset, m, kernels, "all");
                double micros = run.at("/micros/median").asDouble();
                k.put(m.key() + "Micros", micros);
                k.put(m.key() + "PerFrame", (long) Math.floor(EvalAdviceSection.FRAME_MICROS / micros));
            }
            for (JsonNode r : asset.get("dqsOverLbs")) {
                if (r.get("kernels").asText().equals(kernels) && r.get("influences").asText().equals("all")) {
                    k.put("dqsOverLbs", r.at("/ratio/median").asDouble());
                }
            }
            k.put("corOverDqs", EvalReport.round(k.get("corMicros").asDouble() / k.get("dqsMicros").asDouble()));
        }
    }

    /** The twist, bend, character and influence-cap numbers of the quality section. */
    private static void quality(JsonNode quality, ObjectNode in) {
        for (JsonNode asset : quality.get("assets")) {
            String file = asset.get("file").asText();
            if (asset.has("skipped")) {
                continue;
            }
            switch (file) {
                case "cylinder-twist-high.dae" -> twist(asset, in);
                case "cylinder-bend.dae" -> bend(asset, in);
                case "cylinder-twist-full.dae" -> halfTurn(asset, in);
                case EvalAdviceSection.CHARACTER -> characterQuality(quality, asset, in.putObject("characterQuality"));
                default -> {
                    if (asset.has("influences") && asset.get("influences").asInt() > InfluenceCapReport.CAP_4
                            && !in.has("cap")) {
                        cap(asset, in.putObject("cap"));
                    }
                }
            }
        }
    }

    private static void twist(JsonNode asset, ObjectNode in) {
        JsonNode at = atAngle(asset, QUOTED_DEGREES);
        if (at == null) {
            return;
        }
        ObjectNode t = in.putObject("twist");
        t.put("file", asset.get("file").asText());
        t.put("angleDegrees", QUOTED_DEGREES);
        for (SkinningMethod m : SkinningMethod.values()) {
            t.put(m.key() + "Ring", at.at("/methods/" + m.key() + "/ringRadius/0").asDouble());
        }
        // The first sampled angle at which LBS has lost a tenth of the ring.
        JsonNode ring = asset.at("/methods/lbs/ringRadius");
        for (int i = 0; i < ring.size(); i++) {
            if (ring.get(i).asDouble() < 0.9) {
                t.put("lbsRingBelow90PercentAtDegrees", asset.at("/angleDegrees/" + i).asDouble());
                break;
            }
        }
    }

    private static void bend(JsonNode asset, ObjectNode in) {
        JsonNode at = atAngle(asset, QUOTED_DEGREES);
        if (at == null) {
            return;
        }
        ObjectNode b = in.putObject("bend");
        b.put("file", asset.get("file").asText());
        b.put("angleDegrees", QUOTED_DEGREES);
        for (SkinningMethod m : SkinningMethod.values()) {
            String p = "/methods/" + m.key();
            b.put(m.key() + "Bulge", at.at(p + "/bulge/0").asDouble());
            b.put(m.key() + "Volume", at.at(p + "/volume/0").asDouble());
            b.put(m.key() + "MaxBulge", asset.at(p + "/maxBulge").asDouble());
            b.put(m.key() + "MaxBulgeDegrees", asset.at("/angleDegrees/" + asset.at(p + "/maxBulgeSample").asInt())
                    .asDouble());
        }
        b.put("dqsCorPixels", EvalQualitySection.pair(asset, "dqs", "cor").get("maxPixels").asDouble());
    }

    /** The ring's turn either side of a half turn and at the full turn, per method. */
    private static void halfTurn(JsonNode asset, ObjectNode in) {
        JsonNode before = atAngle(asset, BEFORE_HALF_TURN);
        JsonNode after = atAngle(asset, AFTER_HALF_TURN);
        JsonNode full = atAngle(asset, 360);
        if (before == null || after == null || full == null) {
            return;
        }
        ObjectNode t = in.putObject("fullTwist");
        t.put("file", asset.get("file").asText());
        t.put("beforeDegrees", BEFORE_HALF_TURN);
        t.put("afterDegrees", AFTER_HALF_TURN);
        t.put("fullDegrees", 360);
        for (SkinningMethod m : SkinningMethod.values()) {
            String p = "/methods/" + m.key() + "/ringTurnDegrees/0";
            t.put(m.key() + "TurnBefore", before.at(p).asDouble());
            t.put(m.key() + "TurnAfter", after.at(p).asDouble());
            t.put(m.key() + "TurnFull", full.at(p).asDouble());
        }
    }

    private static void characterQuality(JsonNode quality, JsonNode asset, ObjectNode d) {
        JsonNode lbsDqs = EvalQualitySection.pair(asset, "lbs", "dqs");
        d.put("maxLbsDqsPercent", lbsDqs.get("maxPercent").asDouble());
        d.put("maxLbsDqsPixels", lbsDqs.get("maxPixels").asDouble());
        d.put("maxDqsCorPercent", EvalQualitySection.pair(asset, "dqs", "cor").get("maxPercent").asDouble());
        // The character on the phone's screen and as a crowd member: the shift scales with its height in pixels.
        double tall = quality.at("/phone/focalPixels").asDouble() * quality.at("/phone/characterMetres").asDouble()
                / quality.at("/phone/distanceMetres").asDouble();
        d.put("characterPixels", EvalReport.round(tall));
        d.put("crowdPixels", CROWD_PIXELS);
        d.put("crowdLbsDqsPixels", EvalReport.round(lbsDqs.get("maxPixels").asDouble() * CROWD_PIXELS / tall));
    }

    private static void cap(JsonNode asset, ObjectNode cap) {
        cap.put("file", asset.get("file").asText());
        cap.put("influences", asset.get("influences").asInt());
        for (JsonNode c : asset.get("caps")) {
            if (c.get("cap").asInt() == InfluenceCapReport.CAP_4) {
                cap.put("cap", InfluenceCapReport.CAP_4);
                cap.put("cappedPositions", c.get("cappedPositions").asInt());
                cap.put("lbsPercent", c.get("lbsPercent").asDouble());
                cap.put("dqsPercent", c.get("dqsPercent").asDouble());
            }
        }
    }

    /** The quality section's values at {@code degrees} on an asset, or null when its clip does not reach them. */
    static JsonNode atAngle(JsonNode asset, double degrees) {
        for (JsonNode a : asset.path("atAngles")) {
            if (a.get("angleDegrees").asDouble() == degrees) {
                return a;
            }
        }
        return null;
    }

    /** The crowds' characters per frame at all cores. */
    private static void crowds(JsonNode crowds, ObjectNode in) {
        if (crowds == null) {
            return;
        }
        for (JsonNode m : crowds.path("models")) {
            if (!m.get("file").asText().equals(EvalAdviceSection.CHARACTER)) {
                continue;
            }
            ObjectNode c = in.putObject("crowds");
            c.put("cores", crowds.get("cores").asInt());
            c.put("crowd", crowds.get("threadCrowd").asInt());
            for (JsonNode p : m.get("threads")) {
                if (p.get("threads").asInt() == crowds.get("cores").asInt()) {
                    c.put(p.get("method").asText() + "PerFrame",
                            Math.round(p.at("/charactersPerFrame/median").asDouble()));
                }
            }
        }
    }

    /** The tracker's time per whole frame and its share of a frame. */
    private static void tracking(JsonNode tracking, ObjectNode in) {
        if (tracking == null || !tracking.has("time")) {
            return;
        }
        ObjectNode k = in.putObject("tracking");
        k.put("detectMedianMs", tracking.at("/time/detectMs/median").asDouble());
        k.put("trackMedianMs", tracking.at("/time/trackMs/median").asDouble());
        k.put("detectOverTrack", tracking.at("/time/detectOverTrack").asDouble());
        k.put("width", tracking.at("/time/width").asInt());
        k.put("height", tracking.at("/time/height").asInt());
        k.put("fullFrameEvery", tracking.at("/time/fullFrameEvery").asInt());
        k.put("framePercent", EvalReport.round(100 * k.get("detectMedianMs").asDouble() * 1000
                / EvalAdviceSection.FRAME_MICROS));
    }
}
