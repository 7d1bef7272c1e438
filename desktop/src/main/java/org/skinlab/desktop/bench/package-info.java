/**
 * The benchmarks behind the {@code skinlab bench}, {@code bench-render} and {@code eval} commands:
 * what they measure on (generated large files, the shared C++ reference's synthetic data, the
 * corpus of {@code --all-corpus}, the baselines: assimp, the thesis' loop, OpenCV's ArUco) and
 * how they measure (the frame, palette, crowd, render, parse, skinning and AR-frame timings, their
 * warm-up, and the {@code bench frame} table). Inputs and measuring share one package because
 * each input exists only for its timing and each timing reads its inputs' internals; neither
 * knows the command line ({@code org.skinlab.desktop.cli} parses options and prints, and
 * depends on this package, never the reverse).
 */
package org.skinlab.desktop.bench;
