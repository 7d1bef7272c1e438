/**
 * The skeleton and clips at run time: {@code Skeleton} flattens a model's node hierarchy and
 * evaluates world and skinning matrices parents first, {@code AnimationSampler} and
 * {@code MorphWeightSampler} sample a clip's channels from flat arrays, {@code BindPose} places
 * every joint at its bind frame instead, {@code AnimationHelper} and
 * {@code DualQuaternion} hold the rotation and dual-quaternion math (docs/animation.md). Depends on
 * {@code org.skinlab.model} and JOML only; the per-frame calls allocate nothing.
 */
package org.skinlab.animation;
