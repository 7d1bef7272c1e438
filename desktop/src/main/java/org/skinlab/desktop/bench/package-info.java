/** Inputs for the benchmarks of the {@code skinlab bench} commands, e.g. generated large files. */
package org.skinlab.desktop.bench;
