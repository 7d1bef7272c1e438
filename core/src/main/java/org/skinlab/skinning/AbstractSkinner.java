package org.skinlab.skinning;

/**
 * What every skinner holds besides its kernel: the method, the geometry it reads, how it moves
 * normals, and a name for reports. Subclasses (scalar here, SIMD in the desktop's simd module)
 * add only their data layout and {@link #skin}.
 */
public abstract class AbstractSkinner implements Skinner {
    private final SkinningMethod method;
    private final String implementation;
    protected final SkinnedGeometry geometry;
    protected final NormalTransform normals;

    protected AbstractSkinner(SkinningMethod method, String implementation, SkinnedGeometry geometry,
            NormalTransform normals) {
        this.method = method;
        this.implementation = implementation;
        this.geometry = geometry;
        this.normals = normals;
    }

    @Override
    public final SkinningMethod method() {
        return method;
    }

    @Override
    public final NormalTransform normalTransform() {
        return normals;
    }

    @Override
    public final SkinnedGeometry geometry() {
        return geometry;
    }

    @Override
    public final String implementation() {
        return implementation;
    }
}
