package org.skinlab.android;

import static org.junit.Assert.assertTrue;

import java.io.File;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.OutputStream;

import android.graphics.Bitmap;
import android.graphics.Canvas;
import android.graphics.Color;
import android.graphics.Rect;
import android.os.Build;
import android.view.View;
import android.widget.Button;
import android.widget.HorizontalScrollView;
import android.widget.TextView;

import org.junit.After;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.robolectric.RobolectricTestRunner;
import org.robolectric.annotation.Config;
import org.robolectric.annotation.GraphicsMode;

/**
 * The app's screen as Android's own drawing code draws it (Robolectric's native graphics: the
 * platform's Skia on the JVM), written as a PNG for the documentation
 * ({@code android/build/screenshots/android-app-apiN.png}; docs/images/android-app.png is a copy):
 * the status line and the buttons with the five-clip humanoid walking with root motion. The camera
 * image and the model are drawn by OpenGL ES in the GLSurfaceView, which Robolectric does not
 * render: that part of the picture stays empty.
 */
@RunWith(RobolectricTestRunner.class)
@Config(minSdk = 26, shadows = ShadowPermissionRequestState.class, qualifiers = "w1340dp-h560dp-land-hdpi")
@GraphicsMode(GraphicsMode.Mode.NATIVE)
public class ScreenshotTest {
    private final AppDriver app = new AppDriver();

    @After
    public void finish() {
        app.finish();
    }

    @Test
    public void theScreenDrawsItsStatusLineAndButtons() throws IOException {
        app.start(true);
        for (int taps = 0; !app.status().endsWith("humanoid-moves.dae"); taps++) {
            assertTrue(taps < 10);
            app.tap("Next mesh");
            app.awaitStatus("a model loaded", s -> !s.contains("(loading)"));
        }
        app.awaitStatus("the clips read", s -> s.contains("| clip idle | "));
        app.awaitButton("Fade to lean");
        app.tap("Fade to lean");
        app.awaitButton("Fade to run");
        app.tap("Fade to run");
        app.awaitButton("Fade to walk");
        app.tap("Fade to walk");
        app.tap("Root motion: off");
        app.awaitStatus("walking with root motion", s -> s.contains("| clip walk | root motion | "));
        // The row scrolls sideways: the mixer's buttons into view.
        Button fade = app.button("Fade to");
        HorizontalScrollView row = (HorizontalScrollView) fade.getParent().getParent();
        row.scrollTo(fade.getLeft() - 2 * fade.getWidth(), 0);
        app.idle();

        View screen = app.activity().getWindow().getDecorView();
        Bitmap picture = Bitmap.createBitmap(screen.getWidth(), screen.getHeight(), Bitmap.Config.ARGB_8888);
        screen.draw(new Canvas(picture));
        File dir = new File(System.getProperty("skinlab.screenshots", "build/screenshots"));
        assertTrue(dir.isDirectory() || dir.mkdirs());
        File file = new File(dir, "android-app-api" + Build.VERSION.SDK_INT + ".png");
        try (OutputStream out = new FileOutputStream(file)) {
            assertTrue(picture.compress(Bitmap.CompressFormat.PNG, 100, out));
        }

        // Drawn for real: light text on the status line's dark band, and on the mixer's buttons.
        TextView status = null;
        for (TextView t : app.views(TextView.class)) {
            if (!(t instanceof Button) && t.getText().toString().contains(" fps | marker: ")) {
                status = t;
            }
        }
        assertTrue("text on the status line in " + file, lightPixels(picture, status) > 50);
        assertTrue("the cross-fade button drawn in " + file, inkPixels(picture, fade) > 50);
        assertTrue("the root motion button drawn in " + file, inkPixels(picture, app.button("Root motion: on")) > 50);
    }

    private static Rect onScreen(View v) {
        int[] at = new int[2];
        v.getLocationInWindow(at);
        return new Rect(at[0], at[1], at[0] + v.getWidth(), at[1] + v.getHeight());
    }

    /** Pixels within {@code v} bright enough to be white text on the dark status band. */
    private static int lightPixels(Bitmap picture, View v) {
        Rect r = onScreen(v);
        int n = 0;
        for (int y = Math.max(0, r.top); y < Math.min(picture.getHeight(), r.bottom); y++) {
            for (int x = Math.max(0, r.left); x < Math.min(picture.getWidth(), r.right); x++) {
                int c = picture.getPixel(x, y);
                n += Color.red(c) > 200 && Color.green(c) > 200 && Color.blue(c) > 200 ? 1 : 0;
            }
        }
        return n;
    }

    /** Pixels within {@code v} that differ from its most common colour (its background): its label, its edge. */
    private static int inkPixels(Bitmap picture, View v) {
        Rect r = onScreen(v);
        java.util.Map<Integer, Integer> counts = new java.util.HashMap<>();
        int total = 0;
        for (int y = Math.max(0, r.top); y < Math.min(picture.getHeight(), r.bottom); y++) {
            for (int x = Math.max(0, r.left); x < Math.min(picture.getWidth(), r.right); x++) {
                counts.merge(picture.getPixel(x, y), 1, Integer::sum);
                total++;
            }
        }
        int background = counts.values().stream().max(Integer::compare).orElse(0);
        return total - background;
    }
}
