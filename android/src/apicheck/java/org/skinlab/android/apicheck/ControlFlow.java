package org.skinlab.android.apicheck;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.jf.dexlib2.Format;
import org.jf.dexlib2.Opcode;
import org.jf.dexlib2.iface.ExceptionHandler;
import org.jf.dexlib2.iface.MethodImplementation;
import org.jf.dexlib2.iface.TryBlock;
import org.jf.dexlib2.iface.instruction.Instruction;
import org.jf.dexlib2.iface.instruction.OffsetInstruction;
import org.jf.dexlib2.iface.instruction.PayloadInstruction;
import org.jf.dexlib2.iface.instruction.SwitchElement;
import org.jf.dexlib2.iface.instruction.SwitchPayload;

/**
 * A dex method's control-flow graph at instruction granularity: for each instruction, where
 * execution can go next (fall-through, branch and switch targets) and which exception handlers it
 * can reach. Every instruction in a try range is taken to reach the range's handlers, which only
 * adds paths (sound for a lower bound on SDK_INT). Switch and array payloads are data, never run.
 */
final class ControlFlow {
    private final List<Instruction> instructions;
    private final int[] addresses;
    private final int[][] successors;
    private final int[][] handlers;

    private ControlFlow(List<Instruction> instructions, int[] addresses, int[][] successors, int[][] handlers) {
        this.instructions = instructions;
        this.addresses = addresses;
        this.successors = successors;
        this.handlers = handlers;
    }

    static ControlFlow of(MethodImplementation code) {
        List<Instruction> list = new ArrayList<>();
        for (Instruction insn : code.getInstructions()) {
            list.add(insn);
        }
        int n = list.size();
        int[] addresses = new int[n];
        Map<Integer, Integer> indexAt = new HashMap<>();
        for (int i = 0, address = 0; i < n; address += list.get(i).getCodeUnits(), i++) {
            addresses[i] = address;
            indexAt.put(address, i);
        }
        int[][] successors = new int[n][];
        for (int i = 0; i < n; i++) {
            successors[i] = successors(list, addresses, indexAt, i);
        }
        return new ControlFlow(List.copyOf(list), addresses, successors, handlers(code, addresses, indexAt));
    }

    int size() {
        return instructions.size();
    }

    Instruction instruction(int i) {
        return instructions.get(i);
    }

    /** Where execution goes after instruction i; for an if-*, the fall-through first, then the target. */
    int[] successors(int i) {
        return successors[i];
    }

    /** The exception handlers instruction i can throw to. */
    int[] handlers(int i) {
        return handlers[i];
    }

    /** Whether instruction i is an if-* (two successors: fall-through when false, target when true). */
    boolean isConditional(int i) {
        Format format = instructions.get(i).getOpcode().format;
        return format == Format.Format21t || format == Format.Format22t;
    }

    private static int[] successors(List<Instruction> list, int[] addresses, Map<Integer, Integer> indexAt, int i) {
        Instruction insn = list.get(i);
        Opcode op = insn.getOpcode();
        int next = i + 1 < list.size() ? i + 1 : -1;
        if (insn instanceof PayloadInstruction) {
            return new int[0];
        }
        switch (op) {
            case GOTO, GOTO_16, GOTO_32:
                return new int[] {target(indexAt, addresses[i], (OffsetInstruction) insn)};
            case PACKED_SWITCH, SPARSE_SWITCH: {
                int payloadIndex = target(indexAt, addresses[i], (OffsetInstruction) insn);
                List<? extends SwitchElement> cases = ((SwitchPayload) list.get(payloadIndex)).getSwitchElements();
                int[] out = new int[cases.size() + 1];
                out[0] = next;
                for (int c = 0; c < cases.size(); c++) {
                    out[c + 1] = indexAt.get(addresses[i] + cases.get(c).getOffset());
                }
                return out;
            }
            default:
                break;
        }
        if (op.format == Format.Format21t || op.format == Format.Format22t) {
            return new int[] {next, target(indexAt, addresses[i], (OffsetInstruction) insn)};
        }
        return op.canContinue() && next >= 0 ? new int[] {next} : new int[0];
    }

    private static int target(Map<Integer, Integer> indexAt, int address, OffsetInstruction insn) {
        Integer index = indexAt.get(address + insn.getCodeOffset());
        if (index == null) {
            throw new IllegalStateException("branch at " + address + " to no instruction: offset " + insn.getCodeOffset());
        }
        return index;
    }

    private static int[][] handlers(MethodImplementation code, int[] addresses, Map<Integer, Integer> indexAt) {
        List<List<Integer>> lists = new ArrayList<>();
        for (int i = 0; i < addresses.length; i++) {
            lists.add(new ArrayList<>());
        }
        for (TryBlock<? extends ExceptionHandler> block : code.getTryBlocks()) {
            int start = block.getStartCodeAddress();
            int end = start + block.getCodeUnitCount();
            for (ExceptionHandler handler : block.getExceptionHandlers()) {
                int target = indexAt.get(handler.getHandlerCodeAddress());
                for (int i = 0; i < addresses.length; i++) {
                    if (addresses[i] >= start && addresses[i] < end) {
                        lists.get(i).add(target);
                    }
                }
            }
        }
        int[][] out = new int[addresses.length][];
        for (int i = 0; i < out.length; i++) {
            out[i] = lists.get(i).stream().mapToInt(Integer::intValue).toArray();
        }
        return out;
    }
}
