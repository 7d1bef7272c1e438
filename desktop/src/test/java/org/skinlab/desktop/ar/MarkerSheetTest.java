package org.skinlab.desktop.ar;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.List;

import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageInputStream;

import org.apache.pdfbox.Loader;
import org.apache.pdfbox.pdmodel.PDDocument;
import org.apache.pdfbox.pdmodel.common.PDRectangle;
import org.apache.pdfbox.rendering.ImageType;
import org.apache.pdfbox.rendering.PDFRenderer;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.FiducialTracker;
import org.skinlab.ar.GrayImage;
import org.skinlab.ar.MarkerDetection;
import org.skinlab.ar.MarkerDictionary;
import org.skinlab.ar.MarkerPattern;
import org.skinlab.ar.TrackerConfig;

/**
 * The printable marker decodes with our tracker, to its id, and has its physical size: the PDF
 * rendered at 200 dpi (0.127 mm per pixel; the tracker's corners within 0.2 px, so the square's
 * width within 0.1 mm; 0.3 mm allowed), the PNG at its own resolution metadata (exact by
 * construction: whole pixels per cell and the pixels-per-metre of those).
 */
class MarkerSheetTest {
    private static List<MarkerDetection> detect(BufferedImage image, int id) {
        GrayImage gray = GrayImages.of(image);
        CameraIntrinsics k = CameraIntrinsics.fromHorizontalFov(gray.width(), gray.height(), 60);
        return new FiducialTracker(TrackerConfig.defaults(0.1).withTargetId(id), k).detect(gray);
    }

    private static double widthPixels(MarkerDetection d) {
        return (Math.hypot(d.cornerX(1) - d.cornerX(0), d.cornerY(1) - d.cornerY(0))
                + Math.hypot(d.cornerX(2) - d.cornerX(3), d.cornerY(2) - d.cornerY(3))) / 2;
    }

    @Test
    void thePdfIsA4AndItsMarkerDecodesAtItsSize(@TempDir Path dir) throws Exception {
        Path pdf = dir.resolve("m.pdf");
        MarkerSheet.writePdf(MarkerPattern.of(MarkerDictionary.DEFAULT, 17), 100, pdf);
        try (PDDocument doc = Loader.loadPDF(pdf.toFile())) {
            assertEquals(1, doc.getNumberOfPages());
            PDRectangle box = doc.getPage(0).getMediaBox();
            assertEquals(PDRectangle.A4.getWidth(), box.getWidth(), 1e-3);
            assertEquals(PDRectangle.A4.getHeight(), box.getHeight(), 1e-3);
            BufferedImage page = new PDFRenderer(doc).renderImageWithDPI(0, 200, ImageType.GRAY);
            List<MarkerDetection> found = detect(page, 17);
            assertEquals(1, found.size());
            assertEquals(100, widthPixels(found.get(0)) / (200 / 25.4), 0.3, "black square width in mm");
        }
    }

    @Test
    void thePngDecodesAndItsMetadataGivesTheSize(@TempDir Path dir) throws Exception {
        Path png = dir.resolve("m.png");
        MarkerPattern pattern = MarkerPattern.of(MarkerDictionary.APRILTAG_36H11, 3);
        MarkerSheet.writePng(pattern, 80, 300, png);
        BufferedImage image = ImageIO.read(png.toFile());
        int cell = MarkerSheet.cellPixels(pattern, 80, 300);
        assertEquals((pattern.cells() + 2 * MarkerSheet.QUIET_CELLS) * cell, image.getWidth());
        double pixelsPerMetre;
        try (ImageInputStream in = ImageIO.createImageInputStream(png.toFile())) {
            ImageReader reader = ImageIO.getImageReadersByFormatName("png").next();
            reader.setInput(in);
            IIOMetadataNode root = (IIOMetadataNode) reader.getImageMetadata(0).getAsTree("javax_imageio_png_1.0");
            IIOMetadataNode phys = (IIOMetadataNode) root.getElementsByTagName("pHYs").item(0);
            assertEquals("meter", phys.getAttribute("unitSpecifier"));
            pixelsPerMetre = Double.parseDouble(phys.getAttribute("pixelsPerUnitXAxis"));
        }
        assertEquals(80, pattern.cells() * cell / pixelsPerMetre * 1000, 0.05, "the square at the metadata's resolution");
        GrayImage gray = GrayImages.of(image);
        List<MarkerDetection> found = new FiducialTracker(
                TrackerConfig.of(MarkerDictionary.APRILTAG_36H11, 0.08).withTargetId(3),
                CameraIntrinsics.fromHorizontalFov(gray.width(), gray.height(), 60)).detect(gray);
        assertEquals(1, found.size());
        assertEquals(pattern.cells() * cell, widthPixels(found.get(0)), 1.0);
    }

    @Test
    void sizesThatDoNotFitAreRefused(@TempDir Path dir) {
        MarkerPattern p = MarkerPattern.of(MarkerDictionary.DEFAULT, 0);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> MarkerSheet.writePdf(p, 250, dir.resolve("x.pdf")));
        assertEquals(true, e.getMessage().contains("250"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> MarkerSheet.writePng(p, 100, 10, dir.resolve("x.png")));
    }
}
