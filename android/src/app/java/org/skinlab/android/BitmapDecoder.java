package org.skinlab.android;

import android.graphics.Bitmap;
import android.graphics.BitmapFactory;

import org.skinlab.android.logic.ModelTextures;
import org.skinlab.android.logic.TexturePixels;

/**
 * Decodes a model's PNG and JPEG pictures with Android's BitmapFactory (on the loader thread),
 * straight alpha, shrunk by powers of two until no side exceeds {@link ModelTextures#MAX_SIDE}.
 */
final class BitmapDecoder implements ModelTextures.Decoder {
    @Override
    public TexturePixels decode(byte[] encoded) {
        BitmapFactory.Options bounds = new BitmapFactory.Options();
        bounds.inJustDecodeBounds = true;
        BitmapFactory.decodeByteArray(encoded, 0, encoded.length, bounds);
        if (bounds.outWidth <= 0 || bounds.outHeight <= 0) {
            return null;
        }
        int sample = 1;
        while (bounds.outWidth / sample > ModelTextures.MAX_SIDE || bounds.outHeight / sample > ModelTextures.MAX_SIDE) {
            sample *= 2;
        }
        BitmapFactory.Options options = new BitmapFactory.Options();
        options.inSampleSize = sample;
        options.inPremultiplied = false;
        options.inPreferredConfig = Bitmap.Config.ARGB_8888;
        Bitmap bitmap = BitmapFactory.decodeByteArray(encoded, 0, encoded.length, options);
        if (bitmap == null) {
            return null;
        }
        int w = bitmap.getWidth();
        int h = bitmap.getHeight();
        int[] argb = new int[w * h];
        bitmap.getPixels(argb, 0, w, 0, 0, w, h); // straight ARGB whatever the bitmap stores
        bitmap.recycle();
        return TexturePixels.fromArgbTopRowFirst(w, h, argb);
    }
}
