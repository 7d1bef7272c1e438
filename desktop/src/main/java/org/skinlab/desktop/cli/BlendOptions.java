package org.skinlab.desktop.cli;

import java.util.ArrayList;
import java.util.List;

import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;

import picocli.CommandLine.Option;

/**
 * {@code --blend CLIP=W[,CLIP=W...]} and {@code --additive CLIP=W[@REFTIME]}, shared by
 * {@code pose} and {@code bench frame}: the text of a {@link BlendSpec}. The values are read here
 * rather than by picocli converters so that a fault is one line naming the clip and the value
 * ({@code skinlab: pose: --blend: the weight of clip 'walk' is 'x', not a number}), not a line
 * followed by the whole usage.
 */
final class BlendOptions {
    @Option(names = "--blend", split = ",", paramLabel = "CLIP=W",
            description = "play these clips (a glTF animation's name, a COLLADA clip's name or id) blended on the base"
                    + " layer, each with weight W (0 or more), in the order given, each at the time T: T seconds after"
                    + " its own start, looped within it")
    List<String> blend = new ArrayList<>();

    @Option(names = "--additive", split = ",", paramLabel = "CLIP=W[@REFTIME]",
            description = "with --blend: add a layer on top that adds CLIP's difference from its own pose at REFTIME"
                    + " seconds after its start (default 0) with weight W, CLIP at the time T too; repeatable")
    List<String> additive = new ArrayList<>();

    /** Whether either option was given. */
    boolean given() {
        return !blend.isEmpty() || !additive.isEmpty();
    }

    /**
     * The blend asked for, its syntax checked (its clips are checked against the file by
     * {@link BlendSpec#resolve}).
     *
     * @param command the command's name, the start of an error message
     * @return the blend, or null when neither option was given
     * @throws CommandFailure (usage) naming the option and the value at fault
     */
    BlendSpec spec(String command) {
        if (blend.isEmpty()) {
            if (!additive.isEmpty()) {
                throw usage(command, "--additive needs --blend (the clips of the base layer that additive layers go on)");
            }
            return null;
        }
        List<BlendSpec.Weighted> base = new ArrayList<>();
        for (String item : blend) {
            int eq = equalsSign(command, "--blend", "CLIP=W", item);
            String clip = item.substring(0, eq);
            base.add(new BlendSpec.Weighted(clip, weight(command, "--blend", clip, item.substring(eq + 1))));
        }
        List<BlendSpec.Additive> added = new ArrayList<>();
        for (String item : additive) {
            int eq = equalsSign(command, "--additive", "CLIP=W[@REFTIME]", item);
            String clip = item.substring(0, eq);
            String rest = item.substring(eq + 1);
            int at = rest.indexOf('@');
            double w = weight(command, "--additive", clip, at < 0 ? rest : rest.substring(0, at));
            double reference = at < 0 ? 0 : referenceTime(command, clip, rest.substring(at + 1));
            added.add(new BlendSpec.Additive(clip, w, reference));
        }
        return new BlendSpec(base, added);
    }

    /** Where CLIP ends: the last '=' (a clip's name may hold one; a number never does). */
    private static int equalsSign(String command, String option, String form, String item) {
        int eq = item.lastIndexOf('=');
        if (eq <= 0) {
            throw usage(command, option + ": '" + item + "' is not " + form + " (a clip's name, '=', a weight)");
        }
        return eq;
    }

    private static double weight(String command, String option, String clip, String text) {
        String s = text.trim();
        if (!Decimal.matches(s)) {
            throw usage(command, option + ": the weight of clip '" + clip + "' is '" + text + "', not a number");
        }
        double w = Double.parseDouble(s);
        if (Double.isInfinite(w)) {
            throw usage(command, option + ": the weight of clip '" + clip + "' is '" + text + "', beyond the range of"
                    + " numbers");
        }
        if (w < 0) {
            throw usage(command, option + ": the weight of clip '" + clip + "' is " + text + ", negative (a weight is"
                    + " 0 or more)");
        }
        // -0 is 0: the mixer and the JSON need not tell them apart.
        return w + 0.0;
    }

    private static double referenceTime(String command, String clip, String text) {
        String s = text.trim();
        if (!Decimal.matches(s)) {
            throw usage(command, "--additive: the reference time of clip '" + clip + "' is '" + text + "', not a time"
                    + " in seconds (a decimal number)");
        }
        double t = Double.parseDouble(s);
        if (Double.isInfinite(t) || t < 0) {
            throw usage(command, "--additive: the reference time of clip '" + clip + "' is " + text + ", not 0 or"
                    + " more seconds after the clip's start");
        }
        return t + 0.0;
    }

    private static CommandFailure usage(String command, String message) {
        return new CommandFailure(ExitCodes.USAGE, command + ": " + message, null);
    }
}
