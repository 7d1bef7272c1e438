package org.skinlab.desktop.app;

/** Lets tests in other packages run the command line as the window tests do. */
public final class ViewerWindowTestAccess {
    private ViewerWindowTestAccess() {
    }

    public static int run(String... args) {
        ViewerWindowTest.Run r = ViewerWindowTest.skinlab(args);
        if (r.status() != 0) {
            System.err.println(r);
        }
        return r.status();
    }
}
