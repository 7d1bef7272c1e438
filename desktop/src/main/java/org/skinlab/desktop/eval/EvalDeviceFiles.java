package org.skinlab.desktop.eval;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.internal.bench.DeviceResults;
import org.skinlab.internal.bench.DeviceResultsJson;
import org.skinlab.internal.bench.DeviceResultsReader;
import org.skinlab.internal.bench.InvalidDeviceResults;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;

/**
 * {@code skinlab eval --add-device FILE}: a phone's device file (the Android app's
 * {@code results-android.json}, core's {@code DeviceResultsJson}) checked by core's reader and
 * added to the phone section of a report's results.json ({@link EvalPhoneSection#addDevice}),
 * then the report written again from results.json alone ({@link Evaluation#write}), measuring
 * nothing. A bad file changes nothing.
 */
public final class EvalDeviceFiles {
    private EvalDeviceFiles() {
    }

    /** What adding did: the phone's name, whether it replaced an earlier file of it, what was written. */
    public record Added(String device, boolean replaced, Evaluation.Written written) {
    }

    /**
     * Adds {@code file} to {@code out}/results.json and writes the report again.
     *
     * @throws CommandFailure (usage) naming the file and, for a bad device file, the JSON pointer of
     *                        the fault; results.json is then left as it was
     */
    public static Added add(Path out, Path file) throws IOException {
        ObjectNode results = Evaluation.readResults(out);
        ObjectNode device = checked(file);
        ObjectNode sections = (ObjectNode) results.get("sections");
        ObjectNode phone = (ObjectNode) sections.get(EvalPhoneSection.KEY);
        if (phone == null) {
            phone = sections.putObject(EvalPhoneSection.KEY);
            EvalPhoneSection.prepare(phone, sections.get("time"));
        }
        boolean replaced = EvalPhoneSection.addDevice(phone, device, file.getFileName().toString(),
                Instant.now().toString());
        return new Added(EvalPhoneSection.name(device), replaced, Evaluation.write(out, results));
    }

    /** The device file as core's writer writes what its reader read: every value checked, the layout canonical. */
    private static ObjectNode checked(Path file) throws IOException {
        if (!Files.isRegularFile(file)) {
            throw new CommandFailure(ExitCodes.USAGE, file + ": not found (the app writes "
                    + DeviceResultsJson.FILE_NAME + ": docs/ar.md)", null);
        }
        if (Files.size(file) > DeviceResultsReader.MAX_BYTES) {
            throw new CommandFailure(ExitCodes.USAGE, file + ": " + Files.size(file) + " bytes: larger than any"
                    + " device file", null);
        }
        DeviceResults results;
        try {
            results = DeviceResultsReader.read(Files.readAllBytes(file), file.toString());
        } catch (InvalidDeviceResults e) {
            throw new CommandFailure(ExitCodes.USAGE, e.getMessage(), e);
        }
        ByteArrayOutputStream canonical = new ByteArrayOutputStream();
        DeviceResultsJson.write(results, canonical);
        return (ObjectNode) new ObjectMapper().readTree(canonical.toByteArray());
    }
}
