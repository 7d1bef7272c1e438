package org.skinlab.desktop.eval;

import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.math.BigDecimal;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import javax.imageio.ImageIO;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.internal.chartpart.Chart;
import org.skinlab.internal.bench.Spread;

/**
 * README.md of {@code skinlab eval}, built from results.json alone: sections add text, tables and
 * figures, and every number goes through {@link #num}, which prints a number node of the results
 * by one rule ({@link #format}), so a reader (and a test) finds each printed number in the JSON.
 * Numbers are stored rounded ({@link #round}), so the rule needs no rounding of its own. Each
 * figure is a PNG (an XChart chart or a picture) with a footer naming the machine, the JVM and the
 * command.
 */
final class EvalReport {
    private static final int FOOTER_LINE = 16;

    private final StringBuilder md = new StringBuilder();
    private final Path dir;
    private final List<String> footer;
    private final List<String> figures = new ArrayList<>();

    EvalReport(Path dir, JsonNode machine) {
        this.dir = dir;
        this.footer = EvalMachine.lines(machine);
    }

    /** A double rounded to 3 decimals, as results.json stores every measured value. */
    static double round(double d) {
        return Math.round(d * 1000.0) / 1000.0;
    }

    /**
     * A timing taken in several runs, as results.json keeps every one: {@code node.name} becomes
     * {@code {"median", "min", "max", "q1", "q3", "runs": [...]}} (rounded; runs in the order they
     * were taken). Returns the new node.
     */
    static ObjectNode putSpread(ObjectNode node, String name, Spread spread) {
        ObjectNode s = node.putObject(name);
        s.put("median", round(spread.median()));
        s.put("min", round(spread.min()));
        s.put("max", round(spread.max()));
        s.put("q1", round(spread.lowerQuartile()));
        s.put("q3", round(spread.upperQuartile()));
        ArrayNode runs = s.putArray("runs");
        for (double r : spread.runs()) {
            runs.add(round(r));
        }
        return s;
    }

    /** The one rule: integers as they are, decimals without trailing zeros, never an exponent. */
    static String format(JsonNode number) {
        if (!number.isNumber()) {
            throw new IllegalArgumentException("not a number: " + number);
        }
        if (number.isIntegralNumber()) {
            return number.bigIntegerValue().toString();
        }
        BigDecimal d = number.decimalValue().stripTrailingZeros();
        return d.scale() < 0 ? d.setScale(0).toPlainString() : d.toPlainString();
    }

    /** The number at {@code pointer} (a JSON pointer, e.g. "/files/0/medianMillis") below {@code node}. */
    static String num(JsonNode node, String pointer) {
        JsonNode n = node.at(pointer);
        if (n.isMissingNode()) {
            throw new IllegalStateException("results.json has no " + pointer);
        }
        return format(n);
    }

    /** {@link #format}, or a dash for a missing or null value (no number printed). */
    static String numOrDash(JsonNode node, String pointer) {
        JsonNode n = node.at(pointer);
        return n.isNumber() ? format(n) : "-";
    }

    EvalReport line(String text) {
        md.append(text).append('\n');
        return this;
    }

    EvalReport paragraph(String text) {
        md.append(text).append("\n\n");
        return this;
    }

    EvalReport heading(int level, String text) {
        md.append("#".repeat(level)).append(' ').append(text).append("\n\n");
        return this;
    }

    /** A markdown table row: cells joined by pipes. */
    EvalReport row(String... cells) {
        md.append("| ").append(String.join(" | ", cells)).append(" |\n");
        return this;
    }

    /** A table's header and its rule line. */
    EvalReport header(String... cells) {
        row(cells);
        String[] rule = new String[cells.length];
        java.util.Arrays.fill(rule, "---");
        return row(rule);
    }

    /** Writes the chart as {@code file} (PNG, with the footer) and links it with its caption. */
    EvalReport figure(String file, String caption, Chart<?, ?> chart) {
        return image(file, caption, BitmapEncoder.getBufferedImage(chart));
    }

    /**
     * Writes a figure that is a picture rather than a chart (e.g. the viewer's screenshots) as
     * {@code file}, with the same footer, and links it with its caption.
     */
    EvalReport image(String file, String caption, BufferedImage plot) {
        BufferedImage image = new BufferedImage(plot.getWidth(), plot.getHeight() + FOOTER_LINE * footer.size() + 8,
                BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setColor(Color.WHITE);
            g.fillRect(0, 0, image.getWidth(), image.getHeight());
            g.drawImage(plot, 0, 0, null);
            g.setColor(Color.DARK_GRAY);
            g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
            for (int i = 0; i < footer.size(); i++) {
                g.drawString(footer.get(i), 8, plot.getHeight() + FOOTER_LINE * (i + 1));
            }
        } finally {
            g.dispose();
        }
        try {
            ImageIO.write(image, "png", dir.resolve(file).toFile());
        } catch (IOException e) {
            throw new UncheckedIOException(dir.resolve(file) + ": cannot be written", e);
        }
        figures.add(file);
        md.append("![").append(caption).append("](").append(file).append(")\n\n");
        return this;
    }

    /**
     * Links a figure already in the report's folder (written by an earlier run of the section,
     * when the report is written again from results.json alone); says so when it is not there.
     */
    EvalReport existing(String file, String caption) {
        if (java.nio.file.Files.isRegularFile(dir.resolve(file))) {
            figures.add(file);
            md.append("![").append(caption).append("](").append(file).append(")\n\n");
        } else {
            paragraph("(" + caption + ": not drawn in this run.)");
        }
        return this;
    }

    /** The PNG files written (or linked) so far. */
    List<String> figures() {
        return List.copyOf(figures);
    }

    String markdown() {
        return md.toString();
    }
}
