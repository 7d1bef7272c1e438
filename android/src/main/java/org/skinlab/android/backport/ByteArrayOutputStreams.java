package org.skinlab.android.backport;

import java.io.ByteArrayOutputStream;
import java.nio.charset.Charset;

/**
 * {@code ByteArrayOutputStream.toString(Charset)} (Java 10, Android API 33) for Android 8: R8
 * rewrites every call to that method in the APK (EJML's matrix {@code toString()}s make them) into a
 * call to {@link #toString(ByteArrayOutputStream, Charset)} (android/backports.json).
 */
public final class ByteArrayOutputStreams {
    private ByteArrayOutputStreams() {
    }

    /**
     * What {@code out.toString(charset)} returns: the bytes decoded with the charset, malformed and
     * unmappable input replaced by the charset's replacement (as {@code new String(bytes, charset)}).
     */
    public static String toString(ByteArrayOutputStream out, Charset charset) {
        return new String(out.toByteArray(), charset);
    }
}
