package org.skinlab.android.apicheck;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.jf.dexlib2.Opcode;
import org.jf.dexlib2.builder.Label;
import org.jf.dexlib2.builder.MethodImplementationBuilder;
import org.jf.dexlib2.builder.instruction.BuilderInstruction10t;
import org.jf.dexlib2.builder.instruction.BuilderInstruction10x;
import org.jf.dexlib2.builder.instruction.BuilderInstruction11n;
import org.jf.dexlib2.builder.instruction.BuilderInstruction12x;
import org.jf.dexlib2.builder.instruction.BuilderInstruction21c;
import org.jf.dexlib2.builder.instruction.BuilderInstruction21s;
import org.jf.dexlib2.builder.instruction.BuilderInstruction21t;
import org.jf.dexlib2.builder.instruction.BuilderInstruction22t;
import org.jf.dexlib2.iface.MethodImplementation;
import org.jf.dexlib2.immutable.reference.ImmutableFieldReference;
import org.junit.jupiter.api.Test;

/**
 * The SDK_INT dataflow on methods written instruction by instruction (the forms javac and D8 may
 * not produce for the fixtures): if-*z, the constant as first operand, copies, joins, loops.
 */
class SdkIntBoundsTest {
    private static final ImmutableFieldReference SDK_INT =
            new ImmutableFieldReference("Landroid/os/Build$VERSION;", "SDK_INT", "I");

    @Test
    void ifGtzAndIfLezRaiseTheBoundToOneOnTheirSdkIntIsPositiveEdges() {
        // 0: sget v0, SDK_INT; 1: if-gtz v0, :positive; 2: return-void; 3: :positive return-void
        MethodImplementationBuilder b = new MethodImplementationBuilder(1);
        Label positive = b.getLabel("positive");
        b.addInstruction(new BuilderInstruction21c(Opcode.SGET, 0, SDK_INT));
        b.addInstruction(new BuilderInstruction21t(Opcode.IF_GTZ, 0, positive));
        b.addInstruction(new BuilderInstruction10x(Opcode.RETURN_VOID));
        b.addLabel("positive");
        b.addInstruction(new BuilderInstruction10x(Opcode.RETURN_VOID));
        int[] bounds = bounds(b.getMethodImplementation(), 0);
        assertEquals(0, bounds[2], "SDK_INT <= 0 on the fall-through");
        assertEquals(1, bounds[3], "SDK_INT > 0 where the branch goes");

        MethodImplementationBuilder lez = new MethodImplementationBuilder(1);
        Label notPositive = lez.getLabel("notPositive");
        lez.addInstruction(new BuilderInstruction21c(Opcode.SGET, 0, SDK_INT));
        lez.addInstruction(new BuilderInstruction21t(Opcode.IF_LEZ, 0, notPositive));
        lez.addInstruction(new BuilderInstruction10x(Opcode.RETURN_VOID));
        lez.addLabel("notPositive");
        lez.addInstruction(new BuilderInstruction10x(Opcode.RETURN_VOID));
        int[] lezBounds = bounds(lez.getMethodImplementation(), 0);
        assertEquals(1, lezBounds[2], "SDK_INT > 0 on the fall-through");
        assertEquals(0, lezBounds[3]);
    }

    @Test
    void constantOnTheLeftThroughACopyIsSwapped() {
        // sget v0; const/16 v1, 34; move v2, v1; if-gt v2, v0, :old (34 > SDK_INT); [new] return; :old return
        MethodImplementationBuilder b = new MethodImplementationBuilder(3);
        Label old = b.getLabel("old");
        b.addInstruction(new BuilderInstruction21c(Opcode.SGET, 0, SDK_INT));
        b.addInstruction(new BuilderInstruction21s(Opcode.CONST_16, 1, 34));
        b.addInstruction(new BuilderInstruction12x(Opcode.MOVE, 2, 1));
        b.addInstruction(new BuilderInstruction22t(Opcode.IF_GT, 2, 0, old));
        b.addInstruction(new BuilderInstruction10x(Opcode.RETURN_VOID));
        b.addLabel("old");
        b.addInstruction(new BuilderInstruction10x(Opcode.RETURN_VOID));
        int[] bounds = bounds(b.getMethodImplementation(), 26);
        assertEquals(34, bounds[4], "34 <= SDK_INT on the fall-through");
        assertEquals(26, bounds[5], "SDK_INT < 34 where the branch goes: the entry's 26");
    }

    @Test
    void whereAGuardedAndAnUnguardedPathMeetTheBoundIsTheLower() {
        // sget v0; const/16 v1, 30; if-lt v0, v1, :join; const/4 v1, 1; :join return-void
        MethodImplementationBuilder b = new MethodImplementationBuilder(2);
        Label join = b.getLabel("join");
        b.addInstruction(new BuilderInstruction21c(Opcode.SGET, 0, SDK_INT));
        b.addInstruction(new BuilderInstruction21s(Opcode.CONST_16, 1, 30));
        b.addInstruction(new BuilderInstruction22t(Opcode.IF_LT, 0, 1, join));
        b.addInstruction(new BuilderInstruction11n(Opcode.CONST_4, 1, 1));
        b.addLabel("join");
        b.addInstruction(new BuilderInstruction10x(Opcode.RETURN_VOID));
        int[] bounds = bounds(b.getMethodImplementation(), 26);
        assertEquals(30, bounds[3]);
        assertEquals(26, bounds[4]);
    }

    @Test
    void aRegisterOverwrittenWithAConstantIsNoLongerSdkIntAndLoopsEnd() {
        // 0 sget v0; 1 :loop const/16 v1, 20; 2 if-lt v0, v1, :end; 3 const/16 v0, 50; 4 const/16 v1, 40;
        // 5 if-lt v0, v1, :end; 6 return-void; 7 :end goto :loop
        // At 5, v0 holds 50: "v0 >= 40" on the fall-through says nothing of SDK_INT (were v0 still
        // taken for SDK_INT, 6 would get 40). The jump back makes the analysis meet states at 1.
        MethodImplementationBuilder b = new MethodImplementationBuilder(2);
        Label loop = b.getLabel("loop");
        Label end = b.getLabel("end");
        b.addInstruction(new BuilderInstruction21c(Opcode.SGET, 0, SDK_INT));
        b.addLabel("loop");
        b.addInstruction(new BuilderInstruction21s(Opcode.CONST_16, 1, 20));
        b.addInstruction(new BuilderInstruction22t(Opcode.IF_LT, 0, 1, end));
        b.addInstruction(new BuilderInstruction21s(Opcode.CONST_16, 0, 50));
        b.addInstruction(new BuilderInstruction21s(Opcode.CONST_16, 1, 40));
        b.addInstruction(new BuilderInstruction22t(Opcode.IF_LT, 0, 1, end));
        b.addInstruction(new BuilderInstruction10x(Opcode.RETURN_VOID));
        b.addLabel("end");
        b.addInstruction(new BuilderInstruction10t(Opcode.GOTO, loop));
        int[] bounds = bounds(b.getMethodImplementation(), 26);
        assertEquals(26, bounds[6]);
        assertEquals(26, bounds[1], "the loop's head: entered at 26");
    }

    private static int[] bounds(MethodImplementation code, int entry) {
        return SdkIntBounds.of(ControlFlow.of(code), code.getRegisterCount(), entry);
    }
}
