package org.skinlab.collada;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

import org.skinlab.model.Image;
import org.skinlab.model.Material;
import org.skinlab.model.Texture;

/**
 * Reads {@code <library_materials>} with their effects' {@code profile_COMMON} technique
 * ({@code <constant>}, {@code <lambert>}, {@code <phong>}, {@code <blinn>}) into
 * {@link Material}s, and the {@code <image>}s their textures sample.
 *
 * <p>A texture's {@code texture} attribute names a {@code <newparam>} holding a
 * {@code <sampler2D>}; in COLLADA 1.4.1 its {@code <source>} names a {@code <surface>}
 * newparam whose {@code <init_from>} is the image's id, in 1.5 it holds
 * {@code <instance_image url>}. Many exporters (Blender, SketchUp, older 3ds Max) write the
 * image's id straight into the {@code texture} attribute; that is understood too. A colour may
 * be given through {@code <param ref>} to a {@code float3}/{@code float4} newparam, whose value
 * the material may set with {@code <instance_effect><setparam>}.
 *
 * <p>Materials only decide how a mesh looks, so nothing here refuses a file: a dangling effect or
 * image, a missing {@code profile_COMMON}, an unreadable colour get a warning and are left out
 * (the renderer then uses its defaults). Image paths are resolved against the document's folder
 * ({@link DocumentLocation}); no file is opened.
 */
final class MaterialLoader {
    private static final Set<String> SHADINGS = Set.of("constant", "lambert", "phong", "blinn");

    private final ImportContext ctx;
    private final Map<XmlElement, Image> images = new LinkedHashMap<>();

    MaterialLoader(ImportContext ctx) {
        this.ctx = ctx;
    }

    /** One material per {@code <material>} of the libraries, in document order. */
    Map<XmlElement, Material> loadAll(XmlElement collada) {
        Map<XmlElement, Material> materials = new LinkedHashMap<>();
        for (XmlElement library : collada.children("library_materials")) {
            for (XmlElement material : library.children("material")) {
                materials.put(material, load(material));
            }
        }
        return materials;
    }

    /** The images the materials' textures use, in the order first used. */
    List<Image> images() {
        return new ArrayList<>(images.values());
    }

    private Material load(XmlElement material) {
        String name = material.attr("name") != null && !material.attr("name").isEmpty() ? material.attr("name")
                : material.id();
        Material.Builder b = new Material.Builder(material.id(), name);
        XmlElement instance = material.child("instance_effect");
        XmlElement effect = instance == null ? null : reference(instance, "url", "effect");
        if (effect == null) {
            if (instance == null) {
                ctx.warn(material, "has no <instance_effect>; drawn with the renderer's default look");
            }
            return b.build();
        }
        XmlElement profile = effect.child("profile_COMMON");
        XmlElement technique = profile == null ? null : profile.child("technique");
        XmlElement shading = null;
        if (technique != null) {
            for (XmlElement c : technique.children()) {
                if (SHADINGS.contains(c.name())) {
                    shading = c;
                    break;
                }
            }
        }
        if (shading == null) {
            ctx.warn(effect, "has no profile_COMMON <technique> with <constant>, <lambert>, <phong> or <blinn>;"
                    + " material \"" + name + "\" is drawn with the renderer's default look");
            return b.build();
        }
        Scope scope = new Scope(instance, effect, profile, technique);
        b.shading(Material.Shading.valueOf(shading.name().toUpperCase(Locale.ROOT)));
        b.emission(color(shading.child("emission"), scope));
        b.emissionTexture(texture(shading.child("emission"), scope));
        b.ambient(color(shading.child("ambient"), scope));
        XmlElement diffuse = shading.child("diffuse");
        b.diffuse(color(diffuse, scope));
        b.diffuseTexture(texture(diffuse, scope));
        b.specular(color(shading.child("specular"), scope));
        Float shininess = number(shading.child("shininess"), scope);
        b.shininess(shininess == null ? 0f : shininess);
        b.opacity(opacity(shading, scope, name));
        return b.build();
    }

