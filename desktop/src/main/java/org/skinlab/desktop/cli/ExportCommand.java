package org.skinlab.desktop.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.Callable;

import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.gltf.export.ExportResult;
import org.skinlab.gltf.export.GltfExporter;
import org.skinlab.model.Model;
import org.skinlab.skinning.SkinningMethod;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code skinlab export FILE --out OUT.glb [--methods lbs,dqs,cor]}: the model as a binary glTF
 * with skinlab's bind-time skinning data ({@link GltfExporter}; docs/integrations.md).
 * Prints one summary line, and a line per warning (an image left out, ...) on stderr. Exit 0 when
 * written, 2 for a usage error (a method the export has no data for, an output that cannot be
 * written), 3 when FILE cannot be imported.
 */
@Command(name = "export", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Write a model (COLLADA or glTF) as binary glTF 2.0 (GLB) with skinlab's skinning data: the "
                + "SKINLAB_skinning primitive extension and, for cor, each vertex's centre of rotation (_COR_CENTER)."})
public final class ExportCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "FILE", description = "the model file (.dae, .gltf, .glb)")
    Path file;

    @Option(names = "--out", required = true, paramLabel = "OUT.glb", description = "the GLB file to write")
    Path out;

    @Option(names = "--methods", split = ",", paramLabel = "lbs|dqs|cor", description = "the skinning methods the "
            + "file declares and carries data for (default: lbs,dqs,cor)")
    List<String> methods = new ArrayList<>(List.of("lbs", "dqs", "cor"));

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        Set<SkinningMethod> chosen = methods();
        Model model = ModelFiles.load(file).model;
        ExportResult result;
        try {
            Path parent = out.toAbsolutePath().getParent();
            if (parent != null && !Files.isDirectory(parent)) {
                throw new CommandFailure(ExitCodes.USAGE, "cannot write " + out + ": no folder " + parent, null);
            }
            result = GltfExporter.write(model, chosen, out);
        } catch (IOException e) {
            throw new CommandFailure(ExitCodes.USAGE, "cannot write " + out + ": " + e.getMessage(), e);
        }
        PrintWriter err = spec.commandLine().getErr();
        for (String w : result.warnings()) {
            err.println(file.getFileName() + ": " + w);
        }
        err.flush();
        PrintWriter o = spec.commandLine().getOut();
        o.printf(Locale.ROOT, "%s: %d meshes, %d vertices, %d clips, methods %s, %d bytes%n", out, result.meshes(),
                result.vertices(), result.clips(), String.join(",", result.methods()), result.bytes());
        o.flush();
        return ExitCodes.OK;
    }

    private Set<SkinningMethod> methods() {
        Set<SkinningMethod> chosen = EnumSet.noneOf(SkinningMethod.class);
        for (String key : methods) {
            SkinningMethod m;
            try {
                m = MethodKeys.parse(key.trim());
            } catch (IllegalArgumentException e) {
                throw usage("--methods: unknown method '" + key + "'; the export carries data for lbs, dqs and cor");
            }
            if (!GltfExporter.METHODS.contains(m)) {
                throw usage("--methods: the export has no data for " + m.key() + "; only lbs, dqs and cor are accepted");
            }
            chosen.add(m);
        }
        if (chosen.isEmpty()) {
            throw usage("--methods: name at least one of lbs, dqs, cor");
        }
        return chosen;
    }

    private CommandLine.ParameterException usage(String message) {
        return new CommandLine.ParameterException(spec.commandLine(), message);
    }
}
