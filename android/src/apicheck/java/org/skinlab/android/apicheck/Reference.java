package org.skinlab.android.apicheck;

/**
 * One thing a dex class names that has to exist when it runs: a class (extended, instantiated,
 * cast to...), a field (read or written) or a method (called).
 *
 * @param use     what the code does with it
 * @param owner   the class, in internal form ({@code java/nio/file/Path}); for an array type, its
 *                element class
 * @param member  the field or method in animal-sniffer's signature form ({@code SDK_INT#I},
 *                {@code of(Ljava/lang/String;[Ljava/lang/String;)Ljava/nio/file/Path;}), or null
 *                when the class itself is the reference
 * @param index   the instruction's position in its method, -1 for a class declaration
 * @param address the instruction's address in 16-bit code units (what line numbers are keyed by)
 */
record Reference(Use use, String owner, String member, int index, int address) {

    /** What the code does with the referenced class or member, as the failure message says it. */
    enum Use {
        CALLS("calls"),
        READS("reads"),
        WRITES("writes"),
        INSTANTIATES("instantiates"),
        USES_CLASS("uses class"),
        EXTENDS("extends"),
        IMPLEMENTS("implements");

        final String verb;

        Use(String verb) {
            this.verb = verb;
        }
    }

    /** A class declaration's reference (superclass or interface): no instruction, so no guard. */
    static Reference declared(Use use, String owner) {
        return new Reference(use, owner, null, -1, -1);
    }

    /** The class or member in Java's source form, as messages and the exceptions file write it. */
    String text() {
        return member == null ? JavaNames.className(owner) : JavaNames.member(owner, member);
    }
}
