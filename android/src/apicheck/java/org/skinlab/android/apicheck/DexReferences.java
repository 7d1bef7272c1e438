package org.skinlab.android.apicheck;

import java.util.ArrayList;
import java.util.List;

import org.jf.dexlib2.Opcode;
import org.jf.dexlib2.iface.ClassDef;
import org.jf.dexlib2.iface.MethodImplementation;
import org.jf.dexlib2.iface.instruction.Instruction;
import org.jf.dexlib2.iface.instruction.ReferenceInstruction;
import org.jf.dexlib2.iface.reference.CallSiteReference;
import org.jf.dexlib2.iface.reference.FieldReference;
import org.jf.dexlib2.iface.reference.MethodHandleReference;
import org.jf.dexlib2.iface.reference.MethodReference;
import org.jf.dexlib2.iface.reference.TypeReference;

/**
 * The classes and members a dex class names: in its declaration (superclass, interfaces) and in
 * its methods' instructions (invokes, field accesses, new-instance, check-cast, instance-of,
 * const-class, arrays of a class, and the members behind method handles and call sites). Strings
 * and method prototypes name nothing that must exist.
 */
final class DexReferences {
    private DexReferences() {
    }

    static List<Reference> ofDeclaration(ClassDef c) {
        List<Reference> refs = new ArrayList<>();
        if (c.getSuperclass() != null) {
            refs.add(Reference.declared(Reference.Use.EXTENDS, DexProgram.internalName(c.getSuperclass())));
        }
        for (String i : c.getInterfaces()) {
            refs.add(Reference.declared(Reference.Use.IMPLEMENTS, DexProgram.internalName(i)));
        }
        return refs;
    }

    static List<Reference> ofCode(MethodImplementation code) {
        List<Reference> refs = new ArrayList<>();
        int index = 0;
        int address = 0;
        for (Instruction insn : code.getInstructions()) {
            if (insn instanceof ReferenceInstruction r) {
                add(refs, insn.getOpcode(), r.getReference(), index, address);
            }
            index++;
            address += insn.getCodeUnits();
        }
        return refs;
    }

    private static void add(List<Reference> refs, Opcode op, org.jf.dexlib2.iface.reference.Reference ref,
            int index, int address) {
        if (ref instanceof MethodReference m) {
            refs.add(new Reference(Reference.Use.CALLS, owner(m.getDefiningClass()),
                    DexProgram.signature(m.getName(), m.getParameterTypes(), m.getReturnType()), index, address));
        } else if (ref instanceof FieldReference f) {
            // Field reads (iget, sget) set a register; writes do not.
            Reference.Use use = op.setsRegister() ? Reference.Use.READS : Reference.Use.WRITES;
            refs.add(new Reference(use, owner(f.getDefiningClass()), f.getName() + "#" + f.getType(), index, address));
        } else if (ref instanceof TypeReference t) {
            String element = t.getType().replaceFirst("^\\[+", "");
            if (element.length() > 1) {
                Reference.Use use = op == Opcode.NEW_INSTANCE ? Reference.Use.INSTANTIATES : Reference.Use.USES_CLASS;
                refs.add(new Reference(use, DexProgram.internalName(element), null, index, address));
            }
        } else if (ref instanceof MethodHandleReference h) {
            add(refs, op, h.getMemberReference(), index, address);
        } else if (ref instanceof CallSiteReference s) {
            add(refs, op, s.getMethodHandle(), index, address);
        }
    }

    /** A member's owner: an array type's members (clone, length's getters) are Object's. */
    private static String owner(String definingClass) {
        return definingClass.startsWith("[") ? "java/lang/Object" : DexProgram.internalName(definingClass);
    }
}
