package org.skinlab.desktop;

import org.skinlab.desktop.cli.SkinlabCommand;

/** Entry point of the {@code skinlab} application. */
public final class SkinlabMain {
    private SkinlabMain() {
    }

    public static void main(String[] args) {
        System.exit(SkinlabCommand.run(args));
    }
}
