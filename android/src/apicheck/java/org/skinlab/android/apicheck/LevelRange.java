package org.skinlab.android.apicheck;

/**
 * Where a class or member that API 26 lacks first appears, as far as the signatures on Maven
 * Central tell: animal-sniffer's API-26 signature and gummy-bears' API-33 one are the only two
 * public API lists at hand (no per-member database of java.* up to the current API level is), so
 * a level is a range. "Above API 33" also covers what Android's public API never had (java.awt).
 */
enum LevelRange {
    API_27_TO_33(27, "API 27-33"),
    ABOVE_API_33(34, "above API 33");

    /** The lowest level the member can have: a guard {@code SDK_INT >= lowest} or higher covers it. */
    final int lowest;
    final String text;

    LevelRange(int lowest, String text) {
        this.lowest = lowest;
        this.text = text;
    }
}
