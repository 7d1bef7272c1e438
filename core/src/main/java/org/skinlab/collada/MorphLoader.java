package org.skinlab.collada;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.skinlab.model.Mesh;
import org.skinlab.model.Morph;

/**
 * Reads {@code <controller><morph>}s into {@link Morph}s: base, targets and weights from the
 * {@code <targets>} MORPH_TARGET (geometry ids) and MORPH_WEIGHT inputs, and the base morphed
 * with those weights, which instances of the controller draw and a skin on it deforms.
 *
 * <p>A morph's base may be another morph (morphs chain, each result the next one's base). A
 * morph whose base is a skin has no result here: its instances draw the skin, without the morph
 * (the scene loader warns). Lenient (with a warning): a target that is no mesh, or has fewer
 * positions than the base, is left out; a target with more contributes its first ones. Refused:
 * MORPH_TARGET and MORPH_WEIGHT counts that differ, non-finite weights, morph cycles.
 */
final class MorphLoader {
    private final ImportContext ctx;
    private final Map<XmlElement, Mesh> meshes;
    private final Map<XmlElement, Morph> morphs = new IdentityHashMap<>();
    private final Map<XmlElement, Boolean> loading = new IdentityHashMap<>();
    /** Per morph controller, per weight of the file, its index among the morph's targets or -1 (left out). */
    private final Map<XmlElement, int[]> weightSlots = new IdentityHashMap<>();

    MorphLoader(ImportContext ctx, Map<XmlElement, Mesh> meshesByGeometry) {
        this.ctx = ctx;
        this.meshes = meshesByGeometry;
    }

    /** Every morph controller's morph (those on a skin excluded), in document order. */
    Map<XmlElement, Morph> loadAll(XmlElement collada) throws ColladaException {
        Map<XmlElement, Morph> inOrder = new LinkedHashMap<>();
        for (XmlElement library : collada.children("library_controllers")) {
            for (XmlElement controller : library.children("controller")) {
                Morph m = controller.child("morph") == null ? null : load(controller);
                if (m != null) {
                    inOrder.put(controller, m);
                }
            }
        }
        return inOrder;
    }

    /**
     * Per weight of the controller's MORPH_WEIGHT source, the index of its target in the
     * {@link Morph} ({@link Morph#targets()}), or -1 for a target left out; null when the
     * controller has no morph.
     */
    int[] weightSlots(XmlElement controller) {
        return weightSlots.get(controller);
    }

    /** The controller's morph, or null when its base is a skin or a geometry without a mesh. */
    private Morph load(XmlElement controller) throws ColladaException {
        if (morphs.containsKey(controller)) {
            return morphs.get(controller);
        }
        XmlElement morph = controller.child("morph");
        if (loading.put(controller, Boolean.TRUE) != null) {
            throw ctx.error(morph, "source=\"" + morph.attr("source") + "\" leads back to this morph (a cycle)");
        }
        if (loading.size() > SceneLoader.MAX_INSTANCE_DEPTH) {
            // Each morph on a morph is a level of recursion: a hostile chain must not overflow the stack.
            throw ctx.error(morph, "more than " + SceneLoader.MAX_INSTANCE_DEPTH + " morphs on morphs");
        }
        Mesh base = base(morph);
        Morph result = base == null ? null : read(controller, morph, base);
        morphs.put(controller, result);
        loading.remove(controller);
        return result;
    }

    /** The mesh a morph deforms, or null (a skin, or a geometry that is no mesh). */
    private Mesh base(XmlElement morph) throws ColladaException {
        XmlElement source = ctx.resolve(morph, "source", "geometry", "controller");
        if (source.name().equals("geometry")) {
            return meshes.get(source);
        }
        return source.child("morph") != null ? mesh(load(source)) : null;
    }

    private static Mesh mesh(Morph m) {
        return m == null ? null : m.result();
    }

    private Morph read(XmlElement controller, XmlElement morph, Mesh base) throws ColladaException {
        Morph.Method method = method(morph);
        XmlElement targets = ctx.child(morph, "targets");
        XmlElement targetInput = null;
        XmlElement weightInput = null;
        for (XmlElement input : targets.children("input")) {
            String semantic = ctx.attr(input, "semantic");
            if (semantic.equals("MORPH_TARGET") && targetInput == null) {
                targetInput = input;
            } else if (semantic.equals("MORPH_WEIGHT") && weightInput == null) {
                weightInput = input;
            }
        }
        if (targetInput == null || weightInput == null) {
            throw ctx.error(targets, "needs a MORPH_TARGET and a MORPH_WEIGHT input");
        }
        String[] targetIds = ctx.inputSource(targetInput).names(ctx, targetInput, "MORPH_TARGET");
        float[] weights = ctx.inputSource(weightInput).floats(ctx, weightInput, 1, "MORPH_WEIGHT");
        if (weights.length != targetIds.length) {
            throw ctx.error(weightInput, targetIds.length + " morph targets but " + weights.length + " weights");
        }
        List<Mesh> used = new ArrayList<>();
        float[] usedWeights = new float[weights.length];
        int[] slots = new int[weights.length];
        java.util.Arrays.fill(slots, -1);
        weightSlots.put(controller, slots);
        for (int i = 0; i < targetIds.length; i++) {
            Mesh target = usableTarget(targetInput, targetIds[i], base);
            if (target != null) {
                slots[i] = used.size();
                usedWeights[used.size()] = weights[i];
                used.add(target);
            }
        }
        return new Morph(controller.id(), controller.attr("name"), base, method, used,
                java.util.Arrays.copyOf(usedWeights, used.size()));
    }

    /** The morph's method attribute; NORMALIZED when absent or unknown (with a warning). */
    private Morph.Method method(XmlElement morph) {
        String methodName = morph.attr("method");
        Morph.Method method = Morph.Method.NORMALIZED;
        if (methodName != null) {
            try {
                method = Morph.Method.valueOf(methodName.trim().toUpperCase(Locale.ROOT));
            } catch (IllegalArgumentException e) {
                ctx.warn(morph, "method=\"" + methodName + "\" is neither NORMALIZED nor RELATIVE; read as NORMALIZED");
            }
        }
        return method;
    }

    /**
     * The mesh of the target named {@code id}, or null, with a warning, when it names no mesh or
     * one with fewer positions than the base (a target with more is used, and its extra positions
     * not).
     */
    private Mesh usableTarget(XmlElement targetInput, String id, Mesh base) {
        XmlElement g = ctx.byId(id);
        Mesh target = g == null ? null : meshes.get(g);
        if (target == null) {
            ctx.warn(targetInput, "morph target \"" + id + "\" is "
                    + (g == null ? "nothing in the file" : "no <geometry> with a <mesh>") + "; left out");
            return null;
        }
        if (target.positionCount() < base.positionCount()) {
            ctx.warn(targetInput, "morph target \"" + id + "\" has " + target.positionCount()
                    + " positions, the base " + base.positionCount() + "; left out");
            return null;
        }
        if (target.positionCount() > base.positionCount()) {
            ctx.warn(targetInput, "morph target \"" + id + "\" has " + target.positionCount()
                    + " positions, the base " + base.positionCount() + "; its first " + base.positionCount()
                    + " are used");
        }
        return target;
    }
}
