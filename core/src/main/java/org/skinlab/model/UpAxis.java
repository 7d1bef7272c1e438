package org.skinlab.model;

/** The document's up axis ({@code <asset><up_axis>}); COLLADA's default is {@link #Y_UP}. */
public enum UpAxis {
    /** The +X axis points up; (right, up, in) is (-Y, +X, +Z). */
    X_UP,
    /** The +Y axis points up, as in OpenGL and glTF; (right, up, in) is (+X, +Y, +Z). */
    Y_UP,
    /** The +Z axis points up, as in Blender and 3ds Max; (right, up, in) is (+X, +Z, -Y). */
    Z_UP
}
