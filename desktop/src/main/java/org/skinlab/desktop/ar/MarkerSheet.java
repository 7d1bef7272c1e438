package org.skinlab.desktop.ar;

import static org.skinlab.desktop.ar.PrintedPage.POINTS_PER_MM;
import static org.skinlab.desktop.ar.PrintedPage.format;
import static org.skinlab.desktop.ar.PrintedPage.text;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;

import org.apache.pdfbox.pdmodel.PDDocument;
import org.apache.pdfbox.pdmodel.PDPage;
import org.apache.pdfbox.pdmodel.PDPageContentStream;
import org.apache.pdfbox.pdmodel.common.PDRectangle;

import org.skinlab.ar.MarkerPattern;

/**
 * The printable marker: an A4 PDF with the black square at its exact physical size (vector cells,
 * so any printer prints it sharp), the dictionary, id and size printed beside it and a 50 mm
 * ruler to check the print; and a PNG of the marker with a white quiet zone of two cells, whose
 * resolution metadata gives the same physical size.
 */
public final class MarkerSheet {
    /** The largest black square that fits A4 with its margins and text, in mm. */
    public static final double MAX_SIZE_MM = 180;
    /** White cells around the black square in the PNG. */
    public static final int QUIET_CELLS = 2;

    private MarkerSheet() {
    }

    /** Writes the A4 page with {@code pattern}'s black square {@code sizeMm} wide. */
    public static void writePdf(MarkerPattern pattern, double sizeMm, Path file) throws IOException {
        checkSize(sizeMm);
        PDRectangle a4 = PDRectangle.A4;
        try (PDDocument doc = new PDDocument()) {
            PDPage page = new PDPage(a4);
            doc.addPage(page);
            double size = sizeMm * POINTS_PER_MM;
            double x0 = (a4.getWidth() - size) / 2;
            double y0 = (a4.getHeight() - size) / 2 + 20;
            double cell = size / pattern.cells();
            try (PDPageContentStream cs = new PDPageContentStream(doc, page)) {
                cs.setNonStrokingColor(0f);
                // All black cells in one path, filled once: no seams between neighbouring cells.
                for (int row = 0; row < pattern.cells(); row++) {
                    for (int col = 0; col < pattern.cells(); col++) {
                        if (pattern.isBlack(row, col)) {
                            cs.addRect((float) (x0 + col * cell), (float) (y0 + size - (row + 1) * cell), (float) cell,
                                    (float) cell);
                        }
                    }
                }
                cs.fill();
                text(cs, PrintedPage.bold(), 16, 56, a4.getHeight() - 64, "skinlab marker: " + pattern.dictionary().key()
                        + ", id " + pattern.id() + ", black square " + format(sizeMm) + " mm");
                text(cs, PrintedPage.plain(), 11, 56, a4.getHeight() - 84,
                        "Print at 100% (actual size; no \"fit to page\"). Keep the white border around the black square.");
                text(cs, PrintedPage.plain(), 11, 56, a4.getHeight() - 100,
                        "Measure the black square; if it is not " + format(sizeMm) + " mm, give the measured width to skinlab "
                                + "(--marker-size MM).");
                PrintedPage.ruler(cs, (a4.getWidth() - PrintedPage.RULER_MM * POINTS_PER_MM) / 2, y0 - 60);
            }
            PrintedPage.save(doc, file);
        }
    }

    /** Writes the PNG: the black square close to {@code dpi}, whole pixels per cell, the exact resolution in its metadata. */
    public static void writePng(MarkerPattern pattern, double sizeMm, int dpi, Path file) throws IOException {
        checkSize(sizeMm);
        if (dpi < 50 || dpi > 2400) {
            throw new IllegalArgumentException("dpi must be in 50..2400: " + dpi);
        }
        BufferedImage image = image(pattern, sizeMm, dpi);
        int cellPixels = cellPixels(pattern, sizeMm, dpi);
        double pixelsPerMetre = cellPixels * pattern.cells() / (sizeMm / 1000);
        PrintedPage.writePng(image, pixelsPerMetre, file);
    }

    /** Pixels per cell of the PNG: the cell's width at {@code dpi}, rounded to a whole pixel. */
    public static int cellPixels(MarkerPattern pattern, double sizeMm, int dpi) {
        return Math.max(1, (int) Math.round(sizeMm / 25.4 * dpi / pattern.cells()));
    }

    /** The PNG's picture: the cells at {@link #cellPixels} with {@link #QUIET_CELLS} white cells around. */
    public static BufferedImage image(MarkerPattern pattern, double sizeMm, int dpi) {
        int c = cellPixels(pattern, sizeMm, dpi);
        int n = pattern.cells() + 2 * QUIET_CELLS;
        BufferedImage image = new BufferedImage(n * c, n * c, BufferedImage.TYPE_BYTE_GRAY);
        for (int y = 0; y < n * c; y++) {
            for (int x = 0; x < n * c; x++) {
                int row = y / c - QUIET_CELLS;
                int col = x / c - QUIET_CELLS;
                boolean black = row >= 0 && col >= 0 && row < pattern.cells() && col < pattern.cells()
                        && pattern.isBlack(row, col);
                image.getRaster().setSample(x, y, 0, black ? 0 : 255);
            }
        }
        return image;
    }

    private static void checkSize(double sizeMm) {
        if (!(sizeMm >= 20 && sizeMm <= MAX_SIZE_MM)) {
            throw new IllegalArgumentException("marker size must be 20 to " + format(MAX_SIZE_MM) + " mm for an A4 page: "
                    + format(sizeMm));
        }
    }
}
