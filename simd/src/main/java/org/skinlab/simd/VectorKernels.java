package org.skinlab.simd;

import jdk.incubator.vector.FloatVector;

import org.skinlab.skinning.DeformationExpansion;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.Skinner;
import org.skinlab.skinning.SkinningMethod;

/** The Vector API kernels; loaded only once {@link VectorSkinnerProvider} saw the module. */
final class VectorKernels {
    /** Joints the kernels index (stored as char). */
    static final int MAX_JOINTS = 65536;

    private VectorKernels() {
    }

    /** 256-bit float vectors are done in hardware (AVX2 or wider). */
    static boolean fastOnThisMachine() {
        return FloatVector.SPECIES_PREFERRED.vectorBitSize() >= Lanes.S.vectorBitSize();
    }

    static DeformationExpansion deformationExpansion(int[] deformationOfPoint, float[] restNormals) {
        return new VectorDeformationExpansion(deformationOfPoint, restNormals);
    }

    static Skinner create(SkinningMethod method, SkinnedGeometry geometry, NormalTransform normals) {
        switch (method) {
            case LBS:
                return new VectorLbsSkinner(geometry, normals);
            case DQS:
                return new VectorDqsSkinner(geometry, normals);
            case COR:
                return new VectorCorSkinner(geometry, normals);
            case BFDQS:
                return new VectorBulgeFreeDqsSkinner(geometry, normals);
            case STBS_LBS:
            case STBS_DQS:
                return new VectorStbsSkinner(method, geometry, normals);
            case SPLINE:
                return new VectorSplineSkinner(geometry, normals);
            default:
                return null;
        }
    }
}
