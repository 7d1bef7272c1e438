package org.skinlab.skinning;

/**
 * A source of faster skinners than the scalar ones, found with {@link java.util.ServiceLoader}
 * (e.g. the desktop's JDK Vector API kernels). Core stays plain Java that Android can run; a
 * platform adds a provider by putting it on the class path.
 */
public interface SkinnerProvider {
    /**
     * A skinner for the geometry, or null when this provider does not handle the case (e.g. an
     * influence count it has no kernel for, or no SIMD support on this machine).
     *
     * @param method   the method to skin with
     * @param geometry the geometry the skinner is bound to; for CoR it carries its centres of rotation
     * @param normals  how the skinner moves normals
     * @return a new skinner, or null to leave the case to another provider or the scalar kernels
     */
    Skinner create(SkinningMethod method, SkinnedGeometry geometry, NormalTransform normals);

    /**
     * A faster {@link DeformationExpansion} than the scalar one for this mapping and these rest normals
     * (see {@link DeformationExpansion#scalar}), or null.
     *
     * @param deformationOfPoint per point, the index of the deformation it takes
     *                           ({@link SkinnedGeometry#deformationOfPointArray()})
     * @param restNormals        the rest normals, 3 floats per point, bind space
     * @return a new expansion, or null (the default) to use the scalar one
     */
    default DeformationExpansion deformationExpansion(int[] deformationOfPoint, float[] restNormals) {
        return null;
    }
}
