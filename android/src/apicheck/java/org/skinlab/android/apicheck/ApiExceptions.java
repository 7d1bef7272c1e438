package org.skinlab.android.apicheck;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The reviewed references to APIs above the min SDK that the check accepts: third-party code
 * that cannot be changed and is guarded by means the check cannot see. One per line,
 * {@code member | class calling it | why}, the member as the check's message writes it; '#'
 * starts a comment.
 */
record ApiExceptions(String name, List<Entry> entries) {

    record Entry(String member, String caller, String reason) {
        String format() {
            return member + " | " + caller;
        }
    }

    static ApiExceptions none() {
        return new ApiExceptions("no exceptions file", List.of());
    }

    static ApiExceptions read(Path file) throws IOException {
        List<Entry> entries = new ArrayList<>();
        int lineNumber = 0;
        for (String line : Files.readAllLines(file)) {
            lineNumber++;
            String text = line.strip();
            if (text.isEmpty() || text.startsWith("#")) {
                continue;
            }
            String[] parts = text.split("\\|", -1);
            if (parts.length != 3 || parts[0].isBlank() || parts[1].isBlank() || parts[2].isBlank()) {
                throw new IOException(file + ":" + lineNumber + ": expected 'member | calling class | reason'");
            }
            entries.add(new Entry(parts[0].strip(), parts[1].strip(), parts[2].strip()));
        }
        return new ApiExceptions(file.getFileName().toString(), List.copyOf(entries));
    }

    /** The entry allowing the member to be used from the class, or null. */
    Entry find(String member, String caller) {
        return entries.stream().filter(e -> e.member().equals(member) && e.caller().equals(caller)).findFirst()
                .orElse(null);
    }
}
