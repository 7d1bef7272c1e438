package org.skinlab.desktop.eval;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.skinlab.desktop.JavaRuntime;

/**
 * What every figure and the report of {@code skinlab eval} name: the CPU (the first "model name"
 * of /proc/cpuinfo, else the JVM's os.arch), the cores the JVM sees, the operating system, the JVM
 * and the exact command line.
 */
final class EvalMachine {
    private EvalMachine() {
    }

    /** Writes the machine's description into {@code node}, and the commit of the repository at {@code root}. */
    static void describe(ObjectNode node, List<String> args, Path root) {
        node.put("cpu", cpuModel(Path.of("/proc/cpuinfo")));
        node.put("cores", Runtime.getRuntime().availableProcessors());
        node.put("os", System.getProperty("os.name") + " " + System.getProperty("os.version") + " "
                + System.getProperty("os.arch"));
        node.put("jvmVendor", JavaRuntime.vendor());
        node.put("jvmVersion", JavaRuntime.version());
        node.put("jvmName", System.getProperty("java.vm.name"));
        node.put("maxHeapMegabytes", Runtime.getRuntime().maxMemory() / (1024 * 1024));
        node.put("command", "skinlab " + String.join(" ", args));
        node.put("commit", git(root, "rev-parse", "HEAD"));
        String changed = git(root, "status", "--porcelain", "--untracked-files=no");
        node.put("uncommittedChanges", !changed.isEmpty() && !changed.equals(UNKNOWN));
        node.put("loadAverageStart", loadAverage());
    }

    static final String UNKNOWN = "unknown (not a git checkout, or no git)";

    /** What {@code git -C root args...} prints (trimmed), or {@link #UNKNOWN}. */
    static String git(Path root, String... args) {
        List<String> command = new java.util.ArrayList<>(List.of("git", "-C", root.toString()));
        command.addAll(List.of(args));
        try {
            Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
            String out = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8).trim();
            if (!p.waitFor(30, java.util.concurrent.TimeUnit.SECONDS) || p.exitValue() != 0) {
                p.destroyForcibly();
                return UNKNOWN;
            }
            return out;
        } catch (IOException e) {
            return UNKNOWN;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return UNKNOWN;
        }
    }

    /** The one-minute load average (/proc/loadavg), or -1 where there is none. */
    static double loadAverage() {
        try {
            String[] fields = Files.readString(Path.of("/proc/loadavg")).trim().split("\\s+");
            return Double.parseDouble(fields[0]);
        } catch (IOException | RuntimeException e) {
            return -1;
        }
    }

    /** The lines a figure's footer and the report's header print. */
    static List<String> lines(JsonNode machine) {
        return List.of(String.format("Machine: %s, %s cores, %s", machine.path("cpu").asText(),
                machine.path("cores").asText(), machine.path("os").asText()),
                String.format("JVM: %s %s (%s)", machine.path("jvmVendor").asText(),
                        machine.path("jvmVersion").asText(), machine.path("jvmName").asText()),
                "Command: " + machine.path("command").asText() + ", commit " + shortCommit(machine)
                        + (machine.path("uncommittedChanges").asBoolean() ? " with uncommitted changes" : ""));
    }

    /** The commit's first 12 characters, or what was recorded instead. */
    static String shortCommit(JsonNode machine) {
        String c = machine.path("commit").asText("unknown");
        return c.matches("[0-9a-f]{40}") ? c.substring(0, 12) : c;
    }

    static String cpuModel(Path cpuinfo) {
        try {
            for (String line : Files.readAllLines(cpuinfo)) {
                if (line.startsWith("model name")) {
                    return line.substring(line.indexOf(':') + 1).trim();
                }
            }
        } catch (IOException | RuntimeException e) {
            // No /proc (not Linux): the architecture is all the JVM says.
        }
        return "unknown CPU (" + System.getProperty("os.arch") + ")";
    }
}
