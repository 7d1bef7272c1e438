package org.skinlab.desktop;

/**
 * The exit statuses of every skinlab command and of the window (a contract other tools rely on).
 *
 * <ul>
 * <li>0: success</li>
 * <li>1: an internal error (a bug: please report it with the file)</li>
 * <li>2: usage error (unknown option, missing argument, a path that does not exist, an output that
 * cannot be written there)</li>
 * <li>3: the file could not be imported (malformed, refused or inconsistent COLLADA, or unreadable)</li>
 * <li>4: unavailable: the machine lacks what the command needs (a display with OpenGL 3.3, a webcam, a
 * native library such as assimp's); not a bug</li>
 * </ul>
 * A command over several files ({@code inspect FILE...}) goes on after a file fails and returns
 * the most serious status at the end: 1 if any file hit an internal error, else 3 if any file
 * was refused; 2 only before anything was read.
 */
public final class ExitCodes {
    public static final int OK = 0;
    public static final int INTERNAL = 1;
    public static final int USAGE = 2;
    public static final int INVALID_FILE = 3;
    public static final int UNAVAILABLE = 4;

    private ExitCodes() {
    }
}
