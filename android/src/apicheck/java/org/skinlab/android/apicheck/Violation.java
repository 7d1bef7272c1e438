package org.skinlab.android.apicheck;

/**
 * A reference to a class or member the min SDK lacks, reached without an SDK_INT guard as high
 * as its level: where (class, method, source line) and what.
 *
 * @param className the class whose code makes the reference (for an R8 outline, its caller)
 * @param method    the method in source form, or null for a class declaration
 * @param source    file and line ({@code SkinlabActivity.java:42})
 * @param use       what the code does with the reference
 * @param member    the referenced class or member in source form
 * @param level     where the member first appears
 * @param outline   the R8 outline method the reference was moved into, or null
 */
record Violation(String className, String method, String source, Reference.Use use, String member,
        LevelRange level, String outline) {

    String format() {
        String where = method == null ? className : className + "." + method;
        String through = outline == null ? "" : " (through R8's outline " + outline + ")";
        return "  " + where + " (" + source + ")\n      " + use.verb + " " + member + through + ": " + level.text;
    }
}
