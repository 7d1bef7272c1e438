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
     *
     * <p>Bind-time work: a method's kernel computes its bindings here (BFDQS's, SPLINE's), and a
     * SIMD kernel copies the geometry into its layout; make skinners where a model is loaded.
     *
     * @param method   the method to skin with
     * @param geometry the geometry to bind the skinner to; for {@link SkinningMethod#COR} one with
     *                 centres of rotation ({@link SkinnedGeometry#withCentresOfRotation()})
     * @param normals  how normals move; {@link NormalTransform#NONE} only for a method whose
     *                 {@link SkinningMethod#skinsPositionsOnly()} holds
     * @return a new skinner, sharing positions where that pays ({@link PositionSharing#AUTO})
     * @throws IllegalStateException    for CoR on a geometry without centres of rotation
     * @throws IllegalArgumentException for {@link NormalTransform#NONE} with a method that has no
     *                                  positions-only kernels
     */
    public static Skinner create(SkinningMethod method, SkinnedGeometry geometry, NormalTransform normals) {
        return create(method, geometry, normals, PositionSharing.AUTO);
    }

    /**
     * As {@link #create(SkinningMethod, SkinnedGeometry, NormalTransform)} with a choice of sharing.
     *
     * @param method   the method to skin with
     * @param geometry the geometry to bind the skinner to; for {@link SkinningMethod#COR} one with
     *                 centres of rotation
     * @param normals  how normals move
     * @param sharing  whether to skin each shared position once; no effect on a geometry without
     *                 shared positions
     * @return a new skinner
     * @throws IllegalStateException    for CoR on a geometry without centres of rotation
     * @throws IllegalArgumentException for {@link NormalTransform#NONE} with a method that has no
     *                                  positions-only kernels
     */
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

    /**
     * Whether a skinner from here skins each shared position once (then derives the points).
     *
     * @param skinner a skinner made by this class
     * @return true when it deforms the geometry's {@link SkinnedGeometry#sharedPositions()} and expands them
     */
    public static boolean sharesPositions(Skinner skinner) {
        return skinner instanceof SharedPositionSkinner;
    }

    /**
     * The fastest {@link DeformationExpansion} available for a mapping and rest normals.
     *
     * @param deformationOfPoint per point, the index of the deformation it takes
     *                           ({@link SkinnedGeometry#deformationOfPointArray()})
     * @param restNormals        the rest normals, 3 floats per point, bind space
     * @return a provider's expansion, else {@link DeformationExpansion#scalar}
     */
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

    /**
     * The fastest skinner with exact normals ({@link NormalTransform#INVERSE_TRANSPOSE}).
     *
     * @param method   the method to skin with
     * @param geometry the geometry to bind the skinner to; for {@link SkinningMethod#COR} one with
     *                 centres of rotation
     * @return a new skinner
     * @throws IllegalStateException for CoR on a geometry without centres of rotation
     */
    public static Skinner create(SkinningMethod method, SkinnedGeometry geometry) {
        return create(method, geometry, NormalTransform.INVERSE_TRANSPOSE);
    }

    /**
     * The portable plain-Java skinner (for a geometry that shares positions, the scalar kernel on its
     * positions and the scalar expansion).
     *
     * @param method   the method to skin with
     * @param geometry the geometry to bind the skinner to; for {@link SkinningMethod#COR} one with
     *                 centres of rotation
     * @param normals  how normals move
     * @return a new scalar skinner, sharing positions where that pays ({@link PositionSharing#AUTO})
     * @throws IllegalStateException    for CoR on a geometry without centres of rotation
     * @throws IllegalArgumentException for {@link NormalTransform#NONE} with a method that has no
     *                                  positions-only kernels
     */
    public static Skinner scalar(SkinningMethod method, SkinnedGeometry geometry, NormalTransform normals) {
        return scalar(method, geometry, normals, PositionSharing.AUTO);
    }

    /**
     * As {@link #scalar(SkinningMethod, SkinnedGeometry, NormalTransform)} with a choice of sharing.
     *
     * @param method   the method to skin with
     * @param geometry the geometry to bind the skinner to; for {@link SkinningMethod#COR} one with
     *                 centres of rotation
     * @param normals  how normals move
     * @param sharing  whether to skin each shared position once; no effect on a geometry without
     *                 shared positions
     * @return a new scalar skinner
     * @throws IllegalStateException    for CoR on a geometry without centres of rotation
     * @throws IllegalArgumentException for {@link NormalTransform#NONE} with a method that has no
     *                                  positions-only kernels
     */
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
