package org.skinlab.desktop.eval;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.Stroke;
import java.awt.image.BufferedImage;
import java.util.Locale;

import com.fasterxml.jackson.databind.JsonNode;

import org.skinlab.desktop.bench.ArFrameBench;

/**
 * The "ar-frame" section's figure, drawn from its results alone: on top, one bar per variant, its
 * stages' medians stacked left to right with a whisker over the frame's lowest to highest run and
 * the 60 Hz budget as a dashed line; below, each stage's median per variant as a bar with a
 * whisker from its lowest to its highest run (on a scale of its own, so that the small stages
 * show their spread too). Java2D: a stacked bar with asymmetric whiskers is not a chart XChart
 * draws.
 */
final class EvalArFrameFigure {
    private static final int WIDTH = 1100;
    private static final int LEFT = 190;
    private static final int RIGHT = 160;
    private static final int BAR = 26;
    private static final Color[] STAGE_COLOURS = {new Color(0x4C72B0), new Color(0xDD8452), new Color(0x55A868),
        new Color(0xC44E52), new Color(0x8172B3)};
    private static final Color BUDGET = new Color(0xD62728);

    private EvalArFrameFigure() {
    }

    static BufferedImage draw(JsonNode results) {
        JsonNode variants = results.get("variants");
        int n = variants.size();
        int stages = ArFrameBench.Stage.values().length;
        int top = 70;
        int stackHeight = n * (BAR + 14) + 40;
        int lower = top + stackHeight + 70;
        int rowsHeight = stages * (n * (BAR - 8 + 4) + 14) + 40;
        int height = Math.max(420, lower + rowsHeight + 20);
        BufferedImage image = new BufferedImage(WIDTH, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setColor(Color.WHITE);
            g.fillRect(0, 0, WIDTH, height);
            g.setColor(Color.BLACK);
            g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 15));
            g.drawString("An AR frame, per stage: " + results.get("source").asText(), 12, 22);
            g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
            g.drawString("renderer " + results.get("renderer").asText() + (results.get("softwareRenderer").asBoolean()
                    ? " (a software rasteriser on the CPU, not a GPU)" : "") + "; " + results.get("runs").asInt()
                    + " runs of " + results.get("framesPerRun").asInt() + " frames per variant", 12, 40);
            stacked(g, results, top);
            perStage(g, results, lower);
        } finally {
            g.dispose();
        }
        return image;
    }

    /** The stacked medians per variant, the frame's whisker, the budget line and the legend. */
    private static void stacked(Graphics2D g, JsonNode results, int top) {
        JsonNode variants = results.get("variants");
        double budget = results.get("budgetMs").asDouble();
        double max = budget;
        for (JsonNode v : variants) {
            max = Math.max(max, Math.max(v.get("stageMediansMs").asDouble(), v.at("/frame/maxMs").asDouble()));
        }
        Scale x = new Scale(max * 1.08);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 13));
        g.setColor(Color.BLACK);
        g.drawString("Stage medians stacked (ms per frame); whisker: the frame's lowest to highest run", 12, top - 8);
        int y = top + 6;
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        for (JsonNode v : variants) {
            g.setColor(Color.BLACK);
            g.drawString(label(v), 12, y + BAR / 2 + 5);
            double from = 0;
            for (ArFrameBench.Stage s : ArFrameBench.Stage.values()) {
                double ms = v.at("/stages/" + s.key() + "/medianMs").asDouble();
                g.setColor(STAGE_COLOURS[s.ordinal()]);
                int x0 = x.px(from);
                int x1 = x.px(from + ms);
                g.fillRect(x0, y, Math.max(x1 - x0, ms > 0 ? 1 : 0), BAR);
                from += ms;
            }
            whisker(g, x, v.at("/frame/minMs").asDouble(), v.at("/frame/maxMs").asDouble(), y + BAR / 2, BAR / 2);
            g.setColor(Color.BLACK);
            g.drawString(String.format(Locale.ROOT, "%.2f ms", v.get("stageMediansMs").asDouble()),
                    x.px(Math.max(from, v.at("/frame/maxMs").asDouble())) + 6, y + BAR / 2 + 5);
            y += BAR + 14;
        }
        axis(g, x, top, y);
        Stroke plain = g.getStroke();
        g.setColor(BUDGET);
        g.setStroke(new BasicStroke(2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {8f, 6f}, 0f));
        g.drawLine(x.px(budget), top, x.px(budget), y);
        g.setStroke(plain);
        g.drawString(String.format(Locale.ROOT, "%.1f ms (%d Hz)", budget, results.get("displayHz").asInt()),
                x.px(budget) + 4, y - 2);
        // Legend.
        int lx = LEFT;
        int ly = y + 30;
        for (ArFrameBench.Stage s : ArFrameBench.Stage.values()) {
            g.setColor(STAGE_COLOURS[s.ordinal()]);
            g.fillRect(lx, ly - 10, 14, 12);
            g.setColor(Color.BLACK);
            g.drawString(s.key(), lx + 18, ly);
            lx += 30 + g.getFontMetrics().stringWidth(s.key()) + 20;
        }
    }

    /** Each stage's median per variant, with the runs' range. */
    private static void perStage(Graphics2D g, JsonNode results, int top) {
        JsonNode variants = results.get("variants");
        double max = 0;
        for (JsonNode v : variants) {
            for (ArFrameBench.Stage s : ArFrameBench.Stage.values()) {
                max = Math.max(max, v.at("/stages/" + s.key() + "/maxMs").asDouble());
            }
        }
        Scale x = new Scale(Math.max(max, 1e-3) * 1.08);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 13));
        g.setColor(Color.BLACK);
        g.drawString("Each stage: median of the runs (bar) and lowest to highest run (whisker), ms per frame", 12,
                top - 8);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        int bar = BAR - 8;
        int y = top + 6;
        for (ArFrameBench.Stage s : ArFrameBench.Stage.values()) {
            g.setColor(Color.BLACK);
            g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 12));
            g.drawString(s.key(), 12, y + 13);
            g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
            for (JsonNode v : variants) {
                JsonNode t = v.at("/stages/" + s.key());
                double median = t.get("medianMs").asDouble();
                g.setColor(Color.DARK_GRAY);
                g.drawString(label(v), 70, y + bar - 4);
                g.setColor(STAGE_COLOURS[s.ordinal()]);
                g.fillRect(x.px(0), y, Math.max(x.px(median) - x.px(0), median > 0 ? 1 : 0), bar);
                whisker(g, x, t.get("minMs").asDouble(), t.get("maxMs").asDouble(), y + bar / 2, bar / 2);
                g.setColor(Color.BLACK);
                g.drawString(String.format(Locale.ROOT, "%.3f (%.3f - %.3f)", median, t.get("minMs").asDouble(),
                        t.get("maxMs").asDouble()), x.px(t.get("maxMs").asDouble()) + 6, y + bar - 4);
                y += bar + 4;
            }
            y += 14;
        }
        axis(g, x, top, y - 10);
    }

    private static void whisker(Graphics2D g, Scale x, double min, double max, int yMid, int half) {
        g.setColor(Color.BLACK);
        int x0 = x.px(min);
        int x1 = x.px(max);
        g.drawLine(x0, yMid, x1, yMid);
        g.drawLine(x0, yMid - half / 2, x0, yMid + half / 2);
        g.drawLine(x1, yMid - half / 2, x1, yMid + half / 2);
    }

    /** The x axis below a panel: a line and round ticks in ms. */
    private static void axis(Graphics2D g, Scale x, int top, int bottom) {
        g.setColor(Color.GRAY);
        g.drawLine(x.px(0), top, x.px(0), bottom);
        g.drawLine(x.px(0), bottom, x.px(x.max), bottom);
        double step = niceStep(x.max / 8);
        FontMetrics fm = g.getFontMetrics();
        for (double t = 0; t <= x.max + 1e-9; t += step) {
            int px = x.px(t);
            g.drawLine(px, bottom, px, bottom + 4);
            String text = step >= 1 ? String.format(Locale.ROOT, "%.0f", t) : String.format(Locale.ROOT, "%.2f", t);
            g.drawString(text, px - fm.stringWidth(text) / 2, bottom + 16);
        }
        g.drawString("ms", x.px(x.max) + 8, bottom + 16);
    }

    private static double niceStep(double raw) {
        double p = Math.pow(10, Math.floor(Math.log10(raw)));
        double f = raw / p;
        return (f <= 1 ? 1 : f <= 2 ? 2 : f <= 5 ? 5 : 10) * p;
    }

    private static String label(JsonNode variant) {
        return variant.get("method").asText().toUpperCase(Locale.ROOT) + ", "
                + variant.get("skinning").asText().toUpperCase(Locale.ROOT) + " skinning";
    }

    /** Milliseconds to pixels across the plot. */
    private static final class Scale {
        final double max;

        Scale(double max) {
            this.max = max;
        }

        int px(double ms) {
            return LEFT + (int) Math.round(ms / max * (WIDTH - LEFT - RIGHT));
        }
    }
}
