package org.skinlab.desktop.ar;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Path;

import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageInputStream;

import boofcv.struct.geo.PointIndex2D_F64;

import org.apache.pdfbox.Loader;
import org.apache.pdfbox.pdmodel.PDDocument;
import org.apache.pdfbox.pdmodel.common.PDRectangle;
import org.apache.pdfbox.rendering.ImageType;
import org.apache.pdfbox.rendering.PDFRenderer;
import org.apache.pdfbox.text.PDFTextStripper;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.internal.ar.CalibrationTarget;

/**
 * The printable target is found by the calibration's own detector and has its physical size: the
 * PDF rendered at 100 dpi (0.254 mm per pixel; BoofCV's corners within 0.1 px, and the pitch is
 * averaged over every neighbouring pair), the PNG at its metadata's resolution; the page names
 * the options for {@code skinlab calibrate}.
 */
class CalibrationSheetTest {
    /** The mean distance between neighbouring points of a row, in pixels (a chessboard's square pitch). */
    private static double pitchPixels(TargetDetector.View v, int pointsPerRow) {
        double sum = 0;
        int n = 0;
        for (PointIndex2D_F64 p : v.points().points) {
            if ((p.index + 1) % pointsPerRow != 0) {
                PointIndex2D_F64 q = v.points().points.get(p.index + 1);
                sum += p.p.distance(q.p);
                n++;
            }
        }
        return sum / n;
    }

    @Test
    void thePdfIsA4AndItsChessboardIsFoundAtItsSize(@TempDir Path dir) throws Exception {
        CalibrationTarget target = CalibrationTarget.chessboard(7, 10, 0.020);
        Path pdf = dir.resolve("t.pdf");
        CalibrationSheet.writePdf(target, pdf);
        try (PDDocument doc = Loader.loadPDF(pdf.toFile())) {
            assertEquals(1, doc.getNumberOfPages());
            PDRectangle box = doc.getPage(0).getMediaBox();
            assertEquals(PDRectangle.A4.getHeight(), box.getWidth(), 1e-3, "landscape for a wide target");
            assertEquals(PDRectangle.A4.getWidth(), box.getHeight(), 1e-3);
            String text = new PDFTextStripper().getText(doc);
            assertTrue(text.contains("--target chessboard --rows 7 --cols 10 --square-mm 20"), text);
            BufferedImage page = new PDFRenderer(doc).renderImageWithDPI(0, 100, ImageType.GRAY);
            TargetDetector.View v = new TargetDetector(target).detect(GrayImages.of(page));
            assertTrue(v.found(), () -> v.problem());
            assertEquals(20, pitchPixels(v, 9) / (100 / 25.4), 0.1, "square in mm");
        }
    }

    @Test
    void theGridPrintsAndIsFound(@TempDir Path dir) throws Exception {
        CalibrationTarget target = CalibrationTarget.grid(5, 7, 0.020, 0.010);
        Path pdf = dir.resolve("g.pdf");
        CalibrationSheet.writePdf(target, pdf);
        try (PDDocument doc = Loader.loadPDF(pdf.toFile())) {
            BufferedImage page = new PDFRenderer(doc).renderImageWithDPI(0, 100, ImageType.GRAY);
            TargetDetector.View v = new TargetDetector(target).detect(GrayImages.of(page));
            assertTrue(v.found(), () -> v.problem());
            assertEquals(target.points(), v.points().size());
        }
    }

    @Test
    void thePngIsFoundAndItsMetadataGivesTheSize(@TempDir Path dir) throws Exception {
        CalibrationTarget target = CalibrationTarget.chessboard(4, 6, 0.025);
        Path png = dir.resolve("t.png");
        CalibrationSheet.writePng(target, 100, png);
        double ppm;
        try (ImageInputStream in = ImageIO.createImageInputStream(png.toFile())) {
            ImageReader reader = ImageIO.getImageReadersByFormatName("png").next();
            reader.setInput(in);
            IIOMetadataNode root = (IIOMetadataNode) reader.getImageMetadata(0).getAsTree("javax_imageio_png_1.0");
            IIOMetadataNode phys = (IIOMetadataNode) root.getElementsByTagName("pHYs").item(0);
            ppm = Double.parseDouble(phys.getAttribute("pixelsPerUnitXAxis"));
        }
        BufferedImage image = ImageIO.read(png.toFile());
        TargetDetector.View v = new TargetDetector(target).detect(GrayImages.of(image));
        assertTrue(v.found(), () -> v.problem());
        assertEquals(25, pitchPixels(v, 5) / ppm * 1000, 0.1, "square in mm at the metadata's resolution");
    }
}
