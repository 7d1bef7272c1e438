/**
 * The simulating component (thesis section 5.6): {@link org.skinlab.simulation.SkeletalAnimatedMesh}
 * plays a model's clip on its own thread and publishes whole frames (each step's joint palette
 * for GPU skinning and, unless palette-only, the CPU-skinned mesh) that renderers read without
 * locks; {@link org.skinlab.simulation.AnimationConfig} holds the user's switches, changeable from
 * any thread at any moment. Below it, {@code org.skinlab.skinning} does the per-frame work; above
 * it, presenters (desktop, Android) only read frames and flip switches. See
 * {@code docs/architecture.md}, "Simulation thread and snapshots".
 */
package org.skinlab.simulation;
