package org.skinlab.collada;

import java.util.List;
import java.util.Map;

import org.skinlab.model.KeyframeTrack;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Morph;
import org.skinlab.model.MorphWeightChannel;

/**
 * Channels on a morph controller's weights: a target that names the controller's MORPH_WEIGHT
 * {@code <source>} (or its {@code <float_array>}) by id, whole ({@code smile-weights}) or one
 * weight ({@code smile-weights(1)}), as Blender ({@code Ob-morph-weights(i)}) and OpenCOLLADA
 * write them. Each becomes one {@link MorphWeightChannel} per instance that draws the morph
 * (weights are the controller's, so every instance follows them). Weights of targets the morph
 * left out ({@link MorphLoader}) are skipped with a warning.
 */
final class MorphWeightTargets {
    private final ImportContext ctx;
    private final Map<XmlElement, Morph> morphs;
    private final MorphLoader loader;
    private final List<MeshInstance> instances;
    private final SamplerReader samplers;

    MorphWeightTargets(ImportContext ctx, Map<XmlElement, Morph> morphsByController, MorphLoader loader,
            List<MeshInstance> instances, SamplerReader samplers) {
        this.ctx = ctx;
        this.morphs = morphsByController;
        this.loader = loader;
        this.instances = instances;
        this.samplers = samplers;
    }

    /**
     * Reads the channel into {@code out} when its target names morph weights; false (nothing
     * read) when it names something else.
     */
    boolean read(XmlElement channel, String target, XmlElement sampler, List<MorphWeightChannel> out)
            throws ColladaException {
        int open = target.indexOf('(');
        XmlElement controller = controllerOfWeights(open < 0 ? target : target.substring(0, open));
        if (controller == null) {
            return false;
        }
        Morph morph = morphs.get(controller);
        int[] slots = loader.weightSlots(controller);
        if (morph == null || slots == null) {
            ctx.warn(channel, "target=\"" + target + "\" skipped: the morph draws nothing (its base is no mesh)");
            return true;
        }
        int[] range = range(target.substring(open < 0 ? target.length() : open), slots.length);
        if (range == null) {
            ctx.warn(channel, "target=\"" + target + "\" skipped: it selects no weight of the " + slots.length);
            return true;
        }
        int first = slots[range[0]];
        for (int i = 1; i < range[1]; i++) {
            if (slots[range[0] + i] != first + i) {
                first = -1;
            }
        }
        if (first < 0) {
            ctx.warn(channel, "target=\"" + target + "\" skipped: it animates the weight of a target left out");
            return true;
        }
        KeyframeTrack track = samplers.track(sampler, range[1], false, false);
        if (track.keyCount() == 0) {
            ctx.warn(channel, "target=\"" + target + "\" skipped: its sampler has no keys");
            return true;
        }
        int before = out.size();
        for (int i = 0; i < instances.size(); i++) {
            if (instances.get(i).mesh() == morph.result()) {
                out.add(new MorphWeightChannel(i, first, track, target));
            }
        }
        if (out.size() == before) {
            // A morph only used as another morph's base (or not instanced) has no instance of its own.
            ctx.warn(channel, "target=\"" + target + "\" skipped: no instance draws this morph itself"
                    + " (animated weights of a morph under another morph are not supported)");
        }
        return true;
    }

    /** The morph controller whose MORPH_WEIGHT source (or its array) has this id, or null. */
    private XmlElement controllerOfWeights(String id) {
        XmlElement e = ctx.byId(id);
        if (e != null && e.name().equals("float_array")) {
            e = e.parent();
        }
        if (e == null || !e.name().equals("source") || e.parent() == null || !e.parent().name().equals("morph")) {
            return null;
        }
        XmlElement morph = e.parent();
        XmlElement targets = morph.child("targets");
        for (XmlElement input : targets == null ? List.<XmlElement>of() : targets.children("input")) {
            if ("MORPH_WEIGHT".equals(input.attr("semantic")) && ("#" + e.id()).equals(input.attr("source"))) {
                return morph.parent();
            }
        }
        return null;
    }

    /** {first weight, count} of a selector: empty for all, {@code (i)} for one; null otherwise. */
    private static int[] range(String selector, int weights) {
        if (selector.isEmpty()) {
            return weights == 0 ? null : new int[] {0, weights};
        }
        if (!selector.endsWith(")") || selector.indexOf(')') != selector.length() - 1) {
            return null;
        }
        try {
            int i = Integer.parseInt(selector.substring(1, selector.length() - 1).trim());
            return i >= 0 && i < weights ? new int[] {i, 1} : null;
        } catch (NumberFormatException e) {
            return null;
        }
    }
}
