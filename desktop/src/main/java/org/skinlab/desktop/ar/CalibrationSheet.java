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

import org.skinlab.internal.ar.CalibrationTarget;

/**
 * The printable calibration target: an A4 PDF (landscape when the target is wider than tall) with
 * the pattern at its exact physical size in vector squares, the target's parameters and the
 * options that name it to {@code skinlab calibrate} printed above it, and the 50 mm ruler; and a
 * PNG with whole pixels per square and its resolution in the metadata.
 */
public final class CalibrationSheet {
    /** White around the pattern on the page, in mm: the detectors need the outer squares' edges. */
    public static final double QUIET_MM = 8;
    /** The page's side margins, and the space the text (top) and the ruler (bottom) take, in mm. */
    private static final double SIDE_MM = 15;
    private static final double TOP_MM = 29;
    private static final double BOTTOM_MM = 16;

    private CalibrationSheet() {
    }

    /** Writes the A4 page of {@code target}; IllegalArgumentException when it does not fit. */
    public static void writePdf(CalibrationTarget target, Path file) throws IOException {
        double wMm = target.width() * 1000;
        double hMm = target.height() * 1000;
        PDRectangle a4 = PDRectangle.A4;
        PDRectangle box = wMm > hMm ? new PDRectangle(a4.getHeight(), a4.getWidth()) : a4;
        double pageW = box.getWidth() / POINTS_PER_MM;
        double pageH = box.getHeight() / POINTS_PER_MM;
        double roomW = pageW - 2 * SIDE_MM - 2 * QUIET_MM;
        double roomH = pageH - TOP_MM - BOTTOM_MM - 2 * QUIET_MM;
        if (wMm > roomW + 1e-9 || hMm > roomH + 1e-9) {
            throw new IllegalArgumentException("the target (" + target.describe() + ") is " + format(wMm) + " x "
                    + format(hMm) + " mm; with its white border an A4 page holds at most " + format(Math.floor(roomW))
                    + " x " + format(Math.floor(roomH)) + " mm: use fewer or smaller squares");
        }
        try (PDDocument doc = new PDDocument()) {
            PDPage page = new PDPage(box);
            doc.addPage(page);
            // The pattern centred in the room between the text and the ruler; PDF's y grows upward.
            double x0 = (pageW - wMm) / 2 * POINTS_PER_MM;
            double top = (pageH - TOP_MM - QUIET_MM - (roomH - hMm) / 2) * POINTS_PER_MM;
            double square = target.squareMetres() * 1000 * POINTS_PER_MM;
            double pitch = (target.squareMetres() + target.spaceMetres()) * 1000 * POINTS_PER_MM;
            try (PDPageContentStream cs = new PDPageContentStream(doc, page)) {
                cs.setNonStrokingColor(0f);
                // All black squares in one path, filled once: no seams where chessboard squares meet.
                double half = target.squareMetres() / 2;
                double pitchMetres = target.squareMetres() + target.spaceMetres();
                for (int row = 0; row < target.rows(); row++) {
                    for (int col = 0; col < target.cols(); col++) {
                        if (target.isBlackAt(col * pitchMetres + half, row * pitchMetres + half)) {
                            cs.addRect((float) (x0 + col * pitch), (float) (top - row * pitch - square), (float) square,
                                    (float) square);
                        }
                    }
                }
                cs.fill();
                double left = SIDE_MM * POINTS_PER_MM;
                double height = box.getHeight();
                text(cs, PrintedPage.bold(), 15, left, height - 12 * POINTS_PER_MM,
                        "skinlab calibration target: " + target.describe());
                text(cs, PrintedPage.plain(), 10.5f, left, height - 18.5 * POINTS_PER_MM,
                        "skinlab calibrate " + target.options() + " --images DIR --out camera.json");
                text(cs, PrintedPage.plain(), 10.5f, left, height - 24 * POINTS_PER_MM,
                        "Print at 100% (actual size; no \"fit to page\"), lay it flat. Measure a square; if it is not "
                                + format(target.squareMetres() * 1000) + " mm, pass the measured size.");
                PrintedPage.ruler(cs, left, 8 * POINTS_PER_MM);
            }
            PrintedPage.save(doc, file);
        }
    }

    /** Writes the PNG: whole pixels per square close to {@code dpi}, the exact resolution in its metadata. */
    public static void writePng(CalibrationTarget target, int dpi, Path file) throws IOException {
        if (dpi < 50 || dpi > 2400) {
            throw new IllegalArgumentException("dpi must be in 50..2400: " + dpi);
        }
        PrintedPage.writePng(image(target, dpi), pixelsPerMetre(target, dpi), file);
    }

    /** The PNG's scale: the square's width at {@code dpi} rounded to whole pixels, per metre. */
    public static double pixelsPerMetre(CalibrationTarget target, int dpi) {
        long squarePixels = Math.max(1, Math.round(target.squareMetres() / 0.0254 * dpi));
        return squarePixels / target.squareMetres();
    }

    /** The PNG's picture: the pattern with a white border one square wide, sampled at pixel centres. */
    public static BufferedImage image(CalibrationTarget target, int dpi) {
        double ppm = pixelsPerMetre(target, dpi);
        int border = (int) Math.round(target.squareMetres() * ppm);
        int w = (int) Math.round(target.width() * ppm) + 2 * border;
        int h = (int) Math.round(target.height() * ppm) + 2 * border;
        if ((long) w * h > 200_000_000L) {
            throw new IllegalArgumentException("a " + w + " x " + h + " pixel PNG is too large: lower --dpi");
        }
        BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_BYTE_GRAY);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                boolean black = target.isBlackAt((x - border + 0.5) / ppm, (y - border + 0.5) / ppm);
                image.getRaster().setSample(x, y, 0, black ? 0 : 255);
            }
        }
        return image;
    }
}
