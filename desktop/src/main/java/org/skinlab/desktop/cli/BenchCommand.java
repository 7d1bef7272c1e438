package org.skinlab.desktop.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;

/** {@code skinlab bench ...}: benchmarks with their own warm-up, reported as tables or JSON. */
@Command(name = "bench", mixinStandardHelpOptions = true,
        description = "Benchmarks (measured in this process, with warm-up; compare ratios, not absolute times).",
        subcommands = {ParseBenchCommand.class, SkinningBenchCommand.class, FrameBenchCommand.class,
                TrackBenchCommand.class, ArFrameBenchCommand.class})
public final class BenchCommand implements Runnable {
    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(), "a benchmark is required, e.g. 'bench parse'");
    }
}
