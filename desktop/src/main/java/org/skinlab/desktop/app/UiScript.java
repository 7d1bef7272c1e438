package org.skinlab.desktop.app;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

/**
 * A replay of user actions for tests and demos ({@code skinlab view --script FILE}): one step per
 * line, {@code #} starts a comment. Verbs (docs/desktop.md has the list with examples):
 * <pre>
 * action NAME            a toolbar function by name or label (next-mesh, "Split view", ...)
 * key NAME [shift|ctrl]  a key press and release through the window's key callbacks (SPACE, M, F12, PAGE_DOWN)
 * click LABEL            move to an interface item, press, release (over the next frames)
 * move X Y               the mouse to window coordinates
 * drag X0 Y0 X1 Y1       left button drag (orbits the camera outside the interface)
 * scroll DY              the mouse wheel
 * drop PATH              a file dropped on the window
 * open PATH              open a file (as the dialog would)
 * seek SECONDS           the playback time
 * wait N                 let N frames pass
 * wait-seconds S         let S seconds pass (frames go on: the animation plays)
 * wait-loaded            wait until the file being loaded is shown (at most 60 s)
 * screenshot PATH        write the window as PNG
 * expect mesh NAME       the model shown is NAME (as the toolbar names it)
 * expect status TEXT     the status line contains TEXT
 * expect method KEY      the skinning method (any key SkinningMethod.fromKey takes)
 * expect layers N        the model's mixer has N layers (the base included)
 * expect layer I TEXT    the mixer's layer I (0: the base) as MixerReadout words it contains TEXT
 * quit                   close the window
 * </pre>
 * The first step runs once the first model is shown. Paths are relative to the script's folder. Parsing checks every line before anything runs;
 * errors name the file and the line.
 */
public final class UiScript {
    /** One step: its verb, its arguments, and where it was written. */
    public record Step(String verb, List<String> args, int line) {
        String arg(int i) {
            return args.get(i);
        }

        float number(int i) {
            return Float.parseFloat(args.get(i));
        }

        String rest() {
            return String.join(" ", args);
        }
    }

    private static final List<String> VERBS = List.of("action", "key", "click", "move", "drag", "scroll", "drop",
            "open", "seek", "wait", "wait-seconds", "wait-loaded", "screenshot", "expect", "quit");

    private final Path file;
    private final List<Step> steps;

    private UiScript(Path file, List<Step> steps) {
        this.file = file;
        this.steps = List.copyOf(steps);
    }

    public static UiScript read(Path file) throws IOException {
        return parse(file, Files.readAllLines(file, StandardCharsets.UTF_8));
    }

    /** Parses the lines of {@code file}; throws IllegalArgumentException naming the line. */
    public static UiScript parse(Path file, List<String> lines) {
        List<Step> steps = new ArrayList<>();
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i);
            int hash = line.indexOf('#');
            String text = (hash >= 0 ? line.substring(0, hash) : line).trim();
            if (text.isEmpty()) {
                continue;
            }
            String[] words = text.split("\\s+");
            String verb = words[0].toLowerCase(Locale.ROOT);
            List<String> args = Arrays.asList(words).subList(1, words.length);
            Step step = new Step(verb, List.copyOf(args), i + 1);
            String problem = check(step);
            if (problem != null) {
                throw new IllegalArgumentException(file + " line " + (i + 1) + ": " + problem + ": \"" + text + "\"");
            }
            steps.add(step);
        }
        return new UiScript(file, steps);
    }

    private static String check(Step s) {
        if (!VERBS.contains(s.verb())) {
            return "unknown verb " + s.verb() + " (known: " + String.join(", ", VERBS) + ")";
        }
        int n = s.args().size();
        try {
            switch (s.verb()) {
                case "move":
                    s.number(0);
                    s.number(1);
                    return n == 2 ? null : "needs X Y";
                case "drag":
                    for (int i = 0; i < 4; i++) {
                        s.number(i);
                    }
                    return n == 4 ? null : "needs X0 Y0 X1 Y1";
                case "scroll":
                case "seek":
                    s.number(0);
                    return n == 1 ? null : "needs one number";
                case "wait-seconds":
                    return n == 1 && s.number(0) >= 0 ? null : "needs a number of seconds >= 0";
                case "wait":
                    return n == 1 && Integer.parseInt(s.arg(0)) >= 0 ? null : "needs a frame count >= 0";
                case "key":
                    if (n < 1 || n > 2) {
                        return "needs a key name and at most one of shift, ctrl";
                    }
                    if (Keys.code(s.arg(0)) < 0) {
                        return "unknown key " + s.arg(0);
                    }
                    return n == 1 || Keys.modifier(s.arg(1)) >= 0 ? null : "unknown modifier " + s.arg(1);
                case "expect":
                    return expectation(s);
                case "quit":
                case "wait-loaded":
                    return n == 0 ? null : "takes no arguments";
                default:
                    return n >= 1 ? null : "needs an argument";
            }
        } catch (NumberFormatException | IndexOutOfBoundsException e) {
            return "needs numbers";
        }
    }

    private static String expectation(Step s) {
        int n = s.args().size();
        if (n < 2) {
            return "needs what (mesh, status, method, layers, layer) and a value";
        }
        switch (s.arg(0)) {
            case "mesh":
            case "status":
            case "method":
                return null;
            case "layers":
                return n == 2 && Integer.parseInt(s.arg(1)) >= 1 ? null : "needs a layer count >= 1";
            case "layer":
                return n >= 3 && Integer.parseInt(s.arg(1)) >= 0 ? null : "needs a layer index >= 0 and a text";
            default:
                return "can expect mesh, status, method, layers or layer, not " + s.arg(0);
        }
    }

    public Path file() {
        return file;
    }

    public List<Step> steps() {
        return steps;
    }

    /** A path in a step, relative to the script's folder. */
    public Path resolve(String path) {
        Path p = Path.of(path);
        Path dir = file.toAbsolutePath().getParent();
        return p.isAbsolute() || dir == null ? p : dir.resolve(p);
    }
}