    /**
     * Where a parameter is looked up: the material's {@code <instance_effect><setparam>}s first
     * (a material sets the value of an effect's parameter, e.g. its diffuse colour), then the
     * {@code <newparam>}s of the technique, the profile and the effect.
     */
    private static final class Scope {
        final XmlElement instance;
        final XmlElement[] levels;

        Scope(XmlElement instanceEffect, XmlElement effect, XmlElement profile, XmlElement technique) {
            this.instance = instanceEffect;
            this.levels = new XmlElement[] {technique, profile, effect};
        }

        /** The element holding the parameter's value ({@code <setparam>} or {@code <newparam>}), or null. */
        XmlElement newparam(String sid) {
            for (XmlElement p : instance.children("setparam")) {
                if (sid.equals(p.attr("ref"))) {
                    return p;
                }
            }
            for (XmlElement level : levels) {
                for (XmlElement p : level.children("newparam")) {
                    if (sid.equals(p.attr("sid"))) {
                        return p;
                    }
                }
            }
            return null;
        }
    }

    /** A reference that may dangle: the element, or null with a warning. */
    private XmlElement reference(XmlElement from, String attribute, String expected) {
        try {
            return ctx.resolve(from, attribute, expected);
        } catch (ColladaException e) {
            ctx.warn(from, e.problem() + "; ignored");
            return null;
        }
    }

    /** An RGBA colour from {@code <color>} or {@code <param ref>}; null when absent or unreadable. */
    private float[] color(XmlElement holder, Scope scope) {
        if (holder == null) {
            return null;
        }
        XmlElement value = holder.child("color");
        XmlElement param = holder.child("param");
        if (value == null && param != null) {
            XmlElement p = param.attr("ref") == null ? null : scope.newparam(param.attr("ref"));
            value = p == null ? null : p.child("float4") != null ? p.child("float4") : p.child("float3");
            if (value == null) {
                ctx.warn(param, "ref=\"" + param.attr("ref") + "\" names no float3 or float4 <newparam>; ignored");
                return null;
            }
        }
        if (value == null) {
            return null;
        }
        float[] v = floats(value);
        if (v == null) {
            return null;
        }
        if (v.length != 3 && v.length != 4) {
            ctx.warn(value, "has " + v.length + " values, expected 3 or 4 (RGB or RGBA); ignored");
            return null;
        }
        return v.length == 4 ? v : new float[] {v[0], v[1], v[2], 1f};
    }

    /** A float from {@code <float>} or {@code <param ref>}; null when absent or unreadable. */
    private Float number(XmlElement holder, Scope scope) {
        if (holder == null) {
            return null;
        }
        XmlElement value = holder.child("float");
        XmlElement param = holder.child("param");
        if (value == null && param != null && param.attr("ref") != null) {
            XmlElement p = scope.newparam(param.attr("ref"));
            value = p == null ? null : p.child("float");
        }
        float[] v = value == null ? null : floats(value);
        if (v == null || v.length != 1) {
            if (value != null && v != null) {
                ctx.warn(value, "has " + v.length + " values, expected 1; ignored");
            }
            return null;
        }
        return v[0];
    }

    /** The element's numbers, or null with a warning when they are not finite numbers. */
    private float[] floats(XmlElement value) {
        try {
            return NumberParser.floats(ctx, value, -1);
        } catch (ColladaException e) {
            ctx.warn(value, e.problem() + "; ignored");
            return null;
        }
    }

    /** The texture a colour holder ({@code <diffuse>}, {@code <emission>}) holds, or null. */
    private Texture texture(XmlElement holder, Scope scope) {
        XmlElement texture = holder == null ? null : holder.child("texture");
        if (texture == null) {
            return null;
        }
        String sampler = texture.attr("texture");
        XmlElement image = sampler == null ? null : imageOf(sampler, scope);
        if (image == null) {
            ctx.warn(texture, "texture=\"" + sampler + "\" names no sampler2D <newparam> (or <image>) that leads to"
                    + " an image; the texture is left out");
            return null;
        }
        return new Texture(image(image), texture.attr("texcoord"));
    }

