package org.skinlab.ar;

import java.util.Arrays;
import java.util.Locale;
import java.util.stream.Collectors;

import boofcv.factory.fiducial.ConfigHammingMarker;
import boofcv.factory.fiducial.HammingDictionary;

/**
 * The square-marker dictionaries the tracker reads: ArUco's and AprilTag's codes as BoofCV ships
 * them. Every code is a grid of bits inside a black border one cell wide; dictionaries differ in
 * grid size, number of codes and the minimum Hamming distance between two codes (in any of the
 * four rotations), which bounds how many wrong bits can be corrected without mistaking one code for
 * another: {@code (minimumHamming - 1) / 2}.
 *
 * <p>The default, ArUco MIP_36h12, has 250 codes of 6x6 bits at distance 12: up to 5 wrong bits
 * are corrected unambiguously.
 */
public enum MarkerDictionary {
    ARUCO_MIP_36H12(HammingDictionary.ARUCO_MIP_36h12),
    ARUCO_MIP_25H7(HammingDictionary.ARUCO_MIP_25h7),
    ARUCO_MIP_16H3(HammingDictionary.ARUCO_MIP_16h3),
    ARUCO_ORIGINAL(HammingDictionary.ARUCO_ORIGINAL),
    ARUCO_4X4_1000(HammingDictionary.ARUCO_OCV_4x4_1000),
    ARUCO_5X5_1000(HammingDictionary.ARUCO_OCV_5x5_1000),
    ARUCO_6X6_1000(HammingDictionary.ARUCO_OCV_6x6_1000),
    ARUCO_7X7_1000(HammingDictionary.ARUCO_OCV_7x7_1000),
    APRILTAG_16H5(HammingDictionary.APRILTAG_16h5),
    APRILTAG_25H7(HammingDictionary.APRILTAG_25h7),
    APRILTAG_25H9(HammingDictionary.APRILTAG_25h9),
    APRILTAG_36H10(HammingDictionary.APRILTAG_36h10),
    APRILTAG_36H11(HammingDictionary.APRILTAG_36h11);

    /** What {@code skinlab} and the apps use unless told otherwise. */
    public static final MarkerDictionary DEFAULT = ARUCO_MIP_36H12;

    private final HammingDictionary boofcv;
    /** BoofCV's description, parsed from its resource on first use (read-only here: {@link #config} copies). */
    private volatile ConfigHammingMarker parsed;

    MarkerDictionary(HammingDictionary boofcv) {
        this.boofcv = boofcv;
    }

    /** The dictionary of a name as users write it ("aruco_mip_36h12", "APRILTAG_36h11"; case ignored). */
    public static MarkerDictionary byName(String name) {
        String key = name.trim().toUpperCase(Locale.ROOT).replace('-', '_');
        for (MarkerDictionary d : values()) {
            if (d.name().equals(key) || d.boofcv.name().toUpperCase(Locale.ROOT).equals(key)) {
                return d;
            }
        }
        throw new IllegalArgumentException("unknown marker dictionary '" + name + "'; known: " + names());
    }

    /** The names {@link #byName} accepts, comma-separated, lower case. */
    public static String names() {
        return Arrays.stream(values()).map(MarkerDictionary::key).collect(Collectors.joining(", "));
    }

    /** The name in lower case, as the command line and files write it. */
    public String key() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** Bits per side of the code grid (6 for 36h12). */
    public int gridWidth() {
        return parsed().gridWidth;
    }

    /** How many codes (ids 0 .. codeCount - 1). */
    public int codeCount() {
        return parsed().encoding.size();
    }

    /** The smallest Hamming distance between two codes of the dictionary. */
    public int minimumHamming() {
        return parsed().minimumHamming;
    }

    /** BoofCV's name of the dictionary (for its own detector with its default settings, as benchmarks run it). */
    public HammingDictionary boofcvDictionary() {
        return boofcv;
    }

    /** A BoofCV description of the dictionary of the caller's own, which it may change. */
    ConfigHammingMarker config() {
        ConfigHammingMarker copy = new ConfigHammingMarker();
        copy.setTo(parsed());
        return copy;
    }

    private ConfigHammingMarker parsed() {
        ConfigHammingMarker p = parsed;
        if (p == null) {
            // Parsing a dictionary's text resource takes milliseconds; racing threads parse the same.
            p = ConfigHammingMarker.loadDictionary(boofcv);
            parsed = p;
        }
        return p;
    }
}
