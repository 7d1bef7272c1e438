package org.skinlab.model;

/**
 * A {@code <material>} with its effect's {@code profile_COMMON} technique read: the shading model,
 * its colours and textures, shininess and opacity. Colours are RGBA (alpha 1 where the file gives
 * RGB); a colour the effect does not give is null, and so is a texture.
 *
 * <p>Opacity follows COLLADA 1.4.1's "Determining transparency" (and 1.5's two further modes):
 * with {@code <transparent opaque="A_ONE">} (the default) it is {@code transparent.a * transparency};
 * RGB_ZERO: {@code 1 - luminance(transparent.rgb) * transparency}; A_ZERO:
 * {@code 1 - transparent.a * transparency}; RGB_ONE: {@code luminance(transparent.rgb) * transparency};
 * 1 when the effect gives neither.
 */
public final class Material {
    /**
     * How a renderer treats the base colour's alpha (glTF's {@code alphaMode}): OPAQUE ignores it,
     * MASK draws a fragment only where alpha reaches {@link #alphaCutoff()}, BLEND blends with
     * {@link #opacity()}. COLLADA materials are BLEND (their opacity is blended as before).
     */
    public enum AlphaMode {
        OPAQUE, MASK, BLEND
    }

    /** The {@code profile_COMMON} shading models. */
    public enum Shading {
        /** Unlit: the emission colour only. */
        CONSTANT,
        LAMBERT,
        PHONG,
        BLINN
    }

    /** What a renderer draws for a symbol no material is bound to (a plain grey Lambert). */
    public static final Material DEFAULT = new Builder(null, "default").shading(Shading.LAMBERT)
            .diffuse(new float[] {0.8f, 0.8f, 0.8f, 1f}).build();

    private final String id;
    private final String name;
    private final Shading shading;
    private final float[] emission;
    private final Texture emissionTexture;
    private final float[] ambient;
    private final float[] diffuse;
    private final Texture diffuseTexture;
    private final float[] specular;
    private final float shininess;
    private final float opacity;
    private final AlphaMode alphaMode;
    private final float alphaCutoff;
    private final boolean doubleSided;

    private Material(Builder b) {
        this.id = b.id;
        this.name = b.name;
        this.shading = b.shading;
        this.emission = copy(b.emission);
        this.emissionTexture = b.emissionTexture;
        this.ambient = copy(b.ambient);
        this.diffuse = copy(b.diffuse);
        this.diffuseTexture = b.diffuseTexture;
        this.specular = copy(b.specular);
        this.shininess = b.shininess;
        this.opacity = b.opacity;
        this.alphaMode = b.alphaMode;
        this.alphaCutoff = b.alphaCutoff;
        this.doubleSided = b.doubleSided;
    }

    private static float[] copy(float[] rgba) {
        if (rgba != null && rgba.length != 4) {
            throw new IllegalArgumentException("colours are RGBA");
        }
        return rgba == null ? null : rgba.clone();
    }

    /** The material's id (null for {@link #DEFAULT}). */
    public String id() {
        return id;
    }

    /** Its name attribute, else its id. */
    public String name() {
        return name;
    }

    public Shading shading() {
        return shading;
    }

    /** A copy of the emission colour, or null. */
    public float[] emission() {
        return copy(emission);
    }

    /** The emission texture, or null. */
    public Texture emissionTexture() {
        return emissionTexture;
    }

    /**
     * The texture a renderer shows as the surface's colour: the diffuse texture, or, for
     * {@link Shading#CONSTANT} (unlit, emission only), the emission texture; null when none.
     */
    public Texture baseTexture() {
        return shading == Shading.CONSTANT ? emissionTexture : diffuseTexture;
    }

    /** A copy of the ambient colour, or null. */
    public float[] ambient() {
        return copy(ambient);
    }

    /** A copy of the diffuse colour, or null (a texture, or none: constant shading). */
    public float[] diffuse() {
        return copy(diffuse);
    }

    /** The diffuse texture, or null. */
    public Texture diffuseTexture() {
        return diffuseTexture;
    }

    /** A copy of the specular colour, or null (Phong and Blinn only). */
    public float[] specular() {
        return copy(specular);
    }

    /** The specular exponent (0 when the effect gives none). */
    public float shininess() {
        return shininess;
    }

    /** 0 (invisible) to 1 (opaque); see the class comment. */
    public float opacity() {
        return opacity;
    }

    /** How the base colour's alpha is used (BLEND unless the file says otherwise). */
    public AlphaMode alphaMode() {
        return alphaMode;
    }

    /** The alpha below which {@link AlphaMode#MASK} drops a fragment (0.5 unless the file says otherwise). */
    public float alphaCutoff() {
        return alphaCutoff;
    }

    /**
     * True when both faces are drawn lit (COLLADA has no such flag: true, as renderers drew it so
     * far); false when back faces are to be culled (glTF's default).
     */
    public boolean doubleSided() {
        return doubleSided;
    }

    @Override
    public String toString() {
        return "Material[" + name + ", " + shading + (diffuseTexture != null ? ", texture " + diffuseTexture.image().id()
                : diffuse != null ? ", diffuse " + java.util.Arrays.toString(diffuse) : "") + "]";
    }

    /** Builds a material; colours are RGBA and copied. */
    public static final class Builder {
        private final String id;
        private final String name;
        private Shading shading = Shading.LAMBERT;
        private float[] emission;
        private Texture emissionTexture;
        private float[] ambient;
        private float[] diffuse;
        private Texture diffuseTexture;
        private float[] specular;
        private float shininess;
        private float opacity = 1f;
        private AlphaMode alphaMode = AlphaMode.BLEND;
        private float alphaCutoff = 0.5f;
        private boolean doubleSided = true;

        public Builder(String id, String name) {
            this.id = id;
            this.name = name;
        }

        public Builder shading(Shading s) {
            this.shading = s;
            return this;
        }

        public Builder emission(float[] rgba) {
            this.emission = copy(rgba);
            return this;
        }

        public Builder emissionTexture(Texture t) {
            this.emissionTexture = t;
            return this;
        }

        public Builder ambient(float[] rgba) {
            this.ambient = copy(rgba);
            return this;
        }

        public Builder diffuse(float[] rgba) {
            this.diffuse = copy(rgba);
            return this;
        }

        public Builder diffuseTexture(Texture t) {
            this.diffuseTexture = t;
            return this;
        }

        public Builder specular(float[] rgba) {
            this.specular = copy(rgba);
            return this;
        }

        public Builder shininess(float s) {
            this.shininess = s;
            return this;
        }

        public Builder opacity(float o) {
            if (!(o >= 0f && o <= 1f)) {
                throw new IllegalArgumentException("opacity " + o + " is not in [0, 1]");
            }
            this.opacity = o;
            return this;
        }

        public Builder alphaMode(AlphaMode mode) {
            if (mode == null) {
                throw new IllegalArgumentException("alpha mode is null");
            }
            this.alphaMode = mode;
            return this;
        }

        public Builder alphaCutoff(float cutoff) {
            if (!(cutoff >= 0f) || Float.isInfinite(cutoff)) {
                throw new IllegalArgumentException("alpha cutoff " + cutoff + " is not a finite number >= 0");
            }
            this.alphaCutoff = cutoff;
            return this;
        }

        public Builder doubleSided(boolean both) {
            this.doubleSided = both;
            return this;
        }

        public Material build() {
            return new Material(this);
        }
    }
}
