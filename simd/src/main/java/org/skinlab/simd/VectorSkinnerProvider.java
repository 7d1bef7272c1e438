package org.skinlab.simd;

import org.skinlab.skinning.DeformationExpansion;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.Skinner;
import org.skinlab.skinning.SkinnerProvider;
import org.skinlab.skinning.SkinningMethod;

/**
 * Offers the Vector API kernels when they can run fast here: the JVM was started with
 * {@code --add-modules jdk.incubator.vector}, its vectors are at least 256 bits wide (otherwise the
 * API silently falls back to a Java loop per lane, far slower than the scalar kernels), and the
 * geometry has at most 65536 joints (any number of influences). In every other case it returns null
 * and core's scalar kernels run. The same conditions hold for its {@link DeformationExpansion}.
 *
 * <p>This class must load without the incubator module, so it names no class of it: the check
 * goes through the module layer, and {@link VectorKernels} is touched only after it passes.
 */
public final class VectorSkinnerProvider implements SkinnerProvider {
    static final String MODULE = "jdk.incubator.vector";

    @Override
    public Skinner create(SkinningMethod method, SkinnedGeometry geometry, NormalTransform normals) {
        if (!moduleAvailable() || geometry.jointCount() > VectorKernels.MAX_JOINTS
                || !VectorKernels.fastOnThisMachine()) {
            return null;
        }
        return VectorKernels.create(method, geometry, normals);
    }

    @Override
    public DeformationExpansion deformationExpansion(int[] deformationOfPoint, float[] restNormals) {
        if (!moduleAvailable() || !VectorKernels.fastOnThisMachine()) {
            return null;
        }
        return VectorKernels.deformationExpansion(deformationOfPoint, restNormals);
    }

    /**
     * Whether the JDK's Vector API can be used here.
     *
     * @return true when the incubator module is in the boot layer (the JVM got {@code --add-modules})
     */
    public static boolean moduleAvailable() {
        return ModuleLayer.boot().findModule(MODULE).isPresent();
    }
}
