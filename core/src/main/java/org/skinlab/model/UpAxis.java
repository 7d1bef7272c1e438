package org.skinlab.model;

/** The document's up axis ({@code <asset><up_axis>}); COLLADA's default is {@link #Y_UP}. */
public enum UpAxis {
    X_UP, Y_UP, Z_UP
}
