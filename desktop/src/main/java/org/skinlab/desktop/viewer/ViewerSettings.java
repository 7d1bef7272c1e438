package org.skinlab.desktop.viewer;

import org.skinlab.desktop.render.DrawSettings;

/**
 * The viewer's own switches, beyond the simulation's {@link org.skinlab.simulation.AnimationConfig}:
 * what colours show and the difference view's scale, the split view, overlays, the instance grid,
 * the selected joint. Used on the window's thread only.
 */
public final class ViewerSettings {
    /** The instance counts the grid steps through (the thesis' fps-against-meshes figure). */
    static final int[] INSTANCE_STEPS = {1, 2, 4, 8, 12, 16, 24, 32, 48, 64, 96, 128, 192, 256};

    private DrawSettings.View view = DrawSettings.View.SHADED;
    private DifferenceScale differenceScale = DifferenceScale.DEFAULT;
    private boolean split;
    private boolean skeleton;
    private boolean wireframe;
    private boolean help;
    private int instanceStep;
    private int selectedJoint;

    public DrawSettings.View drawView() {
        return view;
    }

    public void setView(DrawSettings.View view) {
        this.view = view;
    }

    public DifferenceScale differenceScale() {
        return differenceScale;
    }

    public void setDifferenceScale(DifferenceScale scale) {
        this.differenceScale = java.util.Objects.requireNonNull(scale, "scale");
    }

    public boolean split() {
        return split;
    }

    public void setSplit(boolean split) {
        this.split = split;
    }

    public boolean skeleton() {
        return skeleton;
    }

    public void setSkeleton(boolean skeleton) {
        this.skeleton = skeleton;
    }

    public boolean wireframe() {
        return wireframe;
    }

    public void setWireframe(boolean wireframe) {
        this.wireframe = wireframe;
    }

    public boolean help() {
        return help;
    }

    public void setHelp(boolean help) {
        this.help = help;
    }

    public int instances() {
        return INSTANCE_STEPS[instanceStep];
    }

    /** Copies per row of the instance grid: about square. */
    public int columns() {
        return DrawSettings.squareColumns(instances());
    }

    public void moreInstances() {
        instanceStep = Math.min(INSTANCE_STEPS.length - 1, instanceStep + 1);
    }

    public void fewerInstances() {
        instanceStep = Math.max(0, instanceStep - 1);
    }

    public int selectedJoint() {
        return selectedJoint;
    }

    /** Selects joint {@code j} wrapped into {@code [0, jointCount)}. */
    public void selectJoint(int j, int jointCount) {
        selectedJoint = jointCount <= 0 ? 0 : Math.floorMod(j, jointCount);
    }
}
