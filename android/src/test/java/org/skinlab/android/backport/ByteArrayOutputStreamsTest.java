package org.skinlab.android.backport;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayOutputStream;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;

import org.junit.jupiter.api.Test;

/** The backport returns what the JDK's ByteArrayOutputStream.toString(Charset) returns. */
class ByteArrayOutputStreamsTest {
    @Test
    void sameStringAsTheJdkForValidMalformedAndUnmappableInput() {
        byte[][] inputs = {
            "matrix 3 x 3\n 1.000  0.000".getBytes(StandardCharsets.UTF_8),
            "größe µ €".getBytes(StandardCharsets.UTF_8),
            {(byte) 0xC3, (byte) 0x28, 'a', (byte) 0xF0, (byte) 0x9F}, // malformed UTF-8: replaced
            {},
        };
        for (Charset charset : new Charset[] {StandardCharsets.UTF_8, StandardCharsets.US_ASCII,
                StandardCharsets.ISO_8859_1, StandardCharsets.UTF_16}) {
            for (byte[] input : inputs) {
                ByteArrayOutputStream out = new ByteArrayOutputStream();
                out.writeBytes(input);
                assertEquals(out.toString(charset), ByteArrayOutputStreams.toString(out, charset), charset.name());
            }
        }
    }
}
