/**
 * The window's Dear ImGui panels (imgui-java, with ImPlot): the thesis' toolbar, the live numbers
 * and their plots, the mixer panel that directs the character, the help panel with every key, the
 * status line. Each draws from the frame the
 * app hands it and reports clicks as actions; depends on core, imgui-java and the app, viewer and
 * render packages of the desktop.
 */
package org.skinlab.desktop.ui;
