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
    /** ArUco MIP_36h12, the {@link #DEFAULT}: 250 codes of 6x6 bits, minimum distance 12. */
    ARUCO_MIP_36H12(HammingDictionary.ARUCO_MIP_36h12),
    /** ArUco MIP_25h7: 100 codes of 5x5 bits, minimum distance 7. */
    ARUCO_MIP_25H7(HammingDictionary.ARUCO_MIP_25h7),
    /** ArUco MIP_16h3: 250 codes of 4x4 bits, minimum distance 3. */
    ARUCO_MIP_16H3(HammingDictionary.ARUCO_MIP_16h3),
    /** The original ArUco dictionary: 1024 codes of 5x5 bits, minimum distance 3. */
    ARUCO_ORIGINAL(HammingDictionary.ARUCO_ORIGINAL),
    /** OpenCV's DICT_4X4_1000: 1000 codes of 4x4 bits; BoofCV records minimum distance 0, so no bit is corrected. */
    ARUCO_4X4_1000(HammingDictionary.ARUCO_OCV_4x4_1000),
    /** OpenCV's DICT_5X5_1000: 1000 codes of 5x5 bits, minimum distance 5. */
    ARUCO_5X5_1000(HammingDictionary.ARUCO_OCV_5x5_1000),
    /** OpenCV's DICT_6X6_1000: 1000 codes of 6x6 bits, minimum distance 9. */
    ARUCO_6X6_1000(HammingDictionary.ARUCO_OCV_6x6_1000),
    /** OpenCV's DICT_7X7_1000: 1000 codes of 7x7 bits, minimum distance 14. */
    ARUCO_7X7_1000(HammingDictionary.ARUCO_OCV_7x7_1000),
    /** AprilTag 16h5: 30 codes of 4x4 bits, minimum distance 5. */
    APRILTAG_16H5(HammingDictionary.APRILTAG_16h5),
    /** AprilTag 25h7: 242 codes of 5x5 bits, minimum distance 7. */
    APRILTAG_25H7(HammingDictionary.APRILTAG_25h7),
    /** AprilTag 25h9: 35 codes of 5x5 bits, minimum distance 9. */
    APRILTAG_25H9(HammingDictionary.APRILTAG_25h9),
    /** AprilTag 36h10: 2320 codes of 6x6 bits, minimum distance 10. */
    APRILTAG_36H10(HammingDictionary.APRILTAG_36h10),
    /** AprilTag 36h11: 587 codes of 6x6 bits, minimum distance 11. */
    APRILTAG_36H11(HammingDictionary.APRILTAG_36h11);

    /** What {@code skinlab} and the apps use unless told otherwise. */
    public static final MarkerDictionary DEFAULT = ARUCO_MIP_36H12;

    private final HammingDictionary boofcv;
    /** BoofCV's description, parsed from its resource on first use (read-only here: {@link #config} copies). */
    private volatile ConfigHammingMarker parsed;

    MarkerDictionary(HammingDictionary boofcv) {
        this.boofcv = boofcv;
    }

    /**
     * The dictionary of a name as users write it ("aruco_mip_36h12", "APRILTAG_36h11"; case ignored).
     *
     * @param name this enum's constant name or BoofCV's {@code HammingDictionary} name (e.g.
     *             {@code aruco_ocv_4x4_1000}), in any case, '-' accepted for '_', surrounding blanks ignored
     * @return the dictionary of that name
     * @throws IllegalArgumentException when no dictionary has that name (the message lists {@link #names()})
     */
    public static MarkerDictionary byName(String name) {
        String key = name.trim().toUpperCase(Locale.ROOT).replace('-', '_');
        for (MarkerDictionary d : values()) {
            if (d.name().equals(key) || d.boofcv.name().toUpperCase(Locale.ROOT).equals(key)) {
                return d;
            }
        }
        throw new IllegalArgumentException("unknown marker dictionary '" + name + "'; known: " + names());
    }

    /**
     * The names {@link #byName} accepts, comma-separated, lower case.
     *
     * @return every dictionary's {@link #key()}, in declaration order, joined by ", "
     */
    public static String names() {
        return Arrays.stream(values()).map(MarkerDictionary::key).collect(Collectors.joining(", "));
    }

    /**
     * The name in lower case, as the command line and files write it.
     *
     * @return the constant's name in lower case, e.g. "aruco_mip_36h12"; {@link #byName} accepts it
     */
    public String key() {
        return name().toLowerCase(Locale.ROOT);
    }

    /**
     * Bits per side of the code grid (6 for 36h12).
     *
     * @return the grid's width in cells, without the black border (4 to 7)
     */
    public int gridWidth() {
        return parsed().gridWidth;
    }

    /**
     * How many codes (ids 0 .. codeCount - 1).
     *
     * @return the number of codes, e.g. 250 for 36h12
     */
    public int codeCount() {
        return parsed().encoding.size();
    }

    /**
     * The smallest Hamming distance between two codes of the dictionary.
     *
     * @return the distance in bits as BoofCV records it (12 for 36h12); {@code (minimumHamming - 1) / 2} wrong bits
     *         can be corrected
     */
    public int minimumHamming() {
        return parsed().minimumHamming;
    }

    /**
     * BoofCV's name of the dictionary (for its own detector with its default settings, as benchmarks run it).
     *
     * @return BoofCV's constant for this dictionary
     */
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
