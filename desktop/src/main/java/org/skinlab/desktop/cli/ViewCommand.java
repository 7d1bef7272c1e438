package org.skinlab.desktop.cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;

import org.skinlab.animation.RotationInterpolation;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.app.AppOptions;
import org.skinlab.desktop.app.SkinlabApp;
import org.skinlab.desktop.render.DrawSettings;
import org.skinlab.desktop.viewer.DifferenceScale;
import org.skinlab.skinning.SkinningGlsl;
import org.skinlab.skinning.SkinningMethod;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code skinlab view [FILE] [options]}: the window (the default character when no file is
 * given); with {@code --screenshot OUT.png} one frame rendered off-screen and written, then exit.
 */
@Command(name = "view", mixinStandardHelpOptions = true,
        description = {"Open the viewer window on a model file, COLLADA or glTF (default: the bundled walking "
                + "character).",
                "With --screenshot, render one frame to a PNG and exit (no window is shown)."})
public final class ViewCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", arity = "0..1", paramLabel = "FILE", description = "a model file (.dae, .gltf, .glb)")
    Path file;

    @Mixin
    WindowOptions window = new WindowOptions();

    @Option(names = "--interpolation", paramLabel = "slerp|nlerp|lerp", converter = PoseCommand.RotationConverter.class,
            description = "rotation interpolation between keyframes (default: slerp)")
    RotationInterpolation interpolation = RotationInterpolation.SLERP;

    @Option(names = "--split", paramLabel = MethodKeys.KEYS, converter = MethodKeys.Converter.class,
            description = "split view: this method drawn beside --method, in sync, skinned on the GPU (a method"
                    + " without shader code cannot be the second view)")
    SkinningMethod split;

    @Option(names = "--gpu", description = "skin in the vertex shader (the default)")
    boolean gpu;

    @Option(names = "--cpu", description = "skin on the CPU and stream the mesh to the GPU")
    boolean cpu;

    @Option(names = "--view", paramLabel = "shaded|weights|difference|checker", converter = ViewConverter.class,
            description = "what colours show (default: shaded); checker: shaded with a checker fixed to the rest shape,"
                    + " so that twist and stretch show")
    DrawSettings.View view = DrawSettings.View.SHADED;

    @Option(names = "--difference-scale", paramLabel = "PERCENT|auto", converter = DifferenceScaleConverter.class,
            description = "the difference view's red: this percentage of the model's size or more (default: 5),"
                    + " or auto: the largest LBS-DQS distance over the clip")
    DifferenceScale differenceScale = DifferenceScale.DEFAULT;

    @Option(names = "--time", paramLabel = "SECONDS", description = "show this playback time, paused")
    Double time;

    @Option(names = "--bind-pose", description = "show the bind pose (every joint at its bind frame, the skins' rest"
            + " shapes) instead of the clip")
    boolean bindPose;

    @Option(names = "--yaw", paramLabel = "DEGREES",
            description = "the camera's angle around the model: 0 from the front (+z, the default), 90 from +x")
    double yaw;

    @Option(names = "--pitch", paramLabel = "DEGREES",
            description = "the camera's elevation: 0 level with the model's centre, 90 from straight above"
                    + " (at most 85); default 12")
    double pitch = AppOptions.DEFAULT_PITCH_DEGREES;

    @Option(names = "--exit-after-frames", paramLabel = "N",
            description = "close after N frames; exit status 1 when the last frame drew nothing")
    int exitAfterFrames;

    @Option(names = "--gl-debug", description = "OpenGL debug context: print GL errors, exit status 1 if any")
    boolean glDebug;

    @Override
    public Integer call() {
        if (gpu && cpu) {
            throw new CommandFailure(ExitCodes.USAGE, "--gpu and --cpu exclude each other", null);
        }
        if (split != null && split == window.method) {
            throw new CommandFailure(ExitCodes.USAGE, "--split names the method drawn beside --method: use another "
                    + "one than " + window.method.key(), null);
        }
        if (split != null && !SkinningGlsl.hasCode(split)) {
            throw new CommandFailure(ExitCodes.USAGE, "--split " + split.key() + ": the second view is skinned on the GPU,"
                    + " and " + split.key() + " has no shader code (it can be --method, skinned on the CPU)", null);
        }
        if (exitAfterFrames < 0) {
            throw new CommandFailure(ExitCodes.USAGE, "--exit-after-frames needs a count >= 0", null);
        }
        if (time != null && !(time >= 0 && !time.isInfinite())) {
            throw new CommandFailure(ExitCodes.USAGE, "--time needs a finite time >= 0 (seconds)", null);
        }
        if (!Double.isFinite(yaw)) {
            throw new CommandFailure(ExitCodes.USAGE, "--yaw needs a finite angle (degrees)", null);
        }
        if (!(Math.abs(pitch) <= 90)) {
            throw new CommandFailure(ExitCodes.USAGE, "--pitch needs an angle from -90 to 90 (degrees)", null);
        }
        AppOptions options = new AppOptions(file, window.method, interpolation, !cpu, view, differenceScale, split,
                time, bindPose, yaw, pitch, window.screenshot, window.size.width(), window.size.height(), window.hideUi,
                window.script, exitAfterFrames, glDebug);
        return SkinlabApp.run(options, spec.commandLine().getOut(), spec.commandLine().getErr());
    }

    static final class ViewConverter implements CommandLine.ITypeConverter<DrawSettings.View> {
        @Override
        public DrawSettings.View convert(String value) {
            for (DrawSettings.View v : DrawSettings.View.values()) {
                if (v.name().equalsIgnoreCase(value)) {
                    return v;
                }
            }
            throw new CommandLine.TypeConversionException("'" + value + "' is not a view (expected shaded, weights, "
                    + "difference or checker)");
        }
    }

    static final class DifferenceScaleConverter implements CommandLine.ITypeConverter<DifferenceScale> {
        @Override
        public DifferenceScale convert(String value) {
            try {
                return DifferenceScale.parse(value);
            } catch (IllegalArgumentException e) {
                throw new CommandLine.TypeConversionException(e.getMessage());
            }
        }
    }
}
