package org.skinlab.internal.scene;

/** Which of our assets every presenter opens first: the one home of that rule. */
public final class DefaultAsset {
    /** The default character, relative to the repository's {@code assets/} folder. */
    public static final String PATH = "characters/humanoid-walk.dae";

    private DefaultAsset() {
    }

    /** The file name alone ("humanoid-walk.dae"), as bundles that flatten folders store it. */
    public static String fileName() {
        return PATH.substring(PATH.lastIndexOf('/') + 1);
    }
}
