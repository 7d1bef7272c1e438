package org.skinlab.android.logic;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.UncheckedIOException;

import javax.imageio.ImageIO;

/** The tests' stand-in for the app's BitmapFactory decoder: Java's ImageIO (an independent decoder). */
final class ImageIoDecoder implements ModelTextures.Decoder {
    @Override
    public TexturePixels decode(byte[] encoded) {
        try {
            BufferedImage image = ImageIO.read(new ByteArrayInputStream(encoded));
            if (image == null) {
                return null;
            }
            int w = image.getWidth();
            int h = image.getHeight();
            return TexturePixels.fromArgbTopRowFirst(w, h, image.getRGB(0, 0, w, h, null, 0, w));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
