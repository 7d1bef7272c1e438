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
import org.skinlab.ar.GrayImage;
import org.skinlab.ar.LensDistortion;
import org.skinlab.ar.MarkerDetection;
import org.skinlab.internal.synthetic.PlacedMarker;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.ar.DemoVideo;
import org.skinlab.desktop.ar.GrayImages;
import org.skinlab.desktop.ar.IntrinsicsFile;
import org.skinlab.desktop.ar.Mp4Writer;
import org.skinlab.desktop.bench.ArFrameInput;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code skinlab ar-demo OUT}: the synthetic video of {@link DemoVideo} as numbered PNG frames, with
 * {@code intrinsics.json} (the camera) and {@code poses.json} (each frame's true marker pose and
 * corners, in {@code skinlab track}'s format without the time, and the marker's size), so {@code skinlab ar --images OUT --intrinsics OUT/intrinsics.json}
 * runs on any machine. With {@code --distortion} the frames are filmed through that lens (and the
 * corners are where it puts them); with {@code --mp4} the frames are also one H.264 video.
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

    @Option(names = "--distortion", paramLabel = "K1,K2,K3,P1,P2",
            description = "film through this lens (Brown-Conrady, as OpenCV's k1, k2, k3, p1, p2; default: none);"
                    + " intrinsics.json then has it")
    String distortion;

    @Option(names = "--mp4", description = "also write the frames as demo.mp4 (H.264 through JCodec's encoder, BT.601,"
            + " 30 fps), for skinlab ar --video and skinlab bench ar-frame --video")
    boolean mp4;

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
            if (distortion != null) {
                k = k.withDistortion(lens(distortion));
            }
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
        if (mp4 && (k.width() % 2 != 0 || k.height() % 2 != 0)) {
            throw new CommandFailure(ExitCodes.USAGE, "--mp4 needs an even width and height (H.264's 4:2:0 chroma): "
                    + size, null);
        }
        try (Mp4Writer writer = mp4 ? new Mp4Writer(out.resolve("demo.mp4"), k.width(), k.height(),
                ArFrameInput.DEMO_FPS) : null) {
            for (int i = 0; i < frames; i++) {
                String name = String.format(Locale.ROOT, "frame-%04d.png", i);
                GrayImage frame = video.frame(i);
                GrayImages.writePng(frame, out.resolve(name));
                if (writer != null) {
                    writer.write(frame);
                }
                PlacedMarker m = video.marker(i);
                TrackJson.addFrame(list, name, Double.NaN, List.of(new MarkerDetection(m.pattern().id(), video.corners(i),
                        m.rotation(), m.translation(), 0)));
            }
        }
        Files.writeString(out.resolve("poses.json"), mapper.writeValueAsString(root) + "\n");
        spec.commandLine().getOut().println("wrote " + frames + " frames, intrinsics.json" + (mp4 ? ", demo.mp4" : "")
                + " and poses.json to " + out);
        spec.commandLine().getOut().flush();
        return ExitCodes.OK;
    }

    /** "k1,k2,k3,p1,p2" as a lens; IllegalArgumentException naming the option otherwise. */
    static LensDistortion lens(String text) {
        String[] parts = text.split(",", -1);
        if (parts.length != 5) {
            throw new IllegalArgumentException("--distortion must be five numbers K1,K2,K3,P1,P2, is " + text);
        }
        double[] v = new double[5];
        for (int i = 0; i < 5; i++) {
            try {
                v[i] = Double.parseDouble(parts[i].trim());
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("--distortion: term " + (i + 1) + " is not a number: " + parts[i]);
            }
        }
        return new LensDistortion(v[0], v[1], v[2], v[3], v[4]);
    }
}
