package org.skinlab.internal.synthetic;

/**
 * How a synthetic frame is degraded, as a camera would.
 *
 * @param blurSigma      Gaussian blur (defocus, motion) in pixels; 0 for none
 * @param noiseSigma     Gaussian sensor noise in gray levels; 0 for none
 * @param gradient       lighting falloff across the image: the far side is {@code 1 - gradient}
 *                       as bright as the near side (0 for even light, up to 0.9)
 * @param clutter        how many things a detector may mistake for markers (dark boxes, squares
 *                       of random bits, other codes, checkerboards, text: {@link Background}) on
 *                       the background
 * @param supersampling  samples per pixel side (4: 16 samples per pixel)
 * @param seed           the noise, clutter, background and gradient direction
 */
public record SceneOptions(double blurSigma, double noiseSigma, double gradient, int clutter, int supersampling,
        long seed) {

    public SceneOptions {
        if (blurSigma < 0 || noiseSigma < 0 || !(gradient >= 0 && gradient <= 0.9) || clutter < 0
                || supersampling < 1 || supersampling > 16) {
            throw new IllegalArgumentException("bad scene options: " + blurSigma + ", " + noiseSigma + ", " + gradient
                    + ", " + clutter + ", " + supersampling);
        }
    }

    /** A sharp, noise-free, evenly lit frame (4x4 samples per pixel). */
    public static SceneOptions clean(long seed) {
        return new SceneOptions(0, 0, 0, 0, 4, seed);
    }

    /** A typical phone frame: slight blur (0.8 px), noise (sigma 3), 30% light falloff. */
    public static SceneOptions camera(long seed) {
        return new SceneOptions(0.8, 3, 0.3, 0, 4, seed);
    }

    public SceneOptions withBlur(double sigma) {
        return new SceneOptions(sigma, noiseSigma, gradient, clutter, supersampling, seed);
    }

    public SceneOptions withNoise(double sigma) {
        return new SceneOptions(blurSigma, sigma, gradient, clutter, supersampling, seed);
    }

    public SceneOptions withGradient(double g) {
        return new SceneOptions(blurSigma, noiseSigma, g, clutter, supersampling, seed);
    }

    public SceneOptions withClutter(int count) {
        return new SceneOptions(blurSigma, noiseSigma, gradient, count, supersampling, seed);
    }

    public SceneOptions withSeed(long s) {
        return new SceneOptions(blurSigma, noiseSigma, gradient, clutter, supersampling, s);
    }
}
