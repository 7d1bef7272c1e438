package org.skinlab.android.apicheck;

import org.jf.dexlib2.iface.ClassDef;
import org.jf.dexlib2.iface.Method;
import org.jf.dexlib2.iface.MethodImplementation;
import org.jf.dexlib2.iface.debug.DebugItem;
import org.jf.dexlib2.iface.debug.LineNumber;

/** A dex method with code, and how messages name it: class, method in source form, file and line. */
record DexMethod(ClassDef owner, Method method) {
    /** The part of the class name R8 gives the classes it makes for calls to APIs above the min SDK. */
    static final String API_OUTLINE = "$$ExternalSyntheticApiModelOutline";

    String key() {
        return DexProgram.key(method);
    }

    MethodImplementation code() {
        return method.getImplementation();
    }

    /** Whether R8 made this method to hold a call to an API above the min SDK (its callers guard it). */
    boolean isApiOutline() {
        return owner.getType().contains(API_OUTLINE);
    }

    String className() {
        return JavaNames.className(owner.getType());
    }

    /** {@code onCreate(android.os.Bundle)}. */
    String display() {
        String descriptor = DexProgram.signature("", method.getParameterTypes(), method.getReturnType());
        return JavaNames.method(method.getName(), descriptor);
    }

    /** The source file and the line of the instruction at this address ({@code SkinlabActivity.java:42}). */
    String source(int address) {
        String file = owner.getSourceFile() == null ? "no source file" : owner.getSourceFile();
        int line = -1;
        for (DebugItem item : code().getDebugItems()) {
            if (item.getCodeAddress() > address) {
                break;
            }
            if (item instanceof LineNumber n) {
                line = n.getLineNumber();
            }
        }
        return line < 0 ? file : file + ":" + line;
    }
}
