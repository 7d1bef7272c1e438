/**
 * What several desktop packages share: the exit statuses every command and the window use
 * ({@code ExitCodes}; docs/cli.md, "Exit statuses"), an expected failure and its status
 * ({@code CommandFailure}), the model files a command names ({@code ModelFiles},
 * {@code ModelFileSearch}) and the Java runtime's description ({@code JavaRuntime}). The entry
 * point, {@code SkinlabMain}, is in {@link org.skinlab.desktop.cli}.
 */
package org.skinlab.desktop;
