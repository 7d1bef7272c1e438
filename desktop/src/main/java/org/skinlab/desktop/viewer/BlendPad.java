package org.skinlab.desktop.viewer;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.skinlab.mixer.BlendSpace;

/**
 * The blend space the mixer panel's pad drives, chosen from a model's clip names, and how a point
 * of the pad (u right, v up, each 0 to 1) maps to the space's parameter. A model with clips named
 * idle, walk and run gets a 1-D speed space on the pad's vertical axis (idle at 0, walk at 1.2 and
 * run at 3.5 m/s: typical walking and running speeds, so the parameter reads as a speed); any
 * other model with two or more clips gets a 2-D space with its clips spread evenly on a circle, the
 * first at the top, so the centre mixes them all equally (gradient bands: on a regular polygon
 * every clip's influence at the centre is 1/2). Immutable.
 */
public final class BlendPad {
    /** The speed space's clips and places (m/s), the names matched ignoring case. */
    private static final String[] SPEED_CLIPS = {"idle", "walk", "run"};
    private static final double[] SPEEDS = {0.0, 1.2, 3.5};
    /** The circle space's pad reaches this far beyond the unit circle, so each clip's point can be reached. */
    private static final double CIRCLE_REACH = 1.15;

    private final BlendSpace space;
    private final String[] clips;
    /** Each clip's place on the pad. */
    private final float[] us;
    private final float[] vs;
    private final String description;

    private BlendPad(BlendSpace space, String[] clips, float[] us, float[] vs, String description) {
        this.space = space;
        this.clips = clips;
        this.us = us;
        this.vs = vs;
        this.description = description;
    }

    /**
     * The pad for a model's clips.
     *
     * @param clipNames the mixer's clip names ({@code Mixer.clipNames()}), distinct
     * @return the pad, or null for fewer than two clips
     */
    public static BlendPad of(List<String> clipNames) {
        String[] speed = speedClips(clipNames);
        if (speed != null) {
            Map<String, Double> places = new LinkedHashMap<>();
            float[] us = new float[speed.length];
            float[] vs = new float[speed.length];
            for (int i = 0; i < speed.length; i++) {
                places.put(speed[i], SPEEDS[i]);
                us[i] = 0.5f;
                vs[i] = (float) (SPEEDS[i] / topSpeed());
            }
            return new BlendPad(BlendSpace.linear(places), speed, us, vs, String.format(Locale.ROOT,
                    "up: speed (%s %.1f, %s %.1f, %s %.1f m/s)", speed[0], SPEEDS[0], speed[1], SPEEDS[1], speed[2],
                    SPEEDS[2]));
        }
        if (clipNames.size() < 2) {
            return null;
        }
        int n = clipNames.size();
        Map<String, double[]> places = new LinkedHashMap<>();
        float[] us = new float[n];
        float[] vs = new float[n];
        for (int i = 0; i < n; i++) {
            double angle = Math.PI / 2 - 2 * Math.PI * i / n;
            double x = Math.cos(angle);
            double y = Math.sin(angle);
            places.put(clipNames.get(i), new double[] {x, y});
            us[i] = (float) ((x / CIRCLE_REACH + 1) / 2);
            vs[i] = (float) ((y / CIRCLE_REACH + 1) / 2);
        }
        return new BlendPad(BlendSpace.planar(places), clipNames.toArray(new String[0]), us, vs,
                "the clips on a circle; the centre mixes them all");
    }

    /** The model's idle, walk and run clips in that order, or null when one is missing. */
    private static String[] speedClips(List<String> names) {
        String[] found = new String[SPEED_CLIPS.length];
        for (String name : names) {
            for (int i = 0; i < SPEED_CLIPS.length; i++) {
                if (found[i] == null && name.equalsIgnoreCase(SPEED_CLIPS[i])) {
                    found[i] = name;
                }
            }
        }
        for (String f : found) {
            if (f == null) {
                return null;
            }
        }
        return found;
    }

    private static double topSpeed() {
        return SPEEDS[SPEEDS.length - 1];
    }

    /** The blend space the base layer plays while the pad drives it. */
    public BlendSpace space() {
        return space;
    }

    /** The parameter's x at the pad's point (u, v): the speed for the 1-D space. */
    public double x(float u, float v) {
        return space.isPlanar() ? (2 * u - 1) * CIRCLE_REACH : v * topSpeed();
    }

    /** The parameter's y at the pad's point (u, v); 0 for the 1-D space (it has none). */
    public double y(float u, float v) {
        return space.isPlanar() ? (2 * v - 1) * CIRCLE_REACH : 0;
    }

    /** Clips placed on the pad. */
    public int clipCount() {
        return clips.length;
    }

    public String clip(int i) {
        return clips[i];
    }

    /** Clip {@code i}'s place on the pad, across (0 left, 1 right). */
    public float u(int i) {
        return us[i];
    }

    /** Clip {@code i}'s place on the pad, up (0 bottom, 1 top). */
    public float v(int i) {
        return vs[i];
    }

    /** Where clip {@code name} lies on the pad, into {@code dest} (u, v); false when the pad has no such clip. */
    public boolean place(String name, float[] dest) {
        for (int i = 0; i < clips.length; i++) {
            if (clips[i].equals(name)) {
                dest[0] = us[i];
                dest[1] = vs[i];
                return true;
            }
        }
        return false;
    }

    /** The clips' names, for root motion switched for all of them at once. */
    public List<String> clips() {
        return List.of(clips);
    }

    /** One line saying what the pad's axes mean. */
    public String description() {
        return description;
    }
}
