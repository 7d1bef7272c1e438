/**
 * The skinlab command line (picocli) and its entry point, {@code SkinlabMain}: commands that parse
 * options and print; what the benchmark commands measure lives in {@link org.skinlab.desktop.bench},
 * the evaluation's report in {@link org.skinlab.desktop.eval}. Output formats and exit statuses
 * ({@link org.skinlab.desktop.ExitCodes}) are contracts other tools rely on: change them only by
 * adding fields.
 */
package org.skinlab.desktop.cli;
