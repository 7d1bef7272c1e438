package org.skinlab.desktop.ar;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Iterator;
import java.util.Locale;

import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageTypeSpecifier;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.metadata.IIOMetadata;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageOutputStream;

import org.apache.pdfbox.pdmodel.PDDocument;
import org.apache.pdfbox.pdmodel.PDPageContentStream;
import org.apache.pdfbox.pdmodel.font.PDType1Font;
import org.apache.pdfbox.pdmodel.font.Standard14Fonts;

/**
 * What every printable page of skinlab shares (the marker, the calibration target): PDF points per
 * millimetre, Helvetica text, the 50 mm ruler that checks the print's scale, saving the PDF, and a
 * PNG whose resolution metadata (pHYs) gives its physical size.
 */
final class PrintedPage {
    /** Points per millimetre (PDF's unit is 1/72 inch). */
    static final double POINTS_PER_MM = 72 / 25.4;
    /** The ruler's length in mm. */
    static final int RULER_MM = 50;

    /**
     * PDFBox logs through java.util.logging that it measures the standard Helvetica with a system
     * font's metrics (viewers draw Helvetica themselves) and that it builds a font cache: noise for
     * a command line. Kept in a field: loggers are only weakly held.
     */
    private static final java.util.logging.Logger PDFBOX_LOG = java.util.logging.Logger.getLogger("org.apache.pdfbox");

    static {
        PDFBOX_LOG.setLevel(java.util.logging.Level.SEVERE);
    }

    private PrintedPage() {
    }

    static PDType1Font bold() {
        return new PDType1Font(Standard14Fonts.FontName.HELVETICA_BOLD);
    }

    static PDType1Font plain() {
        return new PDType1Font(Standard14Fonts.FontName.HELVETICA);
    }

    /** One line of text with its baseline's start at (x, y) points. */
    static void text(PDPageContentStream cs, PDType1Font font, float size, double x, double y, String s)
            throws IOException {
        cs.beginText();
        cs.setFont(font, size);
        cs.newLineAtOffset((float) x, (float) y);
        cs.showText(s);
        cs.endText();
    }

    /** The 50 mm ruler with 10 mm ticks from (x, y) points to the right, and its label. */
    static void ruler(PDPageContentStream cs, double x, double y) throws IOException {
        cs.setStrokingColor(0f);
        cs.setLineWidth(0.7f);
        cs.moveTo((float) x, (float) y);
        cs.lineTo((float) (x + RULER_MM * POINTS_PER_MM), (float) y);
        for (int mm = 0; mm <= RULER_MM; mm += 10) {
            double tx = x + mm * POINTS_PER_MM;
            cs.moveTo((float) tx, (float) y);
            cs.lineTo((float) tx, (float) (y + (mm % RULER_MM == 0 ? 10 : 6)));
        }
        cs.stroke();
        text(cs, plain(), 9, x + RULER_MM * POINTS_PER_MM + 8, y - 3, RULER_MM + " mm: check your print");
    }

    /** Saves {@code doc} to {@code file}, creating its folder and replacing an older file. */
    static void save(PDDocument doc, Path file) throws IOException {
        prepare(file);
        doc.save(file.toFile());
    }

    /** Writes {@code image} as PNG with {@code pixelsPerMetre} in its pHYs chunk (the print size). */
    static void writePng(BufferedImage image, double pixelsPerMetre, Path file) throws IOException {
        prepare(file);
        Iterator<ImageWriter> writers = ImageIO.getImageWritersByFormatName("png");
        ImageWriter writer = writers.next();
        ImageWriteParam param = writer.getDefaultWriteParam();
        IIOMetadata metadata = writer.getDefaultImageMetadata(ImageTypeSpecifier.createFromRenderedImage(image), param);
        IIOMetadataNode root = new IIOMetadataNode("javax_imageio_png_1.0");
        IIOMetadataNode phys = new IIOMetadataNode("pHYs");
        String ppm = Integer.toString((int) Math.round(pixelsPerMetre));
        phys.setAttribute("pixelsPerUnitXAxis", ppm);
        phys.setAttribute("pixelsPerUnitYAxis", ppm);
        phys.setAttribute("unitSpecifier", "meter");
        root.appendChild(phys);
        metadata.mergeTree("javax_imageio_png_1.0", root);
        try (ImageOutputStream out = ImageIO.createImageOutputStream(file.toFile())) {
            writer.setOutput(out);
            writer.write(null, new IIOImage(image, null, metadata), param);
        } finally {
            writer.dispose();
        }
    }

    private static void prepare(Path file) throws IOException {
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        Files.deleteIfExists(file);
    }

    /** Millimetres as printed: whole numbers without decimals, else one decimal. */
    static String format(double mm) {
        return mm == Math.rint(mm) ? Long.toString((long) mm) : String.format(Locale.ROOT, "%.1f", mm);
    }
}
