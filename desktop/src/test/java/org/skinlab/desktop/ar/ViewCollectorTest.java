package org.skinlab.desktop.ar;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.skinlab.ar.GrayImage;

/** The webcam's view picker keeps a frame only when the target is in it and the view is new. */
class ViewCollectorTest {
    @Test
    void keepsNewViewsOnly() {
        List<GrayImage> photos = CalibrationPhotos.images();
        ViewCollector c = new ViewCollector(new TargetDetector(CalibrationPhotos.TARGET));
        assertTrue(c.offer(photos.get(0)).kept());
        ViewCollector.Offer again = c.offer(photos.get(0));
        assertFalse(again.kept());
        assertTrue(again.reason().contains("same view"), again.reason());
        ViewCollector.Offer none = c.offer(CalibrationPhotos.withoutTarget());
        assertFalse(none.kept());
        assertTrue(none.reason().startsWith("no board: "), none.reason());
        // Every other photo differs from the first (moved to a corner or an edge, closer, or tilted).
        for (int i = 1; i < photos.size(); i++) {
            assertTrue(c.offer(photos.get(i)).kept(), "view " + i);
        }
        assertEquals(photos.size(), c.views().size());
    }
}