    /** The {@code <image>} a texture's sampler leads to, or null. */
    private XmlElement imageOf(String sampler, Scope scope) {
        XmlElement param = scope.newparam(sampler);
        XmlElement sampler2d = param == null ? null : param.child("sampler2D");
        if (sampler2d != null) {
            XmlElement instanceImage = sampler2d.child("instance_image"); // COLLADA 1.5
            if (instanceImage != null) {
                return reference(instanceImage, "url", "image");
            }
            XmlElement source = sampler2d.child("source");
            XmlElement surface = source == null ? null : scope.newparam(source.text().trim());
            XmlElement surfaceElement = surface == null ? null : surface.child("surface");
            XmlElement initFrom = surfaceElement == null ? null : surfaceElement.child("init_from");
            if (initFrom != null) {
                return imageById(initFrom.text().trim());
            }
            return null;
        }
        return imageById(sampler); // the image's id written straight into texture=""
    }

    private XmlElement imageById(String id) {
        XmlElement e = ctx.byId(ImportContext.idPart(id));
        return e != null && e.name().equals("image") ? e : null;
    }

    /** The model's image for an {@code <image>} element (one per element). */
    private Image image(XmlElement image) {
        Image known = images.get(image);
        if (known != null) {
            return known;
        }
        XmlElement initFrom = image.child("init_from");
        String uri = null;
        if (initFrom != null) {
            XmlElement ref = initFrom.child("ref"); // COLLADA 1.5
            uri = (ref != null ? ref.text() : initFrom.text()).trim();
        }
        java.nio.file.Path file = null;
        if (uri == null || uri.isEmpty()) {
            ctx.warn(image, "names no file (embedded or generated images are not supported)");
            uri = null;
        } else {
            file = ctx.location.resolve(uri);
            if (file == null) {
                ctx.warn(image, "init_from \"" + uri + "\" is not a file path; the texture cannot be loaded");
            }
        }
        Image result = new Image(image.id(), image.attr("name"), uri, file);
        images.put(image, result);
        return result;
    }

    /**
     * Opacity from {@code <transparent>} and {@code <transparency>} (see {@link Material}). A
     * material the rule makes fully invisible is almost always an exporter that wrote
     * transparency 0 for "opaque" (or 1 with the opposite mode): it is read as opaque, warned.
     */
    private float opacity(XmlElement shading, Scope scope, String name) {
        XmlElement transparentElement = shading.child("transparent");
        float[] transparent = color(transparentElement, scope);
        Float transparency = number(shading.child("transparency"), scope);
        if (transparent == null && transparency == null) {
            return 1f;
        }
        float t = transparency == null ? 1f : transparency;
        String mode = transparentElement == null || transparentElement.attr("opaque") == null ? "A_ONE"
                : transparentElement.attr("opaque").trim();
        float[] c = transparent == null ? new float[] {0f, 0f, 0f, 1f} : transparent;
        double luminance = 0.212671 * c[0] + 0.715160 * c[1] + 0.072169 * c[2];
        double opacity;
        switch (mode) {
            case "RGB_ZERO":
                opacity = 1 - luminance * t;
                break;
            case "A_ZERO":
                opacity = 1 - c[3] * t;
                break;
            case "RGB_ONE":
                opacity = luminance * t;
                break;
            default:
                opacity = c[3] * t;
                break;
        }
        opacity = Math.max(0, Math.min(1, opacity));
        if (opacity == 0) {
            // 3ds Max, FBX, MeshLab, Blender add-ons all write this: one warning per file says it.
            ctx.warnOnce("invisible-material", shading, "material \"" + name + "\" (and maybe others) would be fully"
                    + " transparent by the specification's rule (" + mode + ", transparency " + t + "); read as opaque,"
                    + " as exporters that write this mean");
            return 1f;
        }
        return (float) opacity;
    }
}
