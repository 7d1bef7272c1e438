package org.skinlab.desktop.bench;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import org.skinlab.internal.bench.FrameBench;
import org.skinlab.skinning.SkinningMethod;

/**
 * The markdown table of {@code bench frame} over several files: a row per file, printed as soon
 * as the file is measured, so columns are padded to widths known in advance (a longer cell only
 * shifts its row; markdown does not care). A method's cell is "median / min" in µs per frame.
 */
public final class FrameBenchTable {
    private final List<SkinningMethod> methods;
    private final List<String> titles = new ArrayList<>();
    private final List<Integer> widths = new ArrayList<>();

    /** @param nameWidth the longest file name to be shown */
    public FrameBenchTable(List<SkinningMethod> methods, int nameWidth) {
        this.methods = List.copyOf(methods);
        column("file", nameWidth);
        column("positions skinned", 0);
        column("render vertices", 0);
        column("joints", 0);
        column("influences", 0);
        column("kernel", "vector-256".length());
        for (SkinningMethod m : methods) {
            column(m.key().toUpperCase(Locale.ROOT) + " frame", "100.00 / 100.00".length());
        }
    }

    private void column(String title, int width) {
        titles.add(title);
        widths.add(Math.max(title.length(), width));
    }

    /** The title line and the alignment line (text left, numbers right). */
    public String header() {
        StringBuilder separator = new StringBuilder("|");
        for (int c = 0; c < titles.size(); c++) {
            separator.append(c == 0 || c == 5 ? "-".repeat(widths.get(c) + 2)
                    : "-".repeat(widths.get(c) + 1) + ":").append('|');
        }
        return line(titles) + separator + System.lineSeparator();
    }

    /** A file's row; {@code timings} in the order of the table's methods. */
    public String row(String name, FrameBench.Shape shape, List<FrameBench.Timing> timings) {
        List<String> cells = new ArrayList<>();
        cells.add(name);
        cells.add(String.valueOf(shape.positionsSkinned()));
        cells.add(String.valueOf(shape.renderVertices()));
        cells.add(String.valueOf(shape.joints()));
        cells.add(String.valueOf(shape.influences()));
        cells.add(kernel(timings));
        for (FrameBench.Timing t : timings) {
            cells.add(String.format(Locale.ROOT, "%.2f / %.2f", t.medianMicros(), t.minMicros()));
        }
        return line(cells);
    }

    /** One kernel name when the methods agree (the usual case), else each method's. */
    private String kernel(List<FrameBench.Timing> timings) {
        if (timings.stream().map(FrameBench.Timing::kernel).distinct().count() == 1) {
            return timings.get(0).kernel();
        }
        List<String> each = new ArrayList<>();
        for (int i = 0; i < timings.size(); i++) {
            each.add(methods.get(i).key() + ": " + timings.get(i).kernel());
        }
        return String.join(", ", each);
    }

    private String line(List<String> cells) {
        StringBuilder sb = new StringBuilder("|");
        for (int c = 0; c < cells.size(); c++) {
            String cell = cells.get(c);
            String pad = " ".repeat(Math.max(0, widths.get(c) - cell.length()));
            boolean left = c == 0 || c == 5 || titles.get(c).equals(cell);
            sb.append(' ').append(left ? cell + pad : pad + cell).append(" |");
        }
        return sb.append(System.lineSeparator()).toString();
    }
}
