package org.skinlab.collada;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.skinlab.model.Material;
import org.skinlab.model.MaterialBinding;
import org.skinlab.model.Mesh;
import org.skinlab.model.MeshPart;

/**
 * Binds the material symbols of a placed mesh: {@code <bind_material><technique_common>
 * <instance_material symbol target>} to the materials {@link MaterialLoader} read, with the texture
 * coordinate set {@code <bind_vertex_input>} names. Materials are optional: nothing here refuses.
 */
final class MaterialBinder {
    private final ImportContext ctx;
    private final Map<XmlElement, Material> materials;

    MaterialBinder(ImportContext ctx, Map<XmlElement, Material> materialsByElement) {
        this.ctx = ctx;
        this.materials = materialsByElement;
    }

    /**
     * The materials an instance binds ({@code <bind_material><technique_common><instance_material>}),
     * and the texture coordinate set each one's {@link Material#baseTexture()} uses: the set its
     * {@code <bind_vertex_input>} names for the texture's {@code texcoord}, else the first. A
     * symbol of the mesh that nothing binds, or a binding to no material, is drawn with
     * {@link Material#DEFAULT}, warned.
     */
    List<MaterialBinding> bindings(XmlElement inst, Mesh mesh) {
        List<MaterialBinding> result = new ArrayList<>();
        XmlElement bind = inst.child("bind_material");
        XmlElement common = bind == null ? null : bind.child("technique_common");
        Set<String> bound = new HashSet<>();
        if (common != null) {
            Set<String> used = new HashSet<>();
            for (MeshPart part : mesh.parts()) {
                used.add(part.material());
            }
            for (XmlElement im : common.children("instance_material")) {
                String symbol = im.attr("symbol");
                if (symbol == null || !bound.add(symbol)) {
                    continue;
                }
                // A binding for a symbol the mesh does not use changes nothing, dangling or not.
                Material material = used.contains(symbol) ? material(im) : materialOrNull(im);
                if (material == null) {
                    continue;
                }
                result.add(new MaterialBinding(symbol, material, texCoordSet(im, material, mesh)));
            }
        }
        Set<String> unbound = new LinkedHashSet<>();
        for (MeshPart part : mesh.parts()) {
            if (part.material() != null && !bound.contains(part.material())) {
                unbound.add(part.material());
            }
        }
        if (!unbound.isEmpty()) {
            ctx.warn(inst, "material symbol" + (unbound.size() == 1 ? " " : "s ") + String.join(", ", unbound)
                    + " of mesh \"" + mesh.id() + "\" bound to no material; drawn with the default material");
        }
        return result;
    }

    /** The material an {@code <instance_material>} names, or null (no warning). */
    private Material materialOrNull(XmlElement instanceMaterial) {
        String target = instanceMaterial.attr("target");
        XmlElement e = target == null ? null : ctx.byId(ImportContext.idPart(target));
        return e == null ? null : materials.get(e);
    }

    /** The material an {@code <instance_material>} names, or null with a warning. */
    private Material material(XmlElement instanceMaterial) {
        try {
            return materials.get(ctx.resolve(instanceMaterial, "target", "material"));
        } catch (ColladaException e) {
            ctx.warn(instanceMaterial, e.problem() + "; drawn with the default material");
            return null;
        }
    }

    private int texCoordSet(XmlElement instanceMaterial, Material material, Mesh mesh) {
        if (material.baseTexture() == null || mesh.texCoordSetCount() == 0) {
            return -1;
        }
        String texcoord = material.baseTexture().texcoord();
        for (XmlElement b : instanceMaterial.children("bind_vertex_input")) {
            if (texcoord != null && texcoord.equals(b.attr("semantic"))
                    && (b.attr("input_semantic") == null || "TEXCOORD".equals(b.attr("input_semantic")))) {
                String set = b.attr("input_set");
                int number;
                try {
                    number = set == null ? mesh.texCoordSetNumber(0) : Integer.parseInt(set.trim());
                } catch (NumberFormatException e) {
                    number = Integer.MIN_VALUE;
                }
                int index = mesh.texCoordSetIndex(number);
                if (index < 0) {
                    ctx.warn(b, "input_set=\"" + set + "\" is no texture coordinate set of mesh \"" + mesh.id()
                            + "\"; the first set is used");
                    return 0;
                }
                return index;
            }
        }
        return 0;
    }
}
