package org.skinlab.android.apicheck;

import java.util.ArrayDeque;
import java.util.Arrays;
import java.util.Deque;

import org.jf.dexlib2.Format;
import org.jf.dexlib2.Opcode;
import org.jf.dexlib2.iface.instruction.Instruction;
import org.jf.dexlib2.iface.instruction.NarrowLiteralInstruction;
import org.jf.dexlib2.iface.instruction.OneRegisterInstruction;
import org.jf.dexlib2.iface.instruction.ReferenceInstruction;
import org.jf.dexlib2.iface.instruction.TwoRegisterInstruction;
import org.jf.dexlib2.iface.reference.FieldReference;

/**
 * The lowest value {@code android.os.Build.VERSION.SDK_INT} can have when each instruction of a
 * method runs: a forward dataflow over the method's control-flow graph. It tracks which registers
 * hold SDK_INT (read by sget) and which hold int constants (const, move), and on the two edges of
 * every if-* comparing SDK_INT with a constant (either operand order; the if-*z forms compare with
 * 0) raises the bound where the comparison implies one: {@code SDK_INT >= 34} is 34 on the true
 * edge, {@code SDK_INT < 34} is 34 on the false edge. Where paths meet, the bound is the smaller
 * one and a register keeps its value only if all paths agree. The method's entry has the bound it
 * is called with (the min SDK, or for R8's API outlines the bound at their call sites).
 */
final class SdkIntBounds {
    /** The bound of an instruction no path reaches. */
    static final int UNREACHED = Integer.MAX_VALUE;

    private static final long UNKNOWN = Long.MIN_VALUE;
    private static final long SDK_INT = Long.MIN_VALUE + 1;
    private static final int NO_BOUND = Integer.MIN_VALUE;

    private final ControlFlow flow;
    private final int[] bounds;
    private final long[][] registers;
    private final Deque<Integer> work = new ArrayDeque<>();
    private final boolean[] queued;

    private SdkIntBounds(ControlFlow flow) {
        this.flow = flow;
        this.bounds = new int[flow.size()];
        this.registers = new long[flow.size()][];
        this.queued = new boolean[flow.size()];
        Arrays.fill(bounds, UNREACHED);
    }

    /** For each instruction, the lowest SDK_INT it runs at ({@link #UNREACHED} where none). */
    static int[] of(ControlFlow flow, int registerCount, int entryBound) {
        SdkIntBounds analysis = new SdkIntBounds(flow);
        if (flow.size() > 0) {
            long[] entry = new long[registerCount];
            Arrays.fill(entry, UNKNOWN);
            analysis.join(0, entryBound, entry);
            analysis.run();
        }
        return analysis.bounds.clone();
    }

    private void run() {
        while (!work.isEmpty()) {
            int i = work.poll();
            queued[i] = false;
            int bound = bounds[i];
            long[] in = registers[i];
            for (int handler : flow.handlers(i)) {
                join(handler, bound, in);
            }
            Instruction insn = flow.instruction(i);
            int[] next = flow.successors(i);
            if (flow.isConditional(i)) {
                join(next[0], Math.max(bound, implied(insn, in, false)), in);
                join(next[1], Math.max(bound, implied(insn, in, true)), in);
            } else {
                long[] out = transfer(insn, in);
                for (int s : next) {
                    join(s, bound, out);
                }
            }
        }
    }

    /** Meets a state into instruction i's: the smaller bound, registers kept where equal. */
    private void join(int i, int bound, long[] regs) {
        if (i < 0) {
            return;
        }
        if (bounds[i] == UNREACHED) {
            bounds[i] = bound;
            registers[i] = regs.clone();
            enqueue(i);
            return;
        }
        boolean changed = bound < bounds[i];
        bounds[i] = Math.min(bounds[i], bound);
        long[] mine = registers[i];
        for (int r = 0; r < mine.length; r++) {
            if (mine[r] != UNKNOWN && mine[r] != regs[r]) {
                mine[r] = UNKNOWN;
                changed = true;
            }
        }
        if (changed) {
            enqueue(i);
        }
    }

    private void enqueue(int i) {
        if (!queued[i]) {
            queued[i] = true;
            work.add(i);
        }
    }

    private static long[] transfer(Instruction insn, long[] in) {
        Opcode op = insn.getOpcode();
        if (!op.setsRegister() || !(insn instanceof OneRegisterInstruction one)) {
            return in;
        }
        long[] out = in.clone();
        int a = one.getRegisterA();
        if (op.setsWideRegister()) {
            out[a] = UNKNOWN;
            out[a + 1] = UNKNOWN;
            return out;
        }
        out[a] = switch (op) {
            case SGET -> isSdkInt(insn) ? SDK_INT : UNKNOWN;
            case CONST_4, CONST_16, CONST, CONST_HIGH16 -> ((NarrowLiteralInstruction) insn).getNarrowLiteral();
            case MOVE, MOVE_FROM16, MOVE_16 -> in[((TwoRegisterInstruction) insn).getRegisterB()];
            default -> UNKNOWN;
        };
        return out;
    }

    private static boolean isSdkInt(Instruction insn) {
        FieldReference field = (FieldReference) ((ReferenceInstruction) insn).getReference();
        return field.getDefiningClass().equals("Landroid/os/Build$VERSION;") && field.getName().equals("SDK_INT")
                && field.getType().equals("I");
    }

    /** The lower bound on SDK_INT an if-* implies when its condition is {@code outcome}, or NO_BOUND. */
    private static int implied(Instruction insn, long[] regs, boolean outcome) {
        Comparison cmp = Comparison.of(insn.getOpcode());
        long a = regs[((OneRegisterInstruction) insn).getRegisterA()];
        long b = insn.getOpcode().format == Format.Format22t ? regs[((TwoRegisterInstruction) insn).getRegisterB()] : 0;
        long constant;
        if (a == SDK_INT && isConstant(b)) {
            constant = b;
        } else if (b == SDK_INT && isConstant(a)) {
            constant = a;
            cmp = cmp.swapped();
        } else {
            return NO_BOUND;
        }
        if (!outcome) {
            cmp = cmp.negated();
        }
        return switch (cmp) {
            case GE, EQ -> (int) constant;
            case GT -> (int) Math.min(constant + 1, Integer.MAX_VALUE - 1);
            default -> NO_BOUND;
        };
    }

    private static boolean isConstant(long value) {
        return value != UNKNOWN && value != SDK_INT;
    }

    /** An if-*'s comparison of its first operand with its second (or with 0 for if-*z). */
    private enum Comparison {
        EQ, NE, LT, GE, GT, LE;

        static Comparison of(Opcode op) {
            return switch (op) {
                case IF_EQ, IF_EQZ -> EQ;
                case IF_NE, IF_NEZ -> NE;
                case IF_LT, IF_LTZ -> LT;
                case IF_GE, IF_GEZ -> GE;
                case IF_GT, IF_GTZ -> GT;
                case IF_LE, IF_LEZ -> LE;
                default -> throw new IllegalArgumentException("not an if-*: " + op);
            };
        }

        /** The same condition with the operands exchanged: {@code c < x} is {@code x > c}. */
        Comparison swapped() {
            return switch (this) {
                case LT -> GT;
                case GT -> LT;
                case LE -> GE;
                case GE -> LE;
                default -> this;
            };
        }

        /** The condition's negation: what holds on the fall-through edge. */
        Comparison negated() {
            return switch (this) {
                case EQ -> NE;
                case NE -> EQ;
                case LT -> GE;
                case GE -> LT;
                case GT -> LE;
                case LE -> GT;
            };
        }
    }
}
