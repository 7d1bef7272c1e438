/**
 * The immutable, validated model of an imported file: meshes, skins, morphs, materials and the
 * images they name, the node hierarchy, mesh instances and animation clips, in the document's own
 * frame and units. Runtime code trusts it:
 * indices are in range, counts agree, numbers are finite. Arrays are copied in and out, so the
 * per-frame path copies what it needs once, into its own flat buffers.
 * Depends on nothing of ours, and on JOML only for its read-only matrices.
 */
package org.skinlab.model;
