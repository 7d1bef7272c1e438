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

    /** Writes the machine's description into {@code node}. */
    static void describe(ObjectNode node, List<String> args) {
        node.put("cpu", cpuModel(Path.of("/proc/cpuinfo")));
        node.put("cores", Runtime.getRuntime().availableProcessors());
        node.put("os", System.getProperty("os.name") + " " + System.getProperty("os.version") + " "
                + System.getProperty("os.arch"));
        node.put("jvmVendor", JavaRuntime.vendor());
        node.put("jvmVersion", JavaRuntime.version());
        node.put("jvmName", System.getProperty("java.vm.name"));
        node.put("maxHeapMegabytes", Runtime.getRuntime().maxMemory() / (1024 * 1024));
        node.put("command", "skinlab " + String.join(" ", args));
    }

    /** The lines a figure's footer and the report's header print. */
    static List<String> lines(JsonNode machine) {
        return List.of(String.format("Machine: %s, %s cores, %s", machine.path("cpu").asText(),
                machine.path("cores").asText(), machine.path("os").asText()),
                String.format("JVM: %s %s (%s)", machine.path("jvmVendor").asText(),
                        machine.path("jvmVersion").asText(), machine.path("jvmName").asText()),
                "Command: " + machine.path("command").asText());
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
