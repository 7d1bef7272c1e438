package org.skinlab.gltf;

/**
 * What the importer agrees to allocate, checked against the sizes a file declares before any
 * array is made (a few bytes of hostile JSON must not make it reserve gigabytes).
 */
final class GltfLimits {
    /** Largest document (a .glb, or a .gltf with its data URIs) and largest external buffer. */
    static final int MAX_FILE_BYTES = 1 << 30;
    /** Most numbers one accessor may decode to (count times components): 256 MB of floats. */
    static final long MAX_ACCESSOR_VALUES = 1L << 26;
    /** Most triangles one mesh may have (strips and fans of huge non-indexed primitives). */
    static final long MAX_TRIANGLES = 1L << 25;

    /** Values (4 bytes each) the readers may allocate per byte of document and buffer data... */
    static final long BUDGET_PER_BYTE = 16;
    /** ... plus this many, so that small documents with sparse data still load. */
    static final long BUDGET_BASE = 1L << 24;

    /** The allocation budget, in 4-byte values, for a document of {@code bytes} bytes of data. */
    static long budget(long bytes) {
        return BUDGET_BASE + BUDGET_PER_BYTE * bytes;
    }

    private GltfLimits() {
    }
}
