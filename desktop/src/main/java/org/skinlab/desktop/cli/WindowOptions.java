package org.skinlab.desktop.cli;

import java.nio.file.Path;
import java.util.Locale;

import org.skinlab.desktop.app.AppOptions;
import org.skinlab.skinning.SkinningMethod;

import picocli.CommandLine;
import picocli.CommandLine.Option;

/**
 * The options of the viewer window that {@code view} and {@code ar} share (a picocli mixin):
 * the method at start, the screenshot, the size, the toolbar and the script.
 * {@code --exit-after-frames} stays with each command, whose help says what the last frame means
 * there.
 */
final class WindowOptions {
    @Option(names = "--method", paramLabel = MethodKeys.KEYS, converter = MethodKeys.Converter.class,
            description = "skinning method at start (default: lbs)")
    SkinningMethod method = SkinningMethod.LBS;

    @Option(names = "--screenshot", paramLabel = "OUT.png",
            description = "render one frame off-screen, write it as PNG and exit")
    Path screenshot;

    @Option(names = "--size", paramLabel = "WxH", converter = SizeConverter.class,
            description = "window or screenshot size in pixels (default: 1280x800)")
    Size size = new Size(AppOptions.DEFAULT_WIDTH, AppOptions.DEFAULT_HEIGHT);

    @Option(names = "--hide-ui", description = "draw the scene only, without the toolbar")
    boolean hideUi;

    @Option(names = "--script", paramLabel = "FILE", description = "replay UI actions from FILE (docs/desktop.md)")
    Path script;

    /** A window or picture size in pixels. */
    record Size(int width, int height) {
    }

    static final class SizeConverter implements CommandLine.ITypeConverter<Size> {
        @Override
        public Size convert(String value) {
            String[] parts = value.toLowerCase(Locale.ROOT).split("x");
            try {
                if (parts.length == 2) {
                    int w = Integer.parseInt(parts[0].trim());
                    int h = Integer.parseInt(parts[1].trim());
                    if (w >= 16 && h >= 16 && w <= 16384 && h <= 16384) {
                        return new Size(w, h);
                    }
                }
            } catch (NumberFormatException e) {
                // reported below
            }
            throw new CommandLine.TypeConversionException("'" + value + "' is not a size (expected WxH, e.g. 1280x800, "
                    + "16 to 16384 pixels each)");
        }
    }
}
