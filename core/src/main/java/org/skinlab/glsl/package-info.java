/**
 * GLSL sources kept in core's resources, so that the desktop's OpenGL 3.3 shaders and the Android
 * app's OpenGL ES 3 shaders share one text per formula: {@code GlslInclude} reads a file and gives
 * the {@code #include "name"} line that puts it into a shader (GLSL itself has none). A leaf: it
 * depends on nothing of ours and on no GL binding.
 */
package org.skinlab.glsl;
