package org.skinlab.desktop.cli;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import boofcv.abst.fiducial.FiducialDetector;
import boofcv.factory.distort.LensDistortionFactory;
import boofcv.factory.fiducial.ConfigFiducialHammingDetector;
import boofcv.factory.fiducial.ConfigHammingMarker;
import boofcv.factory.fiducial.FactoryFiducial;
import boofcv.factory.fiducial.HammingDictionary;
import boofcv.struct.calib.CameraPinholeBrown;
import boofcv.struct.image.GrayU8;
import georegression.struct.se.Se3_F64;

import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.FiducialTracker;
import org.skinlab.ar.GrayImage;
import org.skinlab.ar.TrackerConfig;
import org.skinlab.desktop.ar.DemoVideo;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code skinlab bench track}: milliseconds per 640x480 frame of the synthetic video of
 * {@link DemoVideo} (a 10 cm marker 0.35-0.75 m away, seen from 20-50 degrees, with blur, noise,
 * falloff and some clutter),
 * for BoofCV's squareHamming detector with its default settings (detection and its pose per
 * marker), our {@link FiducialTracker#detect} (whole frame) and {@link FiducialTracker#track} (near
 * the last marker first). Rounds alternate between the three; the report gives each one's median
 * and its ratio to BoofCV's default, measured in the same run.
 */
@Command(name = "track", mixinStandardHelpOptions = true,
        description = "Marker tracking speed on a synthetic 640x480 video: BoofCV's default detector, our detect, our track.")
public final class TrackBenchCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = "--frames", paramLabel = "N", description = "frames of the synthetic video (default: ${DEFAULT-VALUE})")
    int frames = 60;

    @Option(names = "--warmup-seconds", paramLabel = "S", description = "warm-up before timing (default: ${DEFAULT-VALUE})")
    double warmupSeconds = 2.0;

    @Option(names = "--seconds", paramLabel = "S", description = "timed rounds for this long (default: ${DEFAULT-VALUE})")
    double seconds = 6.0;

    @Option(names = "--json", description = "print the result as one line of JSON")
    boolean json;

    @Override
    public Integer call() {
        if (frames < 2 || seconds <= 0 || warmupSeconds < 0) {
            throw new CommandFailure(ExitCodes.USAGE, "need --frames >= 2 and positive times", null);
        }
        CameraIntrinsics k = CameraIntrinsics.fromHorizontalFov(640, 480, 60);
        DemoVideo demo = new DemoVideo(k, frames);
        List<GrayImage> video = new ArrayList<>(frames);
        for (int i = 0; i < frames; i++) {
            video.add(demo.frame(i));
        }
        TrackerConfig config = TrackerConfig.defaults(0.1);
        FiducialTracker ours = new FiducialTracker(config, k);
        FiducialDetector<GrayU8> boof = FactoryFiducial.squareHamming(
                ConfigHammingMarker.loadDictionary(HammingDictionary.ARUCO_MIP_36h12),
                new ConfigFiducialHammingDetector(), GrayU8.class);
        boof.setLensDistortion(LensDistortionFactory.narrow(new CameraPinholeBrown(k.fx(), k.fy(), 0, k.cx() + 0.5,
                k.cy() + 0.5, k.width(), k.height())), k.width(), k.height());
        GrayU8 gray = new GrayU8(k.width(), k.height());
        Se3_F64 pose = new Se3_F64();
        int[] found = new int[3];
        int[] inRegion = new int[1];
        Runnable[] contenders = {
            () -> {
                for (GrayImage g : video) {
                    gray.data = g.pixels();
                    boof.detect(gray);
                    for (int i = 0; i < boof.totalFound(); i++) {
                        boof.getFiducialToCamera(i, pose);
                    }
                    found[0] += boof.totalFound();
                }
            },
            () -> {
                for (GrayImage g : video) {
                    found[1] += ours.detect(g).size();
                }
            },
            () -> {
                ours.reset();
                for (GrayImage g : video) {
                    found[2] += ours.track(g).size();
                    inRegion[0] += ours.lastFoundInRegion() ? 1 : 0;
                }
            }};
        String[] names = {"BoofCV squareHamming, default settings", "skinlab detect (whole frame)",
            "skinlab track (near the last marker first)"};
        long warmEnd = System.nanoTime() + (long) (warmupSeconds * 1e9);
        do {
            for (Runnable c : contenders) {
                c.run();
            }
        } while (System.nanoTime() < warmEnd);
        List<List<Double>> perFrame = new ArrayList<>();
        for (int i = 0; i < contenders.length; i++) {
            perFrame.add(new ArrayList<>());
        }
        Arrays.fill(found, 0);
        inRegion[0] = 0;
        int rounds = 0;
        long end = System.nanoTime() + (long) (seconds * 1e9);
        do {
            for (int i = 0; i < contenders.length; i++) {
                long start = System.nanoTime();
                contenders[i].run();
                perFrame.get(i).add((System.nanoTime() - start) * 1e-6 / video.size());
            }
            rounds++;
        } while (System.nanoTime() < end || rounds < 3);
        double[] median = new double[contenders.length];
        for (int i = 0; i < contenders.length; i++) {
            List<Double> v = perFrame.get(i);
            v.sort(null);
            median[i] = v.get(v.size() / 2);
        }
        PrintWriter out = spec.commandLine().getOut();
        if (json) {
            ObjectMapper mapper = new ObjectMapper();
            ObjectNode o = mapper.createObjectNode();
            o.put("frames", video.size());
            o.put("rounds", rounds);
            o.put("java", Runtime.version().toString());
            o.put("boofcvDefaultMs", median[0]);
            o.put("detectMs", median[1]);
            o.put("trackMs", median[2]);
            o.put("markersPerFrameBoofcv", found[0] / (double) (rounds * video.size()));
            o.put("markersPerFrameDetect", found[1] / (double) (rounds * video.size()));
            o.put("markersPerFrameTrack", found[2] / (double) (rounds * video.size()));
            o.put("trackFoundInRegion", inRegion[0] / (double) (rounds * video.size()));
            out.println(o);
        } else {
            out.printf(Locale.ROOT, "marker tracking, %d synthetic 640x480 frames, %d rounds, Java %s%n", video.size(),
                    rounds, Runtime.version());
            for (int i = 0; i < contenders.length; i++) {
                out.printf(Locale.ROOT, "%-44s %6.2f ms/frame  %5.2fx BoofCV's default  %.2f markers/frame%n",
                        names[i], median[i], median[i] / median[0], found[i] / (double) (rounds * video.size()));
            }
            out.printf(Locale.ROOT, "track found the marker near the last one in %.0f%% of frames%n",
                    100.0 * inRegion[0] / (rounds * video.size()));
        }
        out.flush();
        return ExitCodes.OK;
    }
}
