/**
 * OpenGL 3.3 core drawing through LWJGL: the window ({@code GlWindow}), the model with GPU skinning
 * from a frame's palette in texture buffers ({@code ModelRenderer}, {@code GpuGeometry},
 * {@code PaletteBuffers}, {@code SkinningShader}), overlays, the AR camera background, textures and
 * screenshots (docs/desktop.md, "How it is built"). Depends on core and LWJGL; the shader texts are
 * resources, sharing core's GLSL includes.
 */
package org.skinlab.desktop.render;
