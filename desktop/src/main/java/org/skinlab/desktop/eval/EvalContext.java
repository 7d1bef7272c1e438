package org.skinlab.desktop.eval;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;

import com.fasterxml.jackson.databind.JsonNode;

import me.tongfei.progressbar.ProgressBar;

import org.skinlab.desktop.bench.BenchCorpus;

/**
 * What a section of {@code skinlab eval} measures with: the mode (quick or full), the repository's
 * assets, the shared fixtures when present, where to say what it skips, and the progress bar. The
 * bar counts tenths of a second of the sections' estimates; a section reports the fraction of its
 * own work done, so the library's estimate of the time left follows the estimates' weights.
 */
final class EvalContext {
    static final String SHARED_CTS = "../shared/cts/collada-cts-1.4.1-subset.zip";

    private final boolean quick;
    private final Path root;
    private final Path corpus;
    private final Path cts;
    private final PrintWriter log;
    private final ViewerProcess viewer;
    /** The real AR video the "ar-frame" section plays (null: the synthetic one), its camera and marker dictionary. */
    private Path arVideo;
    private Path arIntrinsics;
    private String arDictionary;
    private ProgressBar bar;
    private JsonNode measured;
    private JsonNode earlier;
    private long sectionStart;
    private long sectionLength;

    EvalContext(boolean quick, Path root, PrintWriter log, ViewerProcess viewer) {
        this.quick = quick;
        this.root = root;
        this.corpus = BenchCorpus.sharedCorpus(root, Path.of(""));
        Path zip = root.resolve(SHARED_CTS).normalize();
        this.cts = Files.isRegularFile(zip) ? zip : null;
        this.log = log;
        this.viewer = viewer;
    }

    boolean quick() {
        return quick;
    }

    /** The repository root (holds assets/). */
    Path root() {
        return root;
    }

    /** The shared corpus folder, or null when absent. */
    Path corpus() {
        return corpus;
    }

    /** Where the shared corpus was looked for (for the line saying it is absent). */
    Path corpusPlace() {
        return root.resolve(BenchCorpus.SHARED_CORPUS).normalize();
    }

    /** The conformance suite's zip, or null when absent. */
    Path cts() {
        return cts;
    }

    Path ctsPlace() {
        return root.resolve(SHARED_CTS).normalize();
    }

    /** Plays {@code video} (seen through {@code intrinsics}, or null; markers of {@code dictionary}) in "ar-frame". */
    void useArVideo(Path video, Path intrinsics, String dictionary) {
        this.arVideo = video;
        this.arIntrinsics = intrinsics;
        this.arDictionary = dictionary;
    }

    /** The real AR video, or null for the synthetic demo video. */
    Path arVideo() {
        return arVideo;
    }

    /** The real AR video's camera file, or null (a 60 degree guess). */
    Path arIntrinsics() {
        return arIntrinsics;
    }

    /** The real AR video's marker dictionary. */
    String arDictionary() {
        return arDictionary;
    }

    /** Draws the pictures by {@code skinlab view} in a child JVM. */
    ViewerProcess viewer() {
        return viewer;
    }

    /** Says something on stderr (above the bar). */
    void say(String message) {
        log.println("eval: " + message);
        log.flush();
    }

    /** The results of the sections measured so far, by key (what a later section may draw on). */
    void useResults(JsonNode bySection) {
        this.measured = bySection;
    }

    /** The results of section {@code key} measured earlier in this run, or null when it was not run. */
    JsonNode measured(String key) {
        return measured == null || !measured.has(key) ? null : measured.get(key);
    }

    /** The sections of the results.json this run replaces (null when there was none, or it was not readable). */
    void useEarlier(JsonNode bySection) {
        this.earlier = bySection;
    }

    /**
     * Section {@code key}'s results in the results.json this run replaces, or null: what a section
     * that measures nothing itself keeps (the phones added to the report).
     */
    JsonNode earlier(String key) {
        return earlier == null || !earlier.has(key) ? null : earlier.get(key);
    }

    void useBar(ProgressBar bar) {
        this.bar = bar;
    }

    /** Starts a section that spans {@code length} units of the bar. */
    void startSection(String name, long length) {
        sectionStart = bar == null ? 0 : bar.getCurrent();
        sectionLength = length;
        if (bar != null) {
            bar.setExtraMessage(name);
        }
    }

    /** The fraction (0 to 1) of the current section done. */
    void progress(double fraction) {
        if (bar != null) {
            bar.stepTo(sectionStart + Math.round(Math.min(1, Math.max(0, fraction)) * sectionLength));
        }
    }
}
