package org.skinlab.desktop.cli;

import java.util.ArrayList;
import java.util.List;

import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.skinning.SkinningMethod;

import picocli.CommandLine;

/**
 * The skinning methods on the command line, for every command's {@code --method}: their keys
 * ({@link SkinningMethod#key()}, any case) and the words some commands add ({@code all},
 * {@code both}), parsed in one place.
 */
final class MethodKeys {
    /** Every method's key, as the options' parameter label (an annotation needs a constant; tested against the enum). */
    static final String KEYS = "lbs|dqs|cor|bfdqs|stbs-lbs|stbs-dqs|spline";
    /** {@link #KEYS} or all of them. */
    static final String KEYS_OR_ALL = KEYS + "|all";

    private MethodKeys() {
    }

    /**
     * One method's key, any case: the one place a command turns a key into a method.
     *
     * @throws IllegalArgumentException for anything else, naming the keys
     */
    static SkinningMethod parse(String value) {
        return SkinningMethod.fromKey(value);
    }

    /** The picocli converter of one method's key. */
    static final class Converter implements CommandLine.ITypeConverter<SkinningMethod> {
        @Override
        public SkinningMethod convert(String value) {
            try {
                return parse(value);
            } catch (IllegalArgumentException e) {
                throw new CommandLine.TypeConversionException(e.getMessage());
            }
        }
    }

    /**
     * One method's key, or {@code all} (every method in the enum's order).
     *
     * @throws IllegalArgumentException for anything else, naming the keys (the command words it as its usage error)
     */
    static List<SkinningMethod> parseOneOrAll(String value) {
        if (value.equalsIgnoreCase("all")) {
            return List.of(SkinningMethod.values());
        }
        try {
            return List.of(parse(value));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(e.getMessage() + ", or all", e);
        }
    }

    /** As {@link #parseOneOrAll(String)}, a bad value being a usage error that names the option. */
    static List<SkinningMethod> parseOneOrAll(String option, String value) {
        try {
            return parseOneOrAll(value);
        } catch (IllegalArgumentException e) {
            throw new CommandFailure(ExitCodes.USAGE, option + " " + value + ": " + e.getMessage(), e);
        }
    }

    /** The keys of {@code methods}, comma-separated (for messages). */
    static String keys(List<SkinningMethod> methods) {
        List<String> keys = new ArrayList<>();
        methods.forEach(m -> keys.add(m.key()));
        return String.join(", ", keys);
    }
}
