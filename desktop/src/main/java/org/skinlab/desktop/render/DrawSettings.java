package org.skinlab.desktop.render;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.skinlab.scene.ModelFraming;
import org.skinlab.skinning.SkinningMethod;

/**
 * What one draw of a model shows: camera, placement, where the skinning runs and with which
 * method, the view, the instance grid. Mutable and reused every frame (the render loop allocates
 * nothing); owned by the render thread.
 */
public final class DrawSettings {
    /** How colours are chosen. */
    public enum View {
        /** Materials, textures and light. */
        SHADED,
        /** Colour by the weight of {@link DrawSettings#selectedNode}. */
        WEIGHTS,
        /** Colour by the distance between the LBS and the DQS position of each vertex. */
        DIFFERENCE,
        /**
         * As {@link #SHADED}, darkened on every other square of a 3-D checker fixed to each
         * vertex's rest position, so that twist and stretch show in the pattern.
         */
        CHECKER
    }

    /**
     * The top (red) of the difference view's colour map unless the user chooses another: this
     * share of the model's size.
     */
    public static final float DIFFERENCE_FULL = 0.05f;
    /** The checker view's squares across the model's size (the diagonal of its bind-pose bounds). */
    public static final float CHECKER_SQUARES = 12f;

    public final Matrix4f viewProjection = new Matrix4f();
    /** Upright and unit fix and placement (ModelFraming). */
    public final Matrix4f model = new Matrix4f();
    public final Vector3f eye = new Vector3f();
    /** Skin in the vertex shader from the palette; false draws the frame's CPU-skinned mesh. */
    public boolean gpuSkinning = true;
    /**
     * The method the GPU skins with, one with shader code ({@code SkinningGlsl.hasCode}; CPU-skinned
     * frames carry their own).
     */
    public SkinningMethod method = SkinningMethod.LBS;
    public View view = View.SHADED;
    /**
     * The joint the weight view shows, as its scene node (each geometry has its own palette
     * order; a geometry the joint does not influence shows weight 0).
     */
    public int selectedNode = -1;
    /** The value at the top of the colour map: weight 1, or a distance in model units. */
    public float scalarFull = 1f;
    /** The checker view's square side, in the rest shape's units. */
    public float checkerCell = 1f;
    public int instances = 1;
    /** The grid cell of the first instance drawn (copies with poses of their own are drawn one by one). */
    public int firstInstance;
    /** Grid cells per row; 0: about square for {@link #instances}. */
    public int gridColumns;
    /** Distance between instances in the grid, in world units. */
    public float spacing = 1f;
    public boolean wireframe;

    /** Instances per row of the grid: about square. */
    public int columns() {
        return gridColumns > 0 ? gridColumns : squareColumns(instances);
    }

    /** Columns of an about square grid of {@code instances} copies. */
    public static int squareColumns(int instances) {
        return Math.max(1, (int) Math.ceil(Math.sqrt(instances)));
    }
}
