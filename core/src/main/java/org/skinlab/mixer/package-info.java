/**
 * Directing a character rather than playing one clip: layers of clips blended in local
 * translation, rotation and scale ({@link org.skinlab.mixer.Mixer}), each with a weight, a
 * per-joint mask ({@link org.skinlab.mixer.JointMask}), its own clock and an override or additive
 * mode ({@link org.skinlab.mixer.Layer}); cross-fades, optionally synchronised by phase; 1-D and
 * 2-D blend spaces ({@link org.skinlab.mixer.BlendSpace}); root motion. The rules, and how they
 * compare with three.js' {@code AnimationMixer}, are in docs/animation.md ("Directing a
 * character").
 */
package org.skinlab.mixer;
