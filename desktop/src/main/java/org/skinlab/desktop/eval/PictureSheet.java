package org.skinlab.desktop.eval;

import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.util.List;

import org.skinlab.internal.scene.ColourRamp;

/**
 * The pictures section's figures: the viewer's panels in a grid under a title, each under its
 * label, and the difference view's colour bar (the viewer's own {@link ColourRamp}, so the bar
 * shows exactly the colours the panel uses).
 */
final class PictureSheet {
    private static final int TITLE_HEIGHT = 32;
    private static final int LABEL_LINE = 20;
    private static final int GAP = 6;
    private static final int BAR_WIDTH = 18;

    private PictureSheet() {
    }

    /** {@code panels} (all of one size) in rows of {@code columns}, each under its label, under the title (lines split at "\n"). */
    static BufferedImage grid(String title, List<BufferedImage> panels, List<String> labels, int columns) {
        String[] titleLines = title.split("\n");
        int titleHeight = TITLE_HEIGHT + (titleLines.length - 1) * (TITLE_HEIGHT - 8);
        int w = panels.get(0).getWidth();
        int h = panels.get(0).getHeight();
        int lines = 1;
        for (String l : labels) {
            lines = Math.max(lines, l.split("\n").length);
        }
        int cell = LABEL_LINE * lines + 6 + h;
        int rows = (panels.size() + columns - 1) / columns;
        int cols = Math.min(columns, panels.size());
        BufferedImage sheet = new BufferedImage(cols * w + (cols - 1) * GAP, titleHeight + rows * cell
                + (rows - 1) * GAP, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = sheet.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setColor(Color.WHITE);
            g.fillRect(0, 0, sheet.getWidth(), sheet.getHeight());
            g.setColor(Color.BLACK);
            g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 18));
            for (int l = 0; l < titleLines.length; l++) {
                g.drawString(titleLines[l], 8, 24 + l * (TITLE_HEIGHT - 8));
            }
            g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 15));
            for (int i = 0; i < panels.size(); i++) {
                int x = (i % columns) * (w + GAP);
                int y = titleHeight + (i / columns) * (cell + GAP);
                String[] text = labels.get(i).split("\n");
                for (int l = 0; l < text.length; l++) {
                    g.drawString(text[l], x + 6, y + LABEL_LINE * (l + 1) - 4);
                }
                g.drawImage(panels.get(i), x, y + LABEL_LINE * lines + 6, null);
            }
        } finally {
            g.dispose();
        }
        return sheet;
    }

    /**
     * A copy of the difference panel with the colour bar at its right edge: the ramp from 0 (bottom)
     * to {@code fullPercent} % of the model's size (top; red there and beyond), labelled.
     */
    static BufferedImage withColourBar(BufferedImage panel, String zeroLabel, String fullLabel) {
        BufferedImage out = new BufferedImage(panel.getWidth(), panel.getHeight(), BufferedImage.TYPE_INT_RGB);
        Graphics2D g = out.createGraphics();
        try {
            g.drawImage(panel, 0, 0, null);
            int top = 30;
            int bottom = panel.getHeight() - 30;
            int x = panel.getWidth() - BAR_WIDTH - 12;
            for (int y = top; y <= bottom; y++) {
                g.setColor(new Color(ColourRamp.colour((double) (bottom - y) / (bottom - top))));
                g.drawLine(x, y, x + BAR_WIDTH, y);
            }
            g.setColor(Color.WHITE);
            g.drawRect(x, top, BAR_WIDTH, bottom - top);
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 13));
            int fullWidth = g.getFontMetrics().stringWidth(fullLabel);
            int zeroWidth = g.getFontMetrics().stringWidth(zeroLabel);
            g.drawString(fullLabel, x + BAR_WIDTH - fullWidth, top - 8);
            g.drawString(zeroLabel, x + BAR_WIDTH - zeroWidth, bottom + 20);
        } finally {
            g.dispose();
        }
        return out;
    }
}
