package org.skinlab.collada;

/**
 * COLLADA writes 4x4 matrices row-major (translation in values 3, 7, 11); JOML and OpenGL store
 * them column-major. Both helpers check the bottom row, which must be (0 0 0 1) for the affine
 * transforms skinning works with.
 */
final class RowMajor {
    private RowMajor() {
    }

    /**
     * How far the bottom row may be from (0 0 0 1) before the importer says so: exporters that
     * compute matrices in float write values such as 0.9999999, which mean 1.
     */
    static final float BOTTOM_ROW_TOLERANCE = 1e-5f;

    /**
     * Warns when the row-major matrix at {@code m[o]} has a bottom row other than (0 0 0 1)
     * (beyond float noise); returns false in that case.
     */
    static boolean checkBottomRow(ImportContext ctx, float[] m, int o, XmlElement where, String what) {
        if (Math.abs(m[o + 12]) > BOTTOM_ROW_TOLERANCE || Math.abs(m[o + 13]) > BOTTOM_ROW_TOLERANCE
                || Math.abs(m[o + 14]) > BOTTOM_ROW_TOLERANCE || Math.abs(m[o + 15] - 1f) > BOTTOM_ROW_TOLERANCE) {
            ctx.warn(where, what + " has bottom row (" + m[o + 12] + " " + m[o + 13] + " " + m[o + 14] + " "
                    + m[o + 15] + "), treated as (0 0 0 1)");
            return false;
        }
        return true;
    }

    /**
     * Converts the row-major matrix at {@code m[o]} to column-major in place; the bottom row
     * becomes exactly (0 0 0 1), with a warning when it was something else.
     */
    static void toColumnMajor(ImportContext ctx, float[] m, int o, XmlElement where, String what) {
        checkBottomRow(ctx, m, o, where, what);
        m[o + 12] = 0f;
        m[o + 13] = 0f;
        m[o + 14] = 0f;
        m[o + 15] = 1f;
        for (int r = 0; r < 4; r++) {
            for (int c = r + 1; c < 4; c++) {
                float t = m[o + 4 * r + c];
                m[o + 4 * r + c] = m[o + 4 * c + r];
                m[o + 4 * c + r] = t;
            }
        }
    }
}
