package org.skinlab.android.logic;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.skinlab.animation.RotationInterpolation;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.skinning.SkinningMethod;

/**
 * What the user chose, kept when Android recreates the Activity (after its process was stopped in
 * the background, or a configuration change the app does not handle itself): the animation
 * settings of the buttons, the model, the marker size and where the camera permission stood. As
 * strings, which a Bundle holds; an entry that is missing or unreadable keeps the default, so a
 * state saved by another version of the app never breaks a start.
 *
 * @param settings          the animation settings
 * @param model             the model's file name, or null for the default
 * @param markerMillimetres the printed marker's size, or NaN for the default
 * @param permission        {@link PermissionFlow#savedState()}, or null for a new flow
 */
public record SavedChoices(AnimationConfig.Settings settings, String model, double markerMillimetres,
        String permission) {
    private static final String SPEED = "speed";
    private static final String METHOD = "method";
    private static final String INTERPOLATION = "interpolation";
    private static final String ANIMATION = "animationRunning";
    private static final String MESH_UPDATES = "meshUpdatesRunning";
    private static final String FOLLOW = "followCamera";
    private static final String MODEL = "model";
    private static final String MARKER = "markerMillimetres";
    private static final String PERMISSION = "permission";
    /** Every key {@link #toMap()} may write. */
    public static final List<String> KEYS = List.of(SPEED, METHOD, INTERPOLATION, ANIMATION,
            MESH_UPDATES, FOLLOW, MODEL, MARKER, PERMISSION);

    /** The entries to save. */
    public Map<String, String> toMap() {
        Map<String, String> m = new LinkedHashMap<>();
        m.put(SPEED, Double.toString(settings.speed()));
        m.put(METHOD, settings.method().key());
        m.put(INTERPOLATION, settings.interpolation().name());
        m.put(ANIMATION, Boolean.toString(settings.animationRunning()));
        m.put(MESH_UPDATES, Boolean.toString(settings.meshUpdatesRunning()));
        m.put(FOLLOW, Boolean.toString(settings.followCamera()));
        if (model != null) {
            m.put(MODEL, model);
        }
        if (!Double.isNaN(markerMillimetres)) {
            m.put(MARKER, Double.toString(markerMillimetres));
        }
        if (permission != null) {
            m.put(PERMISSION, permission);
        }
        return m;
    }

    /** The choices in {@code saved} (as {@link #toMap()} wrote them) over {@code defaults}. */
    public static SavedChoices fromMap(Map<String, String> saved, AnimationConfig.Settings defaults) {
        AnimationConfig.Settings s = defaults;
        try {
            s = s.withSpeed(AnimationConfig.clampSpeed(Double.parseDouble(saved.getOrDefault(SPEED, ""))));
        } catch (IllegalArgumentException e) { // not a number, or NaN
            // keep the default speed
        }
        try {
            s = s.withMethod(SkinningMethod.fromKey(saved.getOrDefault(METHOD, "")));
        } catch (IllegalArgumentException e) {
            // keep the default method
        }
        try {
            s = s.withInterpolation(RotationInterpolation.valueOf(saved.getOrDefault(INTERPOLATION, "")));
        } catch (IllegalArgumentException e) {
            // keep the default interpolation
        }
        s = s.withAnimationRunning(flag(saved, ANIMATION, s.animationRunning()))
                .withMeshUpdatesRunning(flag(saved, MESH_UPDATES, s.meshUpdatesRunning()))
                .withFollowCamera(flag(saved, FOLLOW, s.followCamera()));
        double marker = Double.NaN;
        try {
            marker = Double.parseDouble(saved.getOrDefault(MARKER, ""));
        } catch (NumberFormatException e) {
            // the default size
        }
        return new SavedChoices(s, saved.get(MODEL), marker, saved.get(PERMISSION));
    }

    private static boolean flag(Map<String, String> saved, String key, boolean fallback) {
        String v = saved.get(key);
        return "true".equals(v) || !"false".equals(v) && fallback;
    }
}
