package org.skinlab.desktop.bench;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.TreeSet;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.GrayImage;
import org.skinlab.ar.LensDistortion;
import org.skinlab.ar.MarkerDictionary;
import org.skinlab.ar.MarkerPattern;

/**
 * OpenCV's ArUco detector as a contender of {@code skinlab bench track}: bench/aruco_opencv.py in
 * a python3 that has cv2, started once and asked for one timed pass over the frames per round, so
 * that its rounds alternate with the Java contenders'. It gets the same frames (written as PGM)
 * and the dictionary's codes as BoofCV prints them, so it reads the same ids.
 */
public final class OpenCvAruco implements AutoCloseable {
    private final Process process;
    private final BufferedReader in;
    private final Writer out;
    private final String version;
    private final ObjectMapper mapper = new ObjectMapper();

    private OpenCvAruco(Process process, BufferedReader in, Writer out, String version) {
        this.process = process;
        this.in = in;
        this.out = out;
        this.version = version;
    }

    /** What did not start, for the report, when {@link #start} returns null. */
    public static final class Failure {
        public String reason = "";
    }

    /**
     * Starts the script on the frames, or returns null with {@code why.reason} set (no script, no
     * python3, no cv2).
     */
    public static OpenCvAruco start(Path script, Path work, List<GrayImage> frames, CameraIntrinsics k,
            MarkerDictionary dictionary, double markerMetres, String clock, Failure why) throws IOException {
        if (!Files.isRegularFile(script)) {
            why.reason = "not run (no " + script + "; run from the repository root or give --opencv-script)";
            return null;
        }
        Path dir = Files.createDirectories(work.resolve("frames"));
        for (int i = 0; i < frames.size(); i++) {
            writePgm(frames.get(i), dir.resolve(String.format(Locale.ROOT, "f%05d.pgm", i)));
        }
        Path codes = work.resolve("codes.txt");
        writeCodes(dictionary, codes);
        LensDistortion d = k.distortion();
        String camera = String.format(Locale.ROOT, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g", k.fx(),
                k.fy(), k.cx(), k.cy(), d.k1(), d.k2(), d.p1(), d.p2(), d.k3());
        Process p;
        try {
            p = new ProcessBuilder("python3", script.toString(), "--frames", dir.toString(), "--codes",
                    codes.toString(), "--camera", camera, "--marker-size", Double.toString(markerMetres), "--clock",
                    clock)
                    .redirectError(ProcessBuilder.Redirect.INHERIT).start();
        } catch (IOException e) {
            why.reason = "not run (no python3: " + e.getMessage() + ")";
            return null;
        }
        BufferedReader in = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8));
        Writer out = new PrintWriter(p.getOutputStream(), false, StandardCharsets.UTF_8);
        String first = in.readLine();
        JsonNode hello = first == null ? null : new ObjectMapper().readTree(first);
        if (hello == null || !hello.has("opencv")) {
            why.reason = hello != null && hello.has("error") ? hello.get("error").asText() : "the script said nothing";
            p.destroy();
            return null;
        }
        if (hello.get("frames").asInt() != frames.size()) {
            p.destroy();
            throw new IOException(script + " read " + hello.get("frames") + " frames of " + frames.size());
        }
        return new OpenCvAruco(p, in, out, hello.get("opencv").asText());
    }

    public String version() {
        return version;
    }

    /** One timed pass over the frames: milliseconds per frame. */
    public double[] round() throws IOException {
        JsonNode list = ask("round");
        double[] ms = new double[list.size()];
        for (int i = 0; i < ms.length; i++) {
            ms[i] = list.get(i).asDouble();
        }
        return ms;
    }

    /** The ids found in each frame, ascending. */
    public List<List<Integer>> ids() throws IOException {
        JsonNode list = ask("ids");
        List<List<Integer>> ids = new ArrayList<>();
        for (JsonNode frame : list) {
            TreeSet<Integer> s = new TreeSet<>();
            frame.forEach(n -> s.add(n.asInt()));
            ids.add(new ArrayList<>(s));
        }
        return ids;
    }

    private JsonNode ask(String command) throws IOException {
        out.write(command + "\n");
        out.flush();
        String line = in.readLine();
        if (line == null) {
            throw new IOException("bench/aruco_opencv.py ended without answering '" + command + "'");
        }
        JsonNode answer = mapper.readTree(line);
        if (answer.isObject() && answer.has("error")) {
            throw new IOException("bench/aruco_opencv.py: " + answer.get("error").asText());
        }
        return answer;
    }

    @Override
    public void close() throws IOException {
        out.close();
        try {
            process.waitFor();
        } catch (InterruptedException e) {
            process.destroy();
            Thread.currentThread().interrupt();
        }
    }

    private static void writePgm(GrayImage g, Path file) throws IOException {
        byte[] header = ("P5\n" + g.width() + " " + g.height() + "\n255\n").getBytes(StandardCharsets.US_ASCII);
        byte[] data = new byte[header.length + g.width() * g.height()];
        System.arraycopy(header, 0, data, 0, header.length);
        for (int y = 0; y < g.height(); y++) {
            System.arraycopy(g.pixels(), y * g.rowStride(), data, header.length + y * g.width(), g.width());
        }
        Files.write(file, data);
    }

    /** The codes as the script reads them: "GRID MAX_CORRECTION", then each id's cells, '1' white, from the top row. */
    private static void writeCodes(MarkerDictionary dictionary, Path file) throws IOException {
        StringBuilder s = new StringBuilder();
        int grid = dictionary.gridWidth();
        s.append(grid).append(' ').append((dictionary.minimumHamming() - 1) / 2).append('\n');
        for (int id = 0; id < dictionary.codeCount(); id++) {
            MarkerPattern p = MarkerPattern.of(dictionary, id);
            for (int row = 1; row <= grid; row++) {
                for (int col = 1; col <= grid; col++) {
                    s.append(p.isBlack(row, col) ? '0' : '1');
                }
            }
            s.append('\n');
        }
        Files.writeString(file, s);
    }
}
