package org.skinlab.desktop.launch;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;

/**
 * A folder that looks like a JDK to the start scripts: a {@code release} file with a
 * JAVA_VERSION and a {@code bin/java} shell script. The script appends each call's arguments to
 * {@code calls} in the folder; called with {@code -version} it succeeds only if the fake
 * {@code starts}, otherwise it prints {@code fake-java ARGS} (one argument per line after the
 * first) and succeeds, so a test sees exactly what a start script ran.
 */
final class FakeJdk {
    final Path home;

    private FakeJdk(Path home) {
        this.home = home;
    }

    static FakeJdk create(Path home, String javaVersion, boolean starts) throws IOException {
        Files.createDirectories(home.resolve("bin"));
        Files.writeString(home.resolve("release"), "IMPLEMENTOR=\"Fake\"\nJAVA_VERSION=\"" + javaVersion
                + "\"\nOS_NAME=\"Linux\"\n", StandardCharsets.UTF_8);
        Path java = home.resolve("bin/java");
        Files.writeString(java, "#!/bin/sh\n"
                + "printf '%s\\n' \"$*\" >> \"$(dirname \"$0\")/../calls\"\n"
                + "for a in \"$@\"; do [ \"$a\" = -version ] && exit " + (starts ? 0 : 1) + "; done\n"
                + "echo fake-java\n"
                + "printf '%s\\n' \"$@\"\n", StandardCharsets.UTF_8);
        Files.setPosixFilePermissions(java, PosixFilePermissions.fromString("rwxr-xr-x"));
        return new FakeJdk(home);
    }

    Path java() {
        return home.resolve("bin/java");
    }

    /** The argument lists this fake's java was called with, in order. */
    List<String> calls() throws IOException {
        Path calls = home.resolve("calls");
        return Files.exists(calls) ? Files.readAllLines(calls) : List.of();
    }
}
