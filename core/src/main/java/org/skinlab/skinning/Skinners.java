package org.skinlab.skinning;

import java.util.ArrayList;
import java.util.List;
import java.util.ServiceLoader;

/**
 * Where skinners come from: the one place that decides between a platform's faster kernels
 * ({@link SkinnerProvider}s on the class path, e.g. the desktop's SIMD ones) and the portable
 * scalar ones. Callers never branch on it.
 */
public final class Skinners {
    private static final List<SkinnerProvider> PROVIDERS = loadProviders();

    private Skinners() {
    }

    private static List<SkinnerProvider> loadProviders() {
        List<SkinnerProvider> found = new ArrayList<>();
        try {
            for (SkinnerProvider p : ServiceLoader.load(SkinnerProvider.class, Skinners.class.getClassLoader())) {
                found.add(p);
            }
        } catch (java.util.ServiceConfigurationError | LinkageError e) {
            // A provider that cannot load here (e.g. a JVM without the incubator module) is skipped:
            // the scalar kernels always work.
        }
        return List.copyOf(found);
    }

    /**
     * The fastest skinner available for the geometry; for one that shares positions
     * ({@link SkinnedGeometry#sharedPositions()}) the fastest kernel on its positions and the fastest
     * {@link DeformationExpansion}.
     */
    public static Skinner create(SkinningMethod method, SkinnedGeometry geometry, NormalTransform normals) {
        return create(method, geometry, normals, PositionSharing.AUTO);
    }

    /** As {@link #create(SkinningMethod, SkinnedGeometry, NormalTransform)} with a choice of sharing. */
    public static Skinner create(SkinningMethod method, SkinnedGeometry geometry, NormalTransform normals,
            PositionSharing sharing) {
        SkinnedGeometry shared = shared(method, normals, geometry, sharing);
        if (shared != null) {
            Skinner positions = create(method, shared, normals);
            return new SharedPositionSkinner(geometry, positions, normals == NormalTransform.NONE ? null : expansion(
                    geometry.deformationOfPointArray(), SharedPositionSkinner.expansionNormals(method, normals, geometry)));
        }
        for (SkinnerProvider p : PROVIDERS) {
            Skinner s;
            try {
                s = p.create(method, geometry, normals);
            } catch (LinkageError e) {
                continue;
            }
            if (s != null) {
                return s;
            }
        }
        return scalar(method, geometry, normals);
    }

    /** The geometry's positions when they are to be skinned once, else null. */
    private static SkinnedGeometry shared(SkinningMethod method, NormalTransform normals, SkinnedGeometry geometry,
            PositionSharing sharing) {
        SkinnedGeometry shared = geometry.sharedPositions();
        if (shared == null || sharing == PositionSharing.NEVER) {
            return null;
        }
        return sharing == PositionSharing.ALWAYS || SharedPositionSkinner.pays(method, normals, geometry.pointCount(),
                shared.pointCount(), geometry.influencesPerPoint()) ? shared : null;
    }

    /** Whether a skinner from here skins each shared position once (then derives the points). */
    public static boolean sharesPositions(Skinner skinner) {
        return skinner instanceof SharedPositionSkinner;
    }

    /** The fastest {@link DeformationExpansion} available for a mapping and rest normals. */
    public static DeformationExpansion expansion(int[] deformationOfPoint, float[] restNormals) {
        for (SkinnerProvider p : PROVIDERS) {
            DeformationExpansion e;
            try {
                e = p.deformationExpansion(deformationOfPoint, restNormals);
            } catch (LinkageError err) {
                continue;
            }
            if (e != null) {
                return e;
            }
        }
        return DeformationExpansion.scalar(deformationOfPoint, restNormals);
    }

    /** The fastest skinner with exact normals ({@link NormalTransform#INVERSE_TRANSPOSE}). */
    public static Skinner create(SkinningMethod method, SkinnedGeometry geometry) {
        return create(method, geometry, NormalTransform.INVERSE_TRANSPOSE);
    }

    /**
     * The portable plain-Java skinner (for a geometry that shares positions, the scalar kernel on its
     * positions and the scalar expansion).
     */
    public static Skinner scalar(SkinningMethod method, SkinnedGeometry geometry, NormalTransform normals) {
        return scalar(method, geometry, normals, PositionSharing.AUTO);
    }

    /** As {@link #scalar(SkinningMethod, SkinnedGeometry, NormalTransform)} with a choice of sharing. */
    public static Skinner scalar(SkinningMethod method, SkinnedGeometry geometry, NormalTransform normals,
            PositionSharing sharing) {
        SkinnedGeometry shared = shared(method, normals, geometry, sharing);
        if (shared != null) {
            Skinner positions = scalar(method, shared, normals);
            return new SharedPositionSkinner(geometry, positions, normals == NormalTransform.NONE ? null
                    : DeformationExpansion.scalar(geometry.deformationOfPointArray(),
                            SharedPositionSkinner.expansionNormals(method, normals, geometry)));
        }
        switch (method) {
            case LBS:
                return new ScalarLbsSkinner(geometry, normals);
            case DQS:
                return new ScalarDqsSkinner(geometry, normals);
            case COR:
                return new ScalarCorSkinner(geometry, normals);
            case BFDQS:
                return new ScalarBulgeFreeDqsSkinner(geometry, normals);
            case STBS_LBS:
            case STBS_DQS:
                return new ScalarStbsSkinner(method, geometry, normals);
            case SPLINE:
                return new ScalarSplineSkinner(geometry, normals);
            default:
                throw new IllegalArgumentException(String.valueOf(method));
        }
    }
}
