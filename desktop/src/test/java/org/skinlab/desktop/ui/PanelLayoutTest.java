package org.skinlab.desktop.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The panels' columns and what they leave to the scene, with the panel sizes ImGui measures at scale 1. */
class PanelLayoutTest {
    private static final float TOOLBAR = 297f;
    private static final float NUMBERS = 316f;
    private static final float NUMBERS_HEIGHT = 330f;
    private static final float TITLE = 19f;
    private static final float STATUS = 44f;
    private static final float MIXER = 340f;
    /** Title bars drawn collapsed. */
    private static final float TOOLBAR_TITLE = 200f;
    private static final float NUMBERS_TITLE = 170f;
    private static final float MIXER_TITLE = 115f;

    private static PanelLayout measured() {
        PanelLayout layout = new PanelLayout();
        layout.toolbarMeasured(TOOLBAR);
        layout.numbersMeasured(NUMBERS, NUMBERS_HEIGHT);
        layout.statusMeasured(STATUS);
        return layout;
    }

    @Test
    void aWideWindowDocksBothPanelsAndTheSceneLiesBetweenThem() {
        PanelLayout layout = measured();
        layout.decide(1280, 800, TITLE);
        assertTrue(layout.toolbarOpen() && layout.numbersOpen());
        assertEquals(TOOLBAR + 2 * PanelLayout.MARGIN, layout.sceneLeft());
        assertEquals(1280 - NUMBERS - 2 * PanelLayout.MARGIN, layout.sceneRight());
        assertEquals(0f, layout.sceneTop());
        // Under the scene, the row of the views' labels.
        assertEquals(800 - TITLE - PanelLayout.MARGIN, layout.sceneBottom());
        // The status line keeps its place under the toolbar.
        assertEquals(800 - 2 * PanelLayout.MARGIN - STATUS - PanelLayout.MARGIN, layout.toolbarMaxHeight());
        assertEquals(TOOLBAR, layout.statusWidth());
    }

    @Test
    void theNumbersCollapseWhenTheirColumnWouldSqueezeTheScene() {
        PanelLayout layout = measured();
        layout.decide(1280, 800, TITLE);
        layout.decide(640, 480, TITLE);
        assertTrue(layout.toolbarOpen());
        assertFalse(layout.numbersOpen());
        assertTrue(layout.numbersChanged(), "the numbers collapse once, when the layout changes");
        assertEquals(640f, layout.sceneRight());
        // The collapsed title bar is a band along the top: the scene starts below it.
        assertEquals(TITLE + 2 * PanelLayout.MARGIN, layout.sceneTop());
        assertTrue(layout.sceneRight() - layout.sceneLeft() >= PanelLayout.MIN_SCENE_SHARE * 640);
        layout.decide(640, 480, TITLE);
        assertFalse(layout.numbersChanged(), "then the user may open it again");
    }

    @Test
    void aNarrowWindowCollapsesTheToolbarAndPutsTheStatusLineBelowTheScene() {
        PanelLayout layout = measured();
        layout.decide(480, 400, TITLE);
        assertFalse(layout.toolbarOpen());
        assertFalse(layout.numbersOpen());
        assertEquals(0f, layout.sceneLeft());
        assertEquals(480f, layout.sceneRight());
        assertEquals(400 - STATUS - 2 * PanelLayout.MARGIN - (TITLE + PanelLayout.MARGIN), layout.sceneBottom());
        assertEquals(480 - 2 * PanelLayout.MARGIN, layout.statusWidth());
    }

    @Test
    void theMixerLiesUnderTheNumbersInAColumnAsWideAsTheWiderOfThem() {
        PanelLayout layout = measured();
        layout.mixerMeasured(MIXER);
        layout.decide(1280, 800, TITLE);
        assertTrue(layout.numbersOpen());
        assertEquals(1280 - MIXER - 2 * PanelLayout.MARGIN, layout.sceneRight());
        assertEquals(NUMBERS_HEIGHT + 2 * PanelLayout.MARGIN, layout.mixerTop());
        assertEquals(1280 - PanelLayout.MARGIN, layout.mixerRight());
        // It scrolls beyond the window's bottom margin.
        assertEquals(800 - NUMBERS_HEIGHT - 3 * PanelLayout.MARGIN, layout.mixerMaxHeight());
    }

    @Test
    void collapsedTheMixersTitleGoesLeftOfTheNumbersOrInASecondRowUnderThem() {
        PanelLayout layout = measured();
        layout.mixerMeasured(MIXER);
        layout.toolbarTitleMeasured(TOOLBAR_TITLE);
        layout.numbersTitleMeasured(NUMBERS_TITLE);
        layout.mixerTitleMeasured(MIXER_TITLE);
        // Beside the open toolbar there is room for both titles in one row.
        layout.decide(640, 480, TITLE);
        assertTrue(layout.toolbarOpen());
        assertFalse(layout.numbersOpen());
        assertEquals(PanelLayout.MARGIN, layout.mixerTop());
        assertEquals(640 - NUMBERS_TITLE - 2 * PanelLayout.MARGIN, layout.mixerRight());
        assertTrue(layout.mixerRight() - MIXER_TITLE >= TOOLBAR + 2 * PanelLayout.MARGIN);
        assertEquals(TITLE + 2 * PanelLayout.MARGIN, layout.sceneTop());
        // Three titles do not fit in 480: the mixer's goes under the numbers' and the scene below both rows.
        layout.decide(480, 400, TITLE);
        assertFalse(layout.toolbarOpen());
        assertEquals(TITLE + 2 * PanelLayout.MARGIN, layout.mixerTop());
        assertEquals(480 - PanelLayout.MARGIN, layout.mixerRight());
        assertEquals(2 * TITLE + 3 * PanelLayout.MARGIN, layout.sceneTop());
    }
}
