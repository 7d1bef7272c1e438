package org.skinlab.skinning;

/**
 * Skins a geometry whose render vertices share positions ({@link SkinnedGeometry#sharedPositions()})
 * by deforming each position once into a frame, with a kernel built on the position-level
 * geometry, and then deriving every point from its position's frame ({@link FrameExpansion}).
 *
 * <p>Each call deforms all positions, whatever range of points it is asked for: the frames of a
 * range's positions are not a contiguous range. So split a frame over threads at the level of the
 * position kernel, not by wrapping this skinner in a {@link ParallelSkinner} (which would repeat
 * the position work per chunk). The frames live in a per-thread scratch array.
 */
final class SharedPositionSkinner extends AbstractSkinner {
    private final Skinner positionKernel;
    private final FrameExpansion expansion;
    private final int[] frameOfPoint;
    private final float[] restNormals;
    private final int positionCount;
    private final ThreadLocal<float[]> frames;

    SharedPositionSkinner(SkinnedGeometry geometry, Skinner positionKernel, FrameExpansion expansion) {
        super(positionKernel.method(), positionKernel.implementation() + ", each position once ("
                + expansion.implementation() + " expansion)", geometry, positionKernel.normalTransform());
        this.positionKernel = positionKernel;
        this.expansion = expansion;
        this.frameOfPoint = geometry.frameOfPointArray();
        this.restNormals = geometry.normalArray();
        this.positionCount = positionKernel.geometry().pointCount();
        int size = FRAME_FLOATS * positionCount;
        this.frames = ThreadLocal.withInitial(() -> new float[size]);
    }

    /** The kernel that deforms the positions. */
    Skinner positionKernel() {
        return positionKernel;
    }

    @Override
    public void skin(JointPalette palette, float[] outPositions, float[] outNormals, int from, int to) {
        float[] f = frames.get();
        positionKernel.skinFrames(palette, f, 0, positionCount);
        expansion.expand(f, frameOfPoint, restNormals, outPositions, outNormals, from, to,
                normals == NormalTransform.INVERSE_TRANSPOSE);
    }

    @Override
    public void skinFrames(JointPalette palette, float[] outFrames, int from, int to) {
        float[] f = frames.get();
        positionKernel.skinFrames(palette, f, 0, positionCount);
        for (int i = from; i < to; i++) {
            System.arraycopy(f, FRAME_FLOATS * frameOfPoint[i], outFrames, FRAME_FLOATS * i, FRAME_FLOATS);
        }
    }
}
