package org.skinlab.desktop.cli;

import java.io.IOException;
import java.util.concurrent.Callable;

import org.skinlab.internal.ar.CalibrationTarget;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.ar.CalibrationSheet;

import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/** {@code skinlab calibration-target}: the printable calibration target as an A4 PDF and a PNG at exact size. */
@Command(name = "calibration-target", mixinStandardHelpOptions = true,
        description = {"Write the printable camera calibration target: an A4 PDF (print at 100%%) and/or a PNG.",
                "The page names the options that tell skinlab calibrate about it."})
public final class CalibrationTargetCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Mixin
    TargetOptions targetOptions;

    @Mixin
    PrintOptions print;

    @Override
    public Integer call() {
        print.requireOutput();
        CalibrationTarget target = targetOptions.target();
        try {
            if (print.pdf != null) {
                CalibrationSheet.writePdf(target, print.pdf);
                spec.commandLine().getOut().println("wrote " + print.pdf + " (" + target.describe() + "; skinlab calibrate "
                        + target.options() + ")");
            }
            if (print.png != null) {
                CalibrationSheet.writePng(target, print.dpi, print.png);
                spec.commandLine().getOut().println("wrote " + print.png);
            }
        } catch (IllegalArgumentException e) {
            throw new CommandFailure(ExitCodes.USAGE, e.getMessage(), e);
        } catch (IOException e) {
            throw new CommandFailure(ExitCodes.USAGE, "cannot write the calibration target: " + e.getMessage(), e);
        }
        spec.commandLine().getOut().flush();
        return ExitCodes.OK;
    }
}
