package org.skinlab.internal.bench;

/**
 * A device file ({@link DeviceResultsJson}) that is not one: its message names the file, the JSON
 * pointer of the value at fault ("" for the document) and what was expected.
 */
public final class InvalidDeviceResults extends Exception {
    private static final long serialVersionUID = 1L;
    private final String file;
    private final String pointer;
    private final String problem;

    public InvalidDeviceResults(String file, String pointer, String problem) {
        super(file + ": " + (pointer.isEmpty() ? "" : pointer + ": ") + problem);
        this.file = file;
        this.pointer = pointer;
        this.problem = problem;
    }

    public String file() {
        return file;
    }

    /** The JSON pointer of the value at fault, e.g. "/models/0/methods/1/micros/runs/2"; "" for the document. */
    public String pointer() {
        return pointer;
    }

    public String problem() {
        return problem;
    }
}
