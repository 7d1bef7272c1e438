package org.skinlab.desktop.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;

import org.skinlab.desktop.Cli;

/** The consistency of {@link ArFrameJson}'s results, which the command's and the eval's tests both check. */
public final class ArFrameChecks {
    /** Six stored values rounded to 0.0005 ms each, and a little for the sums' floating point. */
    public static final double ROUNDING = 0.0031;

    private ArFrameChecks() {
    }

    /**
     * At least 5 runs in every timing, each median within its runs' range; each run's stages
     * summed to its frame time and the stages' medians to {@code stageMediansMs}, within the
     * rounding of the stored values ({@link #ROUNDING}); the share of the 60 Hz budget; the
     * work each stage must have done: a decode, a search, a pose and a draw in every run, a CPU
     * skin exactly where the CPU skins (LBS and DQS have shader code).
     */
    public static void bookkeeping(JsonNode doc) {
        int runs = doc.get("runs").asInt();
        assertTrue(runs >= 5);
        assertEquals(16.667, doc.get("budgetMs").asDouble(), 0);
        for (JsonNode v : doc.get("variants")) {
            JsonNode stages = v.get("stages");
            assertEquals(List.of("decode", "track", "pose", "skin", "draw"), Cli.keys(stages));
            double medians = 0;
            for (JsonNode s : stages) {
                checkTiming(s, runs, v);
                medians += s.get("medianMs").asDouble();
            }
            checkTiming(v.get("frame"), runs, v);
            for (int i = 0; i < runs; i++) {
                double sum = 0;
                for (JsonNode s : stages) {
                    sum += s.get("runs").get(i).asDouble();
                }
                assertEquals(v.at("/frame/runs/" + i).asDouble(), sum, ROUNDING, "run " + i + "'s stages: " + v);
            }
            assertEquals(v.get("stageMediansMs").asDouble(), medians, ROUNDING, v.toString());
            double percent = 100 * v.get("stageMediansMs").asDouble() / (1000.0 / 60);
            assertEquals(percent, v.get("budgetPercent").asDouble(), 1e-4 * percent + 0.001, v.toString());
            boolean gpu = v.get("skinning").asText().equals("gpu");
            for (int i = 0; i < runs; i++) {
                for (String worked : new String[] {"decode", "track", "pose", "draw"}) {
                    assertTrue(stages.get(worked).get("runs").get(i).asDouble() > 0, worked + " did work: " + v);
                }
                double skin = stages.get("skin").get("runs").get(i).asDouble();
                // LBS and DQS have shader code: with GPU skinning the CPU skins nothing.
                assertTrue(gpu ? skin == 0 : skin > 0, "skin, " + v.get("skinning").asText() + ": " + v);
            }
            assertEquals(stages.at("/decode/medianMs").asDouble() + stages.at("/track/medianMs").asDouble(),
                    v.at("/threads/feedMs").asDouble(), ROUNDING);
            assertEquals(stages.at("/draw/medianMs").asDouble(), v.at("/threads/windowMs").asDouble(), 0);
        }
    }

    private static void checkTiming(JsonNode t, int runs, JsonNode where) {
        assertEquals(runs, t.get("runs").size(), where.toString());
        double min = Double.POSITIVE_INFINITY;
        double max = Double.NEGATIVE_INFINITY;
        for (JsonNode r : t.get("runs")) {
            min = Math.min(min, r.asDouble());
            max = Math.max(max, r.asDouble());
        }
        assertEquals(min, t.get("minMs").asDouble(), 0, where.toString());
        assertEquals(max, t.get("maxMs").asDouble(), 0, where.toString());
        assertTrue(t.get("medianMs").asDouble() >= min && t.get("medianMs").asDouble() <= max, where.toString());
    }

}
