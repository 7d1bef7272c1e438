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
        /** Alpha is ignored: the surface is drawn fully opaque. */
        OPAQUE,
        /** A fragment is drawn, opaque, where alpha is at least {@link Material#alphaCutoff()}, else dropped. */
        MASK,
        /** The surface is blended over what is behind it with its alpha ({@link Material#opacity()}). */
        BLEND
    }

    /** The {@code profile_COMMON} shading models. */
    public enum Shading {
        /** Unlit: the emission colour only. */
        CONSTANT,
        /** Diffuse (Lambertian) lighting, plus the emission and ambient terms; no specular highlight. */
        LAMBERT,
        /** Lambert plus a Phong specular highlight (reflection vector) of exponent {@link Material#shininess()}. */
        PHONG,
        /** Lambert plus a Blinn-Phong specular highlight (half vector) of exponent {@link Material#shininess()}. */
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

    /**
     * The material's id (null for {@link #DEFAULT}).
     *
     * @return the id: COLLADA's {@code <material id>}, glTF's material symbol; or null
     */
    public String id() {
        return id;
    }

    /**
     * Its name attribute, else its id.
     *
     * @return the name to show ("default" for {@link #DEFAULT})
     */
    public String name() {
        return name;
    }

    /**
     * The {@code profile_COMMON} shading model ({@link Shading#LAMBERT} when the effect gives none;
     * glTF materials are LAMBERT, or CONSTANT when unlit).
     *
     * @return the shading model
     */
    public Shading shading() {
        return shading;
    }

    /**
     * A copy of the emission colour, or null.
     *
     * @return a new RGBA array of 4 floats the caller may change, or null
     */
    public float[] emission() {
        return copy(emission);
    }

    /**
     * The emission texture, or null.
     *
     * @return the texture the emission colour comes from, or null
     */
    public Texture emissionTexture() {
        return emissionTexture;
    }

    /**
     * The texture a renderer shows as the surface's colour: the diffuse texture, or, for
     * {@link Shading#CONSTANT} (unlit, emission only), the emission texture; null when none.
     *
     * @return the emission texture for constant shading, else the diffuse texture; or null
     */
    public Texture baseTexture() {
        return shading == Shading.CONSTANT ? emissionTexture : diffuseTexture;
    }

    /**
     * A copy of the ambient colour, or null.
     *
     * @return a new RGBA array of 4 floats the caller may change, or null
     */
    public float[] ambient() {
        return copy(ambient);
    }

    /**
     * A copy of the diffuse colour, or null (a texture, or none: constant shading).
     *
     * @return a new RGBA array of 4 floats the caller may change (glTF's {@code baseColorFactor}), or null
     */
    public float[] diffuse() {
        return copy(diffuse);
    }

    /**
     * The diffuse texture, or null.
     *
     * @return the texture the diffuse colour comes from (glTF's {@code baseColorTexture}), or null
     */
    public Texture diffuseTexture() {
        return diffuseTexture;
    }

    /**
     * A copy of the specular colour, or null (Phong and Blinn only).
     *
     * @return a new RGBA array of 4 floats the caller may change, or null
     */
    public float[] specular() {
        return copy(specular);
    }

    /**
     * The specular exponent (0 when the effect gives none).
     *
     * @return the exponent of the specular highlight, as written in the file
     */
    public float shininess() {
        return shininess;
    }

    /**
     * 0 (invisible) to 1 (opaque); see the class comment.
     *
     * @return the opacity, in [0, 1]; 1 unless the file makes the material transparent
     */
    public float opacity() {
        return opacity;
    }

    /**
     * How the base colour's alpha is used (BLEND unless the file says otherwise).
     *
     * @return the alpha mode, never null
     */
    public AlphaMode alphaMode() {
        return alphaMode;
    }

    /**
     * The alpha below which {@link AlphaMode#MASK} drops a fragment (0.5 unless the file says otherwise).
     *
     * @return the cutoff, finite and at least 0 (used only in MASK mode)
     */
    public float alphaCutoff() {
        return alphaCutoff;
    }

    /**
     * True when both faces are drawn lit (COLLADA has no such flag: true, as renderers drew it so
     * far); false when back faces are to be culled (glTF's default).
     *
     * @return whether back faces are drawn too
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

        /**
         * Starts a material with the defaults: {@link Shading#LAMBERT}, no colours or textures,
         * shininess 0, opacity 1, {@link AlphaMode#BLEND} with cutoff 0.5, double-sided.
         *
         * @param id   the material's id, or null
         * @param name the name to show (its name attribute, else its id)
         */
        public Builder(String id, String name) {
            this.id = id;
            this.name = name;
        }

        /**
         * Sets the shading model.
         *
         * @param s the shading model
         * @return this builder
         */
        public Builder shading(Shading s) {
            this.shading = s;
            return this;
        }

        /**
         * Sets the emission colour.
         *
         * @param rgba 4 floats, red green blue alpha; copied; or null for none
         * @return this builder
         * @throws IllegalArgumentException when {@code rgba} is not null and not of length 4
         */
        public Builder emission(float[] rgba) {
            this.emission = copy(rgba);
            return this;
        }

        /**
         * Sets the emission texture.
         *
         * @param t the texture, or null for none
         * @return this builder
         */
        public Builder emissionTexture(Texture t) {
            this.emissionTexture = t;
            return this;
        }

        /**
         * Sets the ambient colour.
         *
         * @param rgba 4 floats, red green blue alpha; copied; or null for none
         * @return this builder
         * @throws IllegalArgumentException when {@code rgba} is not null and not of length 4
         */
        public Builder ambient(float[] rgba) {
            this.ambient = copy(rgba);
            return this;
        }

        /**
         * Sets the diffuse colour.
         *
         * @param rgba 4 floats, red green blue alpha; copied; or null for none
         * @return this builder
         * @throws IllegalArgumentException when {@code rgba} is not null and not of length 4
         */
        public Builder diffuse(float[] rgba) {
            this.diffuse = copy(rgba);
            return this;
        }

        /**
         * Sets the diffuse texture.
         *
         * @param t the texture, or null for none
         * @return this builder
         */
        public Builder diffuseTexture(Texture t) {
            this.diffuseTexture = t;
            return this;
        }

        /**
         * Sets the specular colour.
         *
         * @param rgba 4 floats, red green blue alpha; copied; or null for none
         * @return this builder
         * @throws IllegalArgumentException when {@code rgba} is not null and not of length 4
         */
        public Builder specular(float[] rgba) {
            this.specular = copy(rgba);
            return this;
        }

        /**
         * Sets the specular exponent.
         *
         * @param s the exponent, as the file writes it
         * @return this builder
         */
        public Builder shininess(float s) {
            this.shininess = s;
            return this;
        }

        /**
         * Sets the opacity (see the class comment for how COLLADA's transparency gives it).
         *
         * @param o 0 (invisible) to 1 (opaque)
         * @return this builder
         * @throws IllegalArgumentException when {@code o} is not in [0, 1] (NaN included)
         */
        public Builder opacity(float o) {
            if (!(o >= 0f && o <= 1f)) {
                throw new IllegalArgumentException("opacity " + o + " is not in [0, 1]");
            }
            this.opacity = o;
            return this;
        }

        /**
         * Sets how the base colour's alpha is used.
         *
         * @param mode the alpha mode
         * @return this builder
         * @throws IllegalArgumentException when {@code mode} is null
         */
        public Builder alphaMode(AlphaMode mode) {
            if (mode == null) {
                throw new IllegalArgumentException("alpha mode is null");
            }
            this.alphaMode = mode;
            return this;
        }

        /**
         * Sets the alpha below which {@link AlphaMode#MASK} drops a fragment.
         *
         * @param cutoff the cutoff, a finite number at least 0
         * @return this builder
         * @throws IllegalArgumentException when {@code cutoff} is negative, infinite or NaN
         */
        public Builder alphaCutoff(float cutoff) {
            if (!(cutoff >= 0f) || Float.isInfinite(cutoff)) {
                throw new IllegalArgumentException("alpha cutoff " + cutoff + " is not a finite number >= 0");
            }
            this.alphaCutoff = cutoff;
            return this;
        }

        /**
         * Sets whether back faces are drawn too.
         *
         * @param both true to draw both faces lit, false to cull back faces
         * @return this builder
         */
        public Builder doubleSided(boolean both) {
            this.doubleSided = both;
            return this;
        }

        /**
         * Makes the material; the builder can go on to make others.
         *
         * @return a new immutable material with the values set so far
         */
        public Material build() {
            return new Material(this);
        }
    }
}
