package org.skinlab.desktop;

/**
 * A command, or the benchmark or file search it runs, failed in an expected way: print the message
 * on one line, exit with the status (one of {@link ExitCodes}).
 */
public final class CommandFailure extends RuntimeException {
    private static final long serialVersionUID = 1L;
    private final int status;

    public CommandFailure(int status, String message, Throwable cause) {
        super(message, cause);
        this.status = status;
    }

    public int status() {
        return status;
    }
}
