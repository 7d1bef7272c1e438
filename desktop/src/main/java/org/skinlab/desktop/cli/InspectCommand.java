package org.skinlab.desktop.cli;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Callable;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.ModelFileSearch;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.desktop.eval.InfluenceCapReport;
import org.skinlab.importer.ModelImporter;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.ImportWarning;
import org.skinlab.model.Material;
import org.skinlab.model.MaterialBinding;
import org.skinlab.model.Mesh;
import org.skinlab.model.Model;
import org.skinlab.model.Skin;
import org.skinlab.model.Texture;
import org.skinlab.internal.metrics.InfluenceCapError;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code skinlab inspect FILE... [--json] [--no-influence-caps]}: what the importer read. The JSON form is a contract:
 * <pre>
 * {"file":..., "upAxis":"Z_UP", "unitMeter":1.0,
 *  "meshes":[{"geometry":ID, "name":NAME, "positions":N, "triangles":N, "skinned":true,
 *             "joints":N, "maxInfluences":N,
 *             "materials":[{"symbol":S, "name":NAME, "diffuse":[r,g,b,a], "texture":PATH}],
 *             "influenceCap":{"restSize":X, "samples":N,
 *                             "caps":{"4":{"cappedPositions":N, "maxDroppedWeight":X,
 *                                          "lbs":{"distance":X, "relative":X, "position":N, "clip":NAME, "time":S},
 *                                          "dqs":{...}},
 *                                     "8":{...}}}}],
 *  "clips":[{"name":..., "duration":S, "channels":N}], "warnings":[...], "loadMillis":X}
 * </pre>
 * One mesh entry per {@code <geometry>} with a mesh, then one per morph controller (its result:
 * {@code geometry} is the controller's id); {@code positions} counts the entries of its
 * {@code <vertices>} POSITION source and {@code triangles} the triangles after fan
 * triangulation (lines not counted). {@code joints} and {@code maxInfluences} come from the first
 * skin on the geometry (0 when it has none). {@code materials}: one entry per material symbol of
 * the mesh's primitives (first use first), bound through the first instance that draws the mesh:
 * the material's name, its diffuse colour (RGBA, or null: a texture, constant shading, or none)
 * and the file of the texture it shows ({@code Material.baseTexture()}: the diffuse texture, or
 * the emission texture of constant shading; null when none or not a file); name, diffuse and
 * texture are null for a symbol nothing binds.
 *
 * <p>{@code influenceCap} (see {@link InfluenceCapError}, docs/skinning.md "Influence caps"):
 * what a renderer that skins with at most 4 or 8 influences per vertex loses, measured on the
 * first instance that places the mesh with a skin; null for a mesh no instance places with a
 * skin, and for every mesh with {@code --no-influence-caps}. {@code restSize} is the diagonal of
 * the bounding box of its positions in the rest pose; {@code samples} the sample times over every
 * clip (30 per second, each clip's end included; the rest pose alone when the file has no clip).
 * Per cap: {@code cappedPositions} the POSITION entries that lose weight and
 * {@code maxDroppedWeight} the most one loses (of 1); per method the largest distance between
 * the position skinned with all its influences and with the cap (model units), that distance
 * over {@code restSize} (null when the size is 0), the POSITION entry, clip and clip time where
 * it happens (the first clip to reach it). When nothing moves (no position loses weight)
 * distance and relative are 0 and position, clip and time null; clip is null too when the file
 * has no clip.
 *
 * <p><b>One FILE</b> (not a folder): that summary, as text or as one line of JSON; a file that
 * cannot be imported is one line on stderr and status 3, a missing file status 2.
 *
 * <p><b>Several FILEs, or a folder</b> (a batch): each argument in the order given; a folder is
 * searched recursively for model files ({@code *.dae}, {@code *.gltf}, {@code *.glb}, any case),
 * its files sorted by their path inside it
 * name by name, links to folders inside it not followed (see {@link ModelFileSearch}). A file
 * named as an argument is read whatever its extension. Files are read one after another, never
 * all held at once. The {@code "file"} value, loaded or not, is the argument as given joined with
 * the path inside a folder argument ({@code models/a/walk.dae} for {@code inspect models/}).
 * <ul>
 * <li>{@code --json}: JSON Lines on stdout, one line per file in order: the object above for a
 * loaded file, and {@code {"file":PATH, "error":MESSAGE}} (exactly these two keys) for a file
 * that is refused (the {@code ImportException} message, one line), cannot be read, is not a
 * regular file (a pipe or a broken link is never opened), for a folder that cannot be listed, or
 * for a file that hit a bug or the memory limit. Nothing on stderr.</li>
 * <li>text: the summaries one after another on stdout; each problem one line on stderr,
 * {@code skinlab: PATH: MESSAGE}; last, a tally on stderr: {@code N files: L loaded, R refused}
 * (then {@code , E internal errors} and {@code ; F folders could not be listed} when there are
 * any).</li>
 * </ul>
 * Before anything is read, an argument that names nothing to inspect (a path that does not exist,
 * or a folder with no model file below it) is a usage error: one line on stderr naming every
 * such argument, nothing on stdout, status 2. Otherwise the status is 1 if any file hit a bug or
 * the memory limit (it wins: a bug must not hide behind a refusal), else 3 if any file was refused
 * or unreadable or any folder could not be listed, else 0.
 */
@Command(name = "inspect", mixinStandardHelpOptions = true,
        description = "Import model files (COLLADA, glTF) and summarise their meshes, skins, clips and warnings.")
public final class InspectCommand implements Callable<Integer> {
    @Parameters(arity = "1..*", paramLabel = "FILE",
            description = "model files (.dae, .gltf, .glb), or folders searched recursively for them")
    List<Path> files;

    @Option(names = "--json", description = "print each summary as one line of JSON (JSON Lines for several files)")
    boolean json;

    @Option(names = "--no-influence-caps", description = "do not measure the position error of capping influences"
            + " at 4 and 8 per position (only meshes with more influences than a cap take time)")
    boolean noInfluenceCaps;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws JsonProcessingException {
        if (files.size() == 1 && !Files.isDirectory(files.get(0))) {
            return single(files.get(0));
        }
        List<ModelFileSearch.Entry> entries = ModelFileSearch.expand(files);
        CommandLine cl = spec.commandLine();
        return new InspectBatch(json, !noInfluenceCaps, cl.getOut(), cl.getErr(), ModelImporter::read).run(entries);
    }

    /** One file, as before batches existed: a refused file is a {@link CommandFailure} (one line on stderr). */
    private int single(Path file) throws JsonProcessingException {
        ModelFiles.Loaded loaded = ModelFiles.load(file);
        PrintWriter out = spec.commandLine().getOut();
        Map<Mesh, InfluenceCapReport.MeshReport> caps = capReports(loaded.model, !noInfluenceCaps);
        if (json) {
            ObjectMapper mapper = new ObjectMapper();
            out.println(mapper.writeValueAsString(summary(mapper, file.toString(), loaded.model, loaded.millis, caps)));
        } else {
            out.print(text(file.toString(), loaded.model, loaded.millis, caps));
        }
        out.flush();
        return ExitCodes.OK;
    }

    /** The influence-cap reports of a model's meshes, or none when not asked for. */
    static Map<Mesh, InfluenceCapReport.MeshReport> capReports(Model model, boolean measure) {
        return measure ? InfluenceCapReport.of(model) : Map.of();
    }

    /**
     * The JSON summary (key order as in the contract); {@code capReports} from
     * {@link #capReports} ({@code "influenceCap"} is null for a mesh without one).
     */
    static ObjectNode summary(ObjectMapper mapper, String fileName, Model model, double loadMillis,
            Map<Mesh, InfluenceCapReport.MeshReport> capReports) {
        ObjectNode root = mapper.createObjectNode();
        root.put("file", fileName);
        root.put("upAxis", model.asset().upAxis().name());
        root.put("unitMeter", model.asset().unitMeter());
        ArrayNode meshes = root.putArray("meshes");
        for (Mesh mesh : model.meshes()) {
            Optional<Skin> skin = model.skinOf(mesh);
            ObjectNode m = meshes.addObject();
            m.put("geometry", mesh.id());
            m.put("name", mesh.name());
            m.put("positions", mesh.positionCount());
            m.put("triangles", mesh.triangleCount());
            m.put("skinned", skin.isPresent());
            m.put("joints", skin.map(Skin::jointCount).orElse(0));
            m.put("maxInfluences", skin.map(Skin::maxInfluences).orElse(0));
            putMaterials(m.putArray("materials"), model.materialsOf(mesh));
            putInfluenceCap(m, capReports.get(mesh));
        }
        ArrayNode clips = root.putArray("clips");
        for (AnimationClip clip : model.clips()) {
            ObjectNode c = clips.addObject();
            c.put("name", clip.name());
            c.put("duration", shortest(clip.duration()));
            c.put("channels", clip.channels().size());
        }
        ArrayNode warnings = root.putArray("warnings");
        for (ImportWarning w : model.warnings()) {
            warnings.add(w.toString());
        }
        root.put("loadMillis", Math.round(loadMillis * 1000.0) / 1000.0);
        return root;
    }

    /** A mesh's bound materials: symbol, name, diffuse colour and texture file, null where unbound. */
    private static void putMaterials(ArrayNode materials, List<MaterialBinding> bindings) {
        for (MaterialBinding b : bindings) {
            ObjectNode entry = materials.addObject();
            entry.put("symbol", b.symbol());
            boolean bound = b.material() != Material.DEFAULT;
            entry.put("name", bound ? b.material().name() : null);
            float[] diffuse = bound ? b.material().diffuse() : null;
            if (diffuse == null) {
                entry.putNull("diffuse");
            } else {
                ArrayNode rgba = entry.putArray("diffuse");
                for (float f : diffuse) {
                    rgba.add(shortest(f));
                }
            }
            Path texture = bound ? textureFile(b.material()) : null;
            entry.put("texture", texture == null ? null : texture.toString());
        }
    }

    /** A mesh's {@code "influenceCap"}: null without a report, else per cap what it costs. */
    private static void putInfluenceCap(ObjectNode m, InfluenceCapReport.MeshReport caps) {
        if (caps == null) {
            m.putNull("influenceCap");
        } else {
            ObjectNode ic = m.putObject("influenceCap");
            ic.put("restSize", shortest((float) caps.restSize()));
            ic.put("samples", caps.samples());
            ObjectNode byCap = ic.putObject("caps");
            for (InfluenceCapReport.Cap cap : caps.caps()) {
                ObjectNode c = byCap.putObject(String.valueOf(cap.cap()));
                c.put("cappedPositions", cap.cappedPositions());
                c.put("maxDroppedWeight", shortest(cap.maxDroppedWeight()));
                putWorst(c.putObject("lbs"), cap.lbs());
                putWorst(c.putObject("dqs"), cap.dqs());
            }
        }
    }

    /** One method's worst: distance and relative always, position, clip and time null when nothing moved. */
    private static void putWorst(ObjectNode node, InfluenceCapReport.Worst w) {
        InfluenceCapError.Worst worst = w.worst();
        node.put("distance", shortest((float) worst.distance()));
        if (Double.isNaN(worst.relative())) {
            node.putNull("relative");
        } else {
            node.put("relative", shortest((float) worst.relative()));
        }
        boolean moved = worst.position() >= 0;
        if (moved) {
            node.put("position", worst.position());
        } else {
            node.putNull("position");
        }
        node.put("clip", w.clip());
        if (moved) {
            node.put("time", shortest(worst.time()));
        } else {
            node.putNull("time");
        }
    }

    private static Path textureFile(Material material) {
        Texture t = material.baseTexture();
        return t == null ? null : t.image().file();
    }

    /** The human-readable summary. */
    static String text(String fileName, Model model, double loadMillis,
            Map<Mesh, InfluenceCapReport.MeshReport> capReports) {
        StringBuilder sb = new StringBuilder();
        sb.append(fileName).append('\n');
        sb.append(String.format(Locale.ROOT, "  frame:    %s, 1 unit = %s m%s%n", model.asset().upAxis(),
                trim(model.asset().unitMeter()),
                model.asset().authoringTool() == null ? "" : ", written by " + model.asset().authoringTool()));
        sb.append(String.format(Locale.ROOT, "  loaded in %.1f ms%n", loadMillis));
        sb.append("  meshes:   ").append(model.meshes().size()).append('\n');
        for (Mesh mesh : model.meshes()) {
            Optional<Skin> skin = model.skinOf(mesh);
            sb.append(String.format(Locale.ROOT, "    %-28s %7d positions %8d triangles  %s%n",
                    mesh.id() + (mesh.name() == null || mesh.name().equals(mesh.id()) ? "" : " (" + mesh.name() + ")"),
                    mesh.positionCount(), mesh.triangleCount(),
                    skin.map(s -> "skinned: " + s.jointCount() + " joints, up to " + s.maxInfluences()
                            + " influences per position").orElse("static")));
            for (MaterialBinding b : model.materialsOf(mesh)) {
                sb.append("      material ").append(b.symbol()).append(": ").append(describe(b.material())).append('\n');
            }
            InfluenceCapReport.MeshReport caps = capReports.get(mesh);
            if (caps != null) {
                describe(caps, sb);
            }
        }
        sb.append("  clips:    ").append(model.clips().size()).append('\n');
        for (AnimationClip clip : model.clips()) {
            sb.append(String.format(Locale.ROOT, "    %-28s %8.3f s %5d channels%n", clip.name(), clip.duration(),
                    clip.channels().size()));
        }
        sb.append("  warnings: ").append(model.warnings().size()).append('\n');
        for (ImportWarning w : model.warnings()) {
            sb.append("    ").append(w).append('\n');
        }
        return sb.toString();
    }

    /** The cap errors of one mesh: a heading line, then one line per cap. */
    private static void describe(InfluenceCapReport.MeshReport caps, StringBuilder sb) {
        String over = caps.clips().isEmpty() ? "the rest pose"
                : caps.clips().size() == 1 ? "clip " + caps.clips().get(0) : caps.clips().size() + " clips";
        sb.append(String.format(Locale.ROOT, "      influence caps over %s (%d sample%s; rest size %.4g):%n", over,
                caps.samples(), caps.samples() == 1 ? "" : "s", caps.restSize()));
        for (InfluenceCapReport.Cap cap : caps.caps()) {
            if (cap.cappedPositions() == 0) {
                sb.append(String.format(Locale.ROOT, "        %d influences: exact, no position loses weight%n", cap.cap()));
                continue;
            }
            sb.append(String.format(Locale.ROOT, "        %d influences: %d positions lose weight (up to %.3g)%n",
                    cap.cap(), cap.cappedPositions(), cap.maxDroppedWeight()));
            sb.append("          LBS ").append(describe(cap.lbs())).append('\n');
            sb.append("          DQS ").append(describe(cap.dqs())).append('\n');
        }
    }

    private static String describe(InfluenceCapReport.Worst w) {
        InfluenceCapError.Worst worst = w.worst();
        if (worst.position() < 0) {
            return "0";
        }
        return String.format(Locale.ROOT, "%.3g (%.2g of the size) at position %d, %s%.3f s", worst.distance(),
                worst.relative(), worst.position(), w.clip() == null ? "" : w.clip() + " ", worst.time());
    }

    private static String describe(Material m) {
        if (m == Material.DEFAULT) {
            return "none bound (drawn with a default grey)";
        }
        StringBuilder sb = new StringBuilder(m.name()).append(", ").append(m.shading().name().toLowerCase(Locale.ROOT));
        Texture t = m.baseTexture();
        if (t != null) {
            sb.append(", texture ").append(t.image().file() != null ? t.image().file() : t.image().uri() + " (not a file)");
        } else if (m.diffuse() != null) {
            float[] c = m.diffuse();
            sb.append(String.format(Locale.ROOT, ", diffuse %.3g %.3g %.3g %.3g", c[0], c[1], c[2], c[3]));
        }
        if (m.opacity() < 1f) {
            sb.append(String.format(Locale.ROOT, ", opacity %.3g", m.opacity()));
        }
        return sb.toString();
    }

    /** The float's shortest decimal form as a double, so JSON shows 0.8333333 and not 0.8333333134651184. */
    static double shortest(float f) {
        return Double.parseDouble(Float.toString(f));
    }

    private static String trim(double d) {
        return d == Math.rint(d) ? String.valueOf((long) d) : String.valueOf(d);
    }
}
