package org.skinlab.android.apicheck;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.codehaus.mojo.animal_sniffer.Clazz;
import org.codehaus.mojo.animal_sniffer.SignatureBuilder;
import org.codehaus.mojo.animal_sniffer.SignatureChecker;
import org.codehaus.mojo.animal_sniffer.logging.PrintWriterLogger;

/**
 * Class models in animal-sniffer's form ({@link Clazz}: name, superclass, interfaces and member
 * signatures), read with animal-sniffer's own code: a platform's API from a {@code .signature}
 * file, or jars' classes (the libraries core is compiled against) through its signature builder.
 */
final class Signatures {
    private Signatures() {
    }

    /** The classes of a signature file (gzip'd serialised {@link Clazz} objects), by internal name. */
    static Map<String, Clazz> read(Path signature) throws IOException {
        try (InputStream in = Files.newInputStream(signature)) {
            return SignatureChecker.loadClasses(in);
        }
    }

    /** The classes of jars, by internal name, with all their members. */
    static Map<String, Clazz> ofJars(List<Path> jars) throws IOException {
        if (jars.isEmpty()) {
            return Map.of();
        }
        ByteArrayOutputStream signature = new ByteArrayOutputStream();
        // The builder logs each jar it reads: nothing a reader of the check's output needs.
        PrintStream quiet = new PrintStream(OutputStream.nullOutputStream());
        SignatureBuilder builder = new SignatureBuilder(signature, new PrintWriterLogger(quiet));
        for (Path jar : jars) {
            builder.process(jar.toFile());
        }
        builder.close();
        return SignatureChecker.loadClasses(new ByteArrayInputStream(signature.toByteArray()));
    }
}
