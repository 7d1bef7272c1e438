package org.skinlab.desktop.viewer;

/**
 * The last {@code capacity} samples (time, value) of one live number, for the rolling plots:
 * a ring that overwrites its oldest sample, copied out oldest first into arrays the plot reuses.
 * Allocation-free after construction; one thread.
 */
public final class RollingSeries {
    private final String name;
    private final float[] times;
    private final float[] values;
    private int next;
    private int size;

    public RollingSeries(String name, int capacity) {
        if (capacity < 1) {
            throw new IllegalArgumentException("capacity " + capacity);
        }
        this.name = name;
        times = new float[capacity];
        values = new float[capacity];
    }

    public String name() {
        return name;
    }

    public int capacity() {
        return times.length;
    }

    public int size() {
        return size;
    }

    /** Adds a sample; NaN values are kept out (a number that was not measured this time). */
    public void add(float time, float value) {
        if (Float.isNaN(value)) {
            return;
        }
        times[next] = time;
        values[next] = value;
        next = (next + 1) % times.length;
        size = Math.min(size + 1, times.length);
    }

    public void clear() {
        size = 0;
        next = 0;
    }

    /** Copies the samples, oldest first, into the arrays (at least {@link #size()} long). */
    public void copyTo(float[] xs, float[] ys) {
        int start = (next - size + times.length) % times.length;
        for (int i = 0; i < size; i++) {
            int j = (start + i) % times.length;
            xs[i] = times[j];
            ys[i] = values[j];
        }
    }

    /** The newest value, NaN when empty. */
    public float last() {
        return size == 0 ? Float.NaN : values[(next - 1 + values.length) % values.length];
    }

    public float mean() {
        if (size == 0) {
            return Float.NaN;
        }
        double sum = 0;
        for (int i = 0; i < size; i++) {
            sum += values[index(i)];
        }
        return (float) (sum / size);
    }

    public float min() {
        float m = Float.NaN;
        for (int i = 0; i < size; i++) {
            float v = values[index(i)];
            m = Float.isNaN(m) ? v : Math.min(m, v);
        }
        return m;
    }

    public float max() {
        float m = Float.NaN;
        for (int i = 0; i < size; i++) {
            float v = values[index(i)];
            m = Float.isNaN(m) ? v : Math.max(m, v);
        }
        return m;
    }

    private int index(int i) {
        return (next - size + i + 2 * values.length) % values.length;
    }
}
