package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;

/**
 * The valid document the robustness tests break ({@code fixtures/robustness/skinned-quad.dae}):
 * each bad-input case is this text with one visible change.
 */
final class QuadFixture {
    static final String NAME = "robustness/skinned-quad.dae";

    private static final String TEXT = load();

    private QuadFixture() {
    }

    /** The unchanged document. */
    static String text() {
        return TEXT;
    }

    /**
     * The document with {@code from} replaced by {@code to}; {@code from} must occur exactly once
     * so that every case says unambiguously what it breaks.
     */
    static String with(String from, String to) {
        int at = TEXT.indexOf(from);
        assertEquals(true, at >= 0 && TEXT.indexOf(from, at + 1) < 0,
                () -> "the fixture must contain exactly one \"" + from + "\"");
        return TEXT.substring(0, at) + to + TEXT.substring(at + from.length());
    }

    private static String load() {
        try (InputStream in = QuadFixture.class.getResourceAsStream("/fixtures/" + NAME)) {
            if (in == null) {
                throw new IllegalStateException("fixture " + NAME + " not on the test class path");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
