package org.skinlab.desktop.cli;

import java.nio.file.Path;

import picocli.CommandLine.Option;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;

/** Where a printable sheet goes ({@code --pdf}, {@code --png}, {@code --dpi}): {@code marker}'s and {@code calibration-target}'s. */
final class PrintOptions {
    @Option(names = "--pdf", paramLabel = "OUT.pdf", description = "where to write the A4 PDF")
    Path pdf;

    @Option(names = "--png", paramLabel = "OUT.png", description = "where to write the PNG")
    Path png;

    @Option(names = "--dpi", paramLabel = "DPI", description = "the PNG's resolution (default: ${DEFAULT-VALUE})")
    int dpi = 300;

    /** Refuses a command line that names no output. */
    void requireOutput() {
        if (pdf == null && png == null) {
            throw new CommandFailure(ExitCodes.USAGE, "nothing to write: give --pdf OUT.pdf and/or --png OUT.png", null);
        }
    }
}
