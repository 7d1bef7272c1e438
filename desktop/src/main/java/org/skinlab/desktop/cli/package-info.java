/**
 * The skinlab command line (picocli). Output formats and exit statuses ({@link
 * org.skinlab.desktop.ExitCodes}) are contracts other tools rely on: change them only
 * by adding fields.
 */
package org.skinlab.desktop.cli;

