package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;

import org.skinlab.model.Model;

/** Imports hand-made fixtures: from a string or from {@code src/test/resources/fixtures/}. */
public final class Fixtures {
    private Fixtures() {
    }

    /** Imports a document given as text (UTF-8). */
    public static Model read(String name, String xml) {
        try {
            return ColladaImporter.read(new ByteArrayInputStream(xml.getBytes(StandardCharsets.UTF_8)), name);
        } catch (ColladaException e) {
            return fail("unexpected import error: " + e.getMessage(), e);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Imports {@code src/test/resources/fixtures/<name>}. */
    public static Model resource(String name) {
        try (InputStream in = open(name)) {
            return ColladaImporter.read(in, name);
        } catch (ColladaException e) {
            return fail("unexpected import error: " + e.getMessage(), e);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Asserts that importing the text fails, and returns the exception for further checks. */
    public static ColladaException error(String name, String xml) {
        return error(name, xml.getBytes(StandardCharsets.UTF_8));
    }

    /** Asserts that importing the bytes fails, and returns the exception for further checks. */
    public static ColladaException error(String name, byte[] bytes) {
        return assertThrows(ColladaException.class, () -> ColladaImporter.read(new ByteArrayInputStream(bytes), name));
    }


    /** The text of {@code src/test/resources/fixtures/<name>} (UTF-8), for tests that change it. */
    public static String text(String name) {
        try (InputStream in = open(name)) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static InputStream open(String name) {
        InputStream in = Fixtures.class.getResourceAsStream("/fixtures/" + name);
        if (in == null) {
            throw new IllegalArgumentException("no fixture " + name);
        }
        return in;
    }
}
