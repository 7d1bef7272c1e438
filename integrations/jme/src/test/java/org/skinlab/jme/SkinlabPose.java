package org.skinlab.jme;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.StringJoiner;
import java.util.concurrent.TimeUnit;

import com.jme3.plugins.json.Json;
import com.jme3.plugins.json.JsonArray;
import com.jme3.plugins.json.JsonObject;

/**
 * The reference: {@code skinlab pose FILE --time T1,T2,T3 --method M --json OUT}, skinlab's own
 * CLI (desktop/build/install/skinlab/bin/skinlab, made by {@code gradle -q :desktop:installDist}),
 * run as a separate process: world positions per POSITION of each placed mesh, per time.
 */
final class SkinlabPose {
    final String clip;
    final double[] times;
    /** Per mesh, per time, 3 floats per position. */
    final List<float[][]> meshes;

    private SkinlabPose(String clip, double[] times, List<float[][]> meshes) {
        this.clip = clip;
        this.times = times;
        this.meshes = meshes;
    }

    static Path cli(Path repository) {
        Path cli = repository.resolve("desktop/build/install/skinlab/bin/skinlab");
        if (!Files.isExecutable(cli)) {
            throw new IllegalStateException(cli + " is missing: run `gradle -q :desktop:installDist` at the repository's root first");
        }
        return cli;
    }

    static SkinlabPose run(Path cli, Path file, String method, double[] times) throws IOException, InterruptedException {
        Path json = Files.createTempFile("skinlab-pose", ".json");
        try {
            StringJoiner t = new StringJoiner(",");
            for (double time : times) {
                t.add(Float.toString((float) time));
            }
            Path log = Files.createTempFile("skinlab-pose", ".log");
            Process p = new ProcessBuilder(cli.toString(), "pose", file.toString(), "--time", t.toString(),
                    "--method", method, "--json", json.toString()).redirectErrorStream(true).redirectOutput(log.toFile())
                    .start();
            if (!p.waitFor(300, TimeUnit.SECONDS) || p.exitValue() != 0) {
                p.destroyForcibly();
                throw new IllegalStateException("skinlab pose " + file + " failed: " + Files.readString(log));
            }
            Files.delete(log);
            try (InputStream in = Files.newInputStream(json)) {
                return parse(Json.create().parse(in));
            }
        } finally {
            Files.deleteIfExists(json);
        }
    }

    private static SkinlabPose parse(JsonObject root) {
        String clip = root.get("clip") == null ? null : root.get("clip").getAsString();
        JsonArray t = root.getAsJsonArray("times");
        double[] times = new double[t.size()];
        for (int i = 0; i < times.length; i++) {
            times[i] = t.get(i).getAsFloat();
        }
        List<float[][]> meshes = new ArrayList<>();
        JsonArray ms = root.getAsJsonArray("meshes");
        for (int m = 0; m < ms.size(); m++) {
            JsonArray poses = ms.get(m).getAsJsonObject().getAsJsonArray("poses");
            float[][] perTime = new float[poses.size()][];
            for (int i = 0; i < perTime.length; i++) {
                JsonArray a = poses.get(i).getAsJsonArray();
                perTime[i] = new float[a.size()];
                for (int k = 0; k < perTime[i].length; k++) {
                    perTime[i][k] = a.get(k).getAsFloat();
                }
            }
            meshes.add(perTime);
        }
        return new SkinlabPose(clip, times, meshes);
    }
}
