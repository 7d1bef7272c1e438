/**
 * The {@code skinlab} application's entry point ({@code SkinlabMain}, which hands the arguments to
 * the picocli commands of {@code org.skinlab.desktop.cli}) and the exit statuses every command and
 * the window share ({@code ExitCodes}; docs/cli.md, "Exit statuses").
 */
package org.skinlab.desktop;
