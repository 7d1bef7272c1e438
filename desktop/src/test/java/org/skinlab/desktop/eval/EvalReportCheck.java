package org.skinlab.desktop.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import javax.imageio.ImageIO;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * The checks every section's test of {@code skinlab eval} makes on a report: the figures it links
 * exist and are not blank, and every number its text prints is a value of results.json.
 */
final class EvalReportCheck {
    /** A number standing alone: not part of a word, a file name or a longer number. */
    private static final Pattern NUMBER = Pattern.compile("(?<![\\w.\\-])\\d+(?:\\.\\d+)?(?![\\w.]*\\w)");
    private static final Pattern FIGURE = Pattern.compile("!\\[[^\\]]*\\]\\(([^)]+)\\)");

    private EvalReportCheck() {
    }

    /**
     * Every figure the report links exists, decodes and is not blank; every PNG written is linked;
     * every number of the text (outside code spans and figure links) is a value of results.json.
     * Returns the linked figures.
     */
    static List<String> figuresAndNumbers(Path dir, JsonNode results, String readme) throws Exception {
        // Every figure it links exists, decodes, and has a plot and a footer's worth of pixels.
        List<String> linked = new ArrayList<>();
        Matcher f = FIGURE.matcher(readme);
        while (f.find()) {
            linked.add(f.group(1));
        }
        for (String png : linked) {
            BufferedImage image = ImageIO.read(dir.resolve(png).toFile());
            assertTrue(image != null && image.getWidth() >= 600 && image.getHeight() >= 400, png);
            assertTrue(colours(image) >= 8, png + " looks blank");
        }
        try (Stream<Path> files = Files.list(dir)) {
            Set<String> written = files.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".png"))
                    .collect(Collectors.toSet());
            assertEquals(new HashSet<>(linked), written, "every PNG written is linked, and only those");
        }

        // Every number of the text (outside code spans and figure links) is a value of results.json.
        Set<String> values = new HashSet<>();
        collect(results, values);
        String text = FIGURE.matcher(readme).replaceAll("").replaceAll("`[^`\n]*`", "");
        Matcher n = NUMBER.matcher(text);
        int found = 0;
        while (n.find()) {
            found++;
            assertTrue(values.contains(n.group()), "README prints " + n.group() + " (near \""
                    + text.substring(Math.max(0, n.start() - 40), Math.min(text.length(), n.end() + 20))
                    + "\"), which results.json does not hold");
        }
        return linked;
    }

    /** The figures the report links, in order. */
    static List<String> linked(String readme) {
        List<String> linked = new ArrayList<>();
        Matcher f = FIGURE.matcher(readme);
        while (f.find()) {
            linked.add(f.group(1));
        }
        return linked;
    }

    static int numbers(String readme) {
        String text = FIGURE.matcher(readme).replaceAll("").replaceAll("`[^`\n]*`", "");
        Matcher n = NUMBER.matcher(text);
        int found = 0;
        while (n.find()) {
            found++;
        }
        return found;
    }

    static void collect(JsonNode node, Set<String> values) {
        if (node.isNumber()) {
            values.add(EvalReport.format(node));
        }
        for (JsonNode child : node) {
            collect(child, values);
        }
    }

    private static int colours(BufferedImage image) {
        Set<Integer> seen = new HashSet<>();
        for (int y = 0; y < image.getHeight(); y += 3) {
            for (int x = 0; x < image.getWidth(); x += 3) {
                seen.add(image.getRGB(x, y));
            }
        }
        return seen.size();
    }
}
