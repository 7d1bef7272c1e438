package org.skinlab.desktop.cli;

import java.io.PrintWriter;
import java.util.List;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.JavaRuntime;

/** The {@code skinlab} command and its subcommands. */
@Command(name = "skinlab", mixinStandardHelpOptions = true, versionProvider = SkinlabCommand.Version.class,
        description = "Skeletal animation lab: view COLLADA characters skinned with LBS and DQS (no subcommand: the window "
                + "on the default character), inspect them, pose them, benchmark.",
        subcommands = {ViewCommand.class, EvalCommand.class, CheckGpuCommand.class, RenderBenchCommand.class, CompareCommand.class,
                CentresCommand.class, ExportCommand.class, TwistPlotCommand.class,
                InspectCommand.class, PoseCommand.class, BenchCommand.class, TrackCommand.class,
                MarkerCommand.class, CalibrationTargetCommand.class, CalibrateCommand.class, ArCommand.class, ArDemoCommand.class,
                CommandLine.HelpCommand.class})
public final class SkinlabCommand implements Runnable {
    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(), "a subcommand is required");
    }

    /**
     * The arguments with {@code view} in front when they name no subcommand: {@code skinlab} alone
     * opens the window, and {@code skinlab --exit-after-frames 120} is {@code skinlab view ...}.
     * The top-level help and version options stay the top level's.
     */
    static String[] withDefaultCommand(String... args) {
        if (args.length > 0 && (!args[0].startsWith("-") || List.of("-h", "--help", "-V", "--version")
                .contains(args[0]))) {
            return args;
        }
        String[] view = new String[args.length + 1];
        view[0] = "view";
        System.arraycopy(args, 0, view, 1, args.length);
        return view;
    }

    /** Runs the command line and returns the exit status (see {@link ExitCodes}). */
    public static int run(String... args) {
        return run(new PrintWriter(System.out, true), new PrintWriter(System.err, true), args);
    }

    /** Runs with the given output streams (used by tests). */
    public static int run(PrintWriter out, PrintWriter err, String... args) {
        CommandLine cl = new CommandLine(new SkinlabCommand());
        cl.setOut(out);
        cl.setErr(err);
        cl.setExitCodeExceptionMapper(e -> ExitCodes.USAGE);
        // Failures are one line on stderr, never a stack trace.
        cl.setExecutionExceptionHandler((e, commandLine, parseResult) -> {
            if (e instanceof CommandFailure) {
                commandLine.getErr().println("skinlab: " + oneLine(e.getMessage()));
                return ((CommandFailure) e).status();
            }
            commandLine.getErr().println("skinlab: internal error: " + oneLine(String.valueOf(e)));
            return ExitCodes.INTERNAL;
        });
        int status;
        try {
            status = cl.execute(withDefaultCommand(args));
        } catch (OutOfMemoryError e) {
            // Errors bypass picocli's exception handler; this one is worth a clear line.
            err.println("skinlab: out of memory; give Java more with SKINLAB_OPTS=-Xmx4g (or JAVA_OPTS)");
            status = ExitCodes.INTERNAL;
        }
        out.flush();
        err.flush();
        return status;
    }

    static String oneLine(String message) {
        return message == null ? "" : message.replaceAll("\\s+", " ").trim();
    }

    /**
     * Version from the jar manifest when packaged, else "development"; then the Java that runs it
     * (the start scripts choose the newest JDK found: README, "Which Java runs skinlab").
     */
    public static final class Version implements CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() {
            String v = SkinlabCommand.class.getPackage().getImplementationVersion();
            return new String[] {"skinlab " + (v == null ? "development" : v), JavaRuntime.describeWithHome()};
        }
    }
}
