package org.skinlab.desktop.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.MarkerDetection;
import org.skinlab.ar.synthetic.PlacedMarker;
import org.skinlab.desktop.ar.DemoVideo;
import org.skinlab.desktop.ar.GrayImages;
import org.skinlab.desktop.ar.IntrinsicsFile;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code skinlab ar-demo OUT}: the synthetic video of {@link DemoVideo} as numbered PNG frames, with
 * {@code intrinsics.json} (the camera) and {@code poses.json} (each frame's true marker pose and
 * corners, in {@code skinlab track}'s format without the time, and the marker's size), so {@code skinlab ar --images OUT --intrinsics OUT/intrinsics.json}
 * runs on any machine.
 */
@Command(name = "ar-demo", mixinStandardHelpOptions = true,
        description = "Write a synthetic camera video of the printed marker (PNG frames, intrinsics.json, poses.json).")
public final class ArDemoCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "OUT", description = "folder to write (created)")
    Path out;

    @Option(names = "--frames", paramLabel = "N", description = "frames (default: ${DEFAULT-VALUE}, 4 s at 30 fps)")
    int frames = 120;

    @Option(names = "--size", paramLabel = "WxH", description = "image size (default: ${DEFAULT-VALUE})")
    String size = "640x480";

    @Option(names = "--fov", paramLabel = "DEG", description = "horizontal field of view (default: ${DEFAULT-VALUE})")
    double fov = 60;

    @Override
    public Integer call() throws IOException {
        CameraIntrinsics k;
        DemoVideo video;
        try {
            String[] wh = size.toLowerCase(Locale.ROOT).split("x");
            if (wh.length != 2) {
                throw new IllegalArgumentException("--size must be WIDTHxHEIGHT, e.g. 640x480: " + size);
            }
            k = CameraIntrinsics.fromHorizontalFov(Integer.parseInt(wh[0].trim()), Integer.parseInt(wh[1].trim()), fov);
            video = new DemoVideo(k, frames);
        } catch (IllegalArgumentException e) {
            throw new CommandFailure(ExitCodes.USAGE, e.getMessage(), e);
        }
        Files.createDirectories(out);
        IntrinsicsFile.write(k, out.resolve("intrinsics.json"));
        ObjectMapper mapper = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);
        ObjectNode root = mapper.createObjectNode();
        root.put("markerSizeMetres", DemoVideo.MARKER_METRES);
        ArrayNode list = root.putArray("frames");
        for (int i = 0; i < frames; i++) {
            String name = String.format(Locale.ROOT, "frame-%04d.png", i);
            GrayImages.writePng(video.frame(i), out.resolve(name));
            PlacedMarker m = video.marker(i);
            TrackJson.addFrame(list, name, Double.NaN, List.of(new MarkerDetection(m.pattern().id(), video.corners(i),
                    m.rotation(), m.translation(), 0)));
        }
        Files.writeString(out.resolve("poses.json"), mapper.writeValueAsString(root) + "\n");
        spec.commandLine().getOut().println("wrote " + frames + " frames, intrinsics.json and poses.json to " + out);
        spec.commandLine().getOut().flush();
        return ExitCodes.OK;
    }
}
