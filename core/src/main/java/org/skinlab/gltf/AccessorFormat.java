package org.skinlab.gltf;

/**
 * The accessor formats of glTF 2.0 (specification 3.6.2): component types, element types and
 * how many bytes an element takes. The one home of these tables for the reader ({@link Accessors})
 * and the checks ({@link GltfDocumentChecks}).
 */
final class AccessorFormat {
    static final int BYTE = 5120;
    static final int UNSIGNED_BYTE = 5121;
    static final int SHORT = 5122;
    static final int UNSIGNED_SHORT = 5123;
    static final int UNSIGNED_INT = 5125;
    static final int FLOAT = 5126;

    private AccessorFormat() {
    }

    /** Bytes per component of a component type, 0 for a type glTF does not define. */
    static int componentSize(int componentType) {
        switch (componentType) {
            case BYTE:
            case UNSIGNED_BYTE:
                return 1;
            case SHORT:
            case UNSIGNED_SHORT:
                return 2;
            case UNSIGNED_INT:
            case FLOAT:
                return 4;
            default:
                return 0;
        }
    }

    /** Components per element of an accessor type ("VEC3": 3), 0 for a type glTF does not define. */
    static int components(String type) {
        switch (type) {
            case "SCALAR":
                return 1;
            case "VEC2":
                return 2;
            case "VEC3":
                return 3;
            case "VEC4":
            case "MAT2":
                return 4;
            case "MAT3":
                return 9;
            case "MAT4":
                return 16;
            default:
                return 0;
        }
    }

    /**
     * Bytes of one element of a defined type, with the column padding of small matrices (each
     * column starts on a 4-byte boundary, specification 3.6.2.4).
     */
    static int elementSize(String type, int componentType) {
        return components(type) / rows(type) * columnStride(type, componentType);
    }

    /** The padding after a small matrix's last column, which a reader never needs. */
    static int trailingPadding(String type, int componentType) {
        return columnStride(type, componentType) - rows(type) * componentSize(componentType);
    }

    /** Rows of a matrix type; a vector or scalar is one column of all its components. */
    static int rows(String type) {
        int components = components(type);
        return type.startsWith("MAT") ? (int) Math.round(Math.sqrt(components)) : components;
    }

    /** Bytes from one column of an element to the next. */
    static int columnStride(String type, int componentType) {
        int bytes = rows(type) * componentSize(componentType);
        return type.startsWith("MAT") ? (bytes + 3) / 4 * 4 : bytes;
    }
}
