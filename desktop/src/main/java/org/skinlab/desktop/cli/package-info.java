/**
 * The skinlab command line (picocli): commands that parse options and print; what the benchmark
 * commands measure lives in {@link org.skinlab.desktop.bench}. Output formats and exit statuses
 * ({@link org.skinlab.desktop.ExitCodes}) are contracts other tools rely on: change them only by
 * adding fields.
 */
package org.skinlab.desktop.cli;
