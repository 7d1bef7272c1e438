package org.skinlab.desktop.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;

import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.style.Styler;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.model.Model;
import org.skinlab.model.Node;
import org.skinlab.internal.metrics.BoneProfile;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * How each method spreads a joint's twist along its bone ({@link BoneProfile}): per ring from
 * the joint (0) to its bone's tail (1) the twist angle and the ring's radius over rest, as a table
 * and, with {@code --png}, as a plot of the twist (docs/images/stbs-twist.png is made by
 * {@code skinlab twist-plot assets/twist/arm-twist.dae --joint forearm --time 0.875 --png ...}).
 */
@Command(name = "twist-plot", mixinStandardHelpOptions = true,
        description = "Twist angle and ring radius along a joint's bone, per skinning method, in one pose.")
public final class TwistPlotCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "FILE", description = "a model file (.dae, .gltf, .glb)")
    Path file;

    @Option(names = "--joint", required = true, paramLabel = "NAME", description = "the twisting joint (node name, id or sid)")
    String joint;

    @Option(names = "--time", paramLabel = "T", description = "clip time in seconds (default: ${DEFAULT-VALUE})")
    float time = 0f;

    @Option(names = "--methods", split = ",", paramLabel = "KEY", converter = MethodKeys.Converter.class,
            description = "methods to compare (default: lbs,dqs,stbs-lbs,stbs-dqs)")
    List<SkinningMethod> methods = List.of(SkinningMethod.LBS, SkinningMethod.DQS, SkinningMethod.STBS_LBS,
            SkinningMethod.STBS_DQS);

    @Option(names = "--png", paramLabel = "FILE", description = "also write the twist plot there")
    Path png;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws IOException {
        Model model = ModelFiles.load(file).model;
        SkinnedModel skinned = new SkinnedModel(model, model.clips().isEmpty() ? null : model.clips().get(0),
                NormalTransform.INVERSE_TRANSPOSE);
        for (int g = 0; g < skinned.geometries().size(); g++) {
            SkinnedGeometry geometry = skinned.geometries().get(g);
            int j = paletteIndex(model, geometry, joint);
            if (j >= 0) {
                plot(skinned, g, j);
                return ExitCodes.OK;
            }
        }
        throw new CommandFailure(ExitCodes.USAGE, file + ": no skin has a joint named " + joint, null);
    }

    private void plot(SkinnedModel skinned, int g, int j) throws IOException {
        SkinnedGeometry geometry = skinned.geometries().get(g);
        BoneProfile profile = new BoneProfile(geometry, j, 0, 1, 8);
        skinned.pose(skinned.sampler().clamp(time), RotationInterpolation.SLERP);
        PrintWriter out = spec.commandLine().getOut();
        out.printf(Locale.ROOT, "%s, joint %s at t = %.3f s: twist (degrees) / ring radius over rest, %d rings%n",
                file.getFileName(), joint, time, profile.ringCount());
        XYChart chart = new XYChartBuilder().width(800).height(480)
                .title(String.format(Locale.ROOT, "Twist along the %s of %s at t = %.3f s", joint, file.getFileName(), time))
                .xAxisTitle("position along the bone (0 joint, 1 tail)").yAxisTitle("twist of the ring (degrees)").build();
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideSE);
        for (SkinningMethod method : methods) {
            float[] points = new float[3 * geometry.pointCount()];
            skinned.skin(g, method, points, new float[points.length]);
            List<BoneProfile.Ring> rings = profile.measure(points, skinned.palette(g).prepareAll());
            List<Double> x = new ArrayList<>();
            List<Double> y = new ArrayList<>();
            StringBuilder line = new StringBuilder(String.format(Locale.ROOT, "%-9s", method.key()));
            for (BoneProfile.Ring r : rings) {
                x.add(r.along());
                y.add(Math.toDegrees(r.twist()));
                line.append(String.format(Locale.ROOT, " %.2f:%.1f/%.3f", r.along(), Math.toDegrees(r.twist()), r.radius()));
            }
            out.println(line);
            chart.addSeries(method.key(), x, y);
        }
        if (png != null) {
            BitmapEncoder.saveBitmap(chart, png.toString(), BitmapEncoder.BitmapFormat.PNG);
            out.println("wrote " + png);
        }
        out.flush();
    }

    private static int paletteIndex(Model model, SkinnedGeometry g, String name) {
        for (int j = 0; j < g.jointCount(); j++) {
            int node = g.jointNode(j);
            if (node >= 0) {
                Node n = model.node(node);
                if (name.equals(n.name()) || name.equals(n.id()) || name.equals(n.sid())) {
                    return j;
                }
            }
        }
        return -1;
    }
}
