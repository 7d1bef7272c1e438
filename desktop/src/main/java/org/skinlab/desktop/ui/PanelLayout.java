package org.skinlab.desktop.ui;

/**
 * Where the panels go and what they leave to the scene, in window coordinates (ImGui's: origin
 * at the top left). The toolbar docks at the left edge and the numbers at the right with the mixer
 * panel under them, each column as wide as its widest panel and never reached by the scene, and the
 * status line sits under the toolbar, wrapped to its width. A
 * panel whose column would leave the scene less than {@value #MIN_SCENE_SHARE} of the window's
 * width collapses to its title bar (a click opens it again, over the scene); collapsed title bars
 * form a band along the top, and the scene starts below it. The mixer's title goes left of the
 * numbers' in the band, or where the toolbar leaves no room there, in a second row under it. The
 * views' labels get a row of their own under the scene. Panel sizes are those measured when each
 * was last drawn open, so a collapsed panel keeps the size it would open to; title bars are
 * measured when drawn collapsed.
 */
final class PanelLayout {
    /** Space between the window's edges, the panels and the scene. */
    static final float MARGIN = 8f;
    /** The least share of the window's width a column may leave the scene. */
    static final float MIN_SCENE_SHARE = 0.4f;

    private float toolbarWidth;
    private float numbersWidth;
    private float numbersHeight;
    private float mixerWidth;
    private float toolbarTitleWidth;
    private float numbersTitleWidth;
    private float mixerTitleWidth;
    private boolean mixerSecondRow;
    private float statusHeight;
    private boolean toolbarOpen = true;
    private boolean numbersOpen = true;
    private boolean toolbarChanged;
    private boolean numbersChanged;
    private float toolbarMaxHeight;
    private float statusWidth;
    private float sceneLeft;
    private float sceneTop;
    private float sceneRight;
    private float sceneBottom;
    private float width;
    private float height;
    private float titleHeight;

    /** Decides the layout of a window {@code width x height} whose title bars are {@code titleHeight} high. */
    void decide(float width, float height, float titleHeight) {
        boolean toolbar = width - (toolbarWidth + 2 * MARGIN) >= MIN_SCENE_SHARE * width;
        float left = toolbar ? toolbarWidth + 2 * MARGIN : 0f;
        float column = Math.max(numbersWidth, mixerWidth);
        boolean numbers = width - left - (column + 2 * MARGIN) >= MIN_SCENE_SHARE * width;
        toolbarChanged = toolbar != toolbarOpen;
        numbersChanged = numbers != numbersOpen;
        toolbarOpen = toolbar;
        numbersOpen = numbers;
        float status = statusHeight > 0 ? statusHeight + MARGIN : 0f;
        sceneLeft = left;
        sceneRight = numbers ? width - (column + 2 * MARGIN) : width;
        float free = toolbar ? toolbarWidth + 2 * MARGIN : toolbarTitleWidth + 2 * MARGIN;
        mixerSecondRow = !numbers && width - numbersTitleWidth - 2 * MARGIN - mixerTitleWidth < free;
        sceneTop = toolbar && numbers ? 0f : titleHeight + 2 * MARGIN + (mixerSecondRow ? titleHeight + MARGIN : 0f);
        // Under a collapsed toolbar the status line spans the bottom, below the scene.
        float below = toolbar ? 0f : status + MARGIN;
        sceneBottom = height - below - labelRow(titleHeight);
        toolbarMaxHeight = Math.max(titleHeight, height - 2 * MARGIN - status);
        statusWidth = toolbar ? Math.max(toolbarWidth, 1f) : width - 2 * MARGIN;
        this.width = width;
        this.height = height;
        this.titleHeight = titleHeight;
    }

    /** The height of the row under the scene that holds the views' labels (one line of text). */
    static float labelRow(float lineHeight) {
        return lineHeight + MARGIN;
    }

    /** Records the toolbar's width as drawn open. */
    void toolbarMeasured(float width) {
        toolbarWidth = width;
    }

    /** Records the numbers panel's size as drawn open. */
    void numbersMeasured(float width, float height) {
        numbersWidth = width;
        numbersHeight = height;
    }

    /** Records the mixer panel's width as drawn open. */
    void mixerMeasured(float width) {
        mixerWidth = width;
    }

    /** Records the toolbar's title bar width as drawn collapsed. */
    void toolbarTitleMeasured(float width) {
        toolbarTitleWidth = width;
    }

    /** Records the numbers panel's title bar width as drawn collapsed. */
    void numbersTitleMeasured(float width) {
        numbersTitleWidth = width;
    }

    /** Records the mixer panel's title bar width as drawn collapsed. */
    void mixerTitleMeasured(float width) {
        mixerTitleWidth = width;
    }

    /** Records the status line's height (0 when it showed nothing). */
    void statusMeasured(float height) {
        statusHeight = height;
    }

    boolean toolbarOpen() {
        return toolbarOpen;
    }

    /** Whether the toolbar opened or collapsed at the last decision (then it is put so, once). */
    boolean toolbarChanged() {
        return toolbarChanged;
    }

    boolean numbersOpen() {
        return numbersOpen;
    }

    boolean numbersChanged() {
        return numbersChanged;
    }

    /** The toolbar's greatest height: it scrolls beyond, and the status line keeps its place below. */
    float toolbarMaxHeight() {
        return toolbarMaxHeight;
    }

    /**
     * Where the mixer panel's top edge goes: under the numbers in an open column, else in the band
     * of title bars along the top (its first row or its second).
     */
    float mixerTop() {
        return numbersOpen ? numbersHeight + 2 * MARGIN : mixerSecondRow ? titleHeight + 2 * MARGIN : MARGIN;
    }

    /**
     * Where the mixer panel's right edge goes: the column's in an open column, else left of the
     * numbers' title bar, or under it.
     */
    float mixerRight() {
        return numbersOpen || mixerSecondRow ? width - MARGIN : width - numbersTitleWidth - 2 * MARGIN;
    }

    /** The mixer panel's greatest height: it scrolls beyond. */
    float mixerMaxHeight() {
        return Math.max(titleHeight, height - mixerTop() - MARGIN);
    }

    /** The status line's width at most. */
    float statusWidth() {
        return statusWidth;
    }

    float sceneLeft() {
        return sceneLeft;
    }

    float sceneTop() {
        return sceneTop;
    }

    float sceneRight() {
        return sceneRight;
    }

    float sceneBottom() {
        return sceneBottom;
    }
}
