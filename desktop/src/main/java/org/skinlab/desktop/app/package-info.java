/**
 * The viewer window's render loop ({@code SkinlabApp}: one simulation frame per iteration, drawn
 * whole by {@code ScenePainter}), its input, scripted UI replay ({@code UiScript},
 * {@code ScriptPlayer}) and the AR mode ({@code ArPresenter}, {@code ArSetup}); docs/desktop.md.
 * Depends on core, {@code org.skinlab.desktop.viewer}, {@code .render}, {@code .ui} and
 * {@code .ar}, and LWJGL.
 */
package org.skinlab.desktop.app;
