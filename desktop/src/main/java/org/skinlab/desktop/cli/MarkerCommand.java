package org.skinlab.desktop.cli;

import java.io.IOException;
import java.util.concurrent.Callable;

import org.skinlab.ar.MarkerDictionary;
import org.skinlab.ar.MarkerPattern;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.ar.MarkerSheet;

import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code skinlab marker}: the printable marker as an A4 PDF and a PNG at exact physical size. */
@Command(name = "marker", mixinStandardHelpOptions = true,
        description = "Write the printable marker: an A4 PDF (print at 100%%) and/or a PNG at exact size.")
public final class MarkerCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = "--dictionary", paramLabel = "NAME", description = "marker dictionary (default: aruco_mip_36h12)")
    String dictionary = MarkerDictionary.DEFAULT.key();

    @Option(names = "--id", paramLabel = "N", description = "marker id (default: ${DEFAULT-VALUE})")
    int id = 0;

    @Option(names = "--size-mm", paramLabel = "MM", description = "the black square's printed width (default: ${DEFAULT-VALUE})")
    double sizeMm = 100;

    @Mixin
    PrintOptions print;

    @Override
    public Integer call() {
        print.requireOutput();
        MarkerPattern pattern;
        try {
            pattern = MarkerPattern.of(MarkerDictionary.byName(dictionary), id);
            if (print.pdf != null) {
                MarkerSheet.writePdf(pattern, sizeMm, print.pdf);
                spec.commandLine().getOut().println("wrote " + print.pdf);
            }
            if (print.png != null) {
                MarkerSheet.writePng(pattern, sizeMm, print.dpi, print.png);
                spec.commandLine().getOut().println("wrote " + print.png);
            }
        } catch (IllegalArgumentException e) {
            throw new CommandFailure(ExitCodes.USAGE, e.getMessage(), e);
        } catch (IOException e) {
            throw new CommandFailure(ExitCodes.USAGE, "cannot write the marker: " + e.getMessage(), e);
        }
        spec.commandLine().getOut().flush();
        return ExitCodes.OK;
    }
}
