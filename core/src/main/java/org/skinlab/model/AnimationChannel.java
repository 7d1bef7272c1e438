package org.skinlab.model;

/**
 * A COLLADA {@code <channel>} resolved to what it animates: values
 * {@code [valueOffset, valueOffset + track.width())} of transform element
 * {@code transformIndex} of node {@code node}, in the element's own value layout
 * ({@link TransformElement}: row-major for matrices, degrees for angles).
 *
 * <p>Examples: {@code Bone/transform} on a matrix is offset 0, width 16;
 * {@code Bone/transform(3)(0)} is offset 3 (column 3, row 0: translation x);
 * {@code Bone/rotateZ.ANGLE} is offset 3, width 1; {@code Bone/translate.Y} is offset 1, width 1.
 *
 * @param node           index into {@link Model#nodes()}
 * @param transformIndex index into that node's {@link Node#transforms()}
 * @param valueOffset    first value of the element this channel drives
 * @param track          the keys; each key's {@link KeyframeTrack#width()} values go to the element's
 *                       values from {@code valueOffset} on
 * @param target         the {@code target} attribute as written, for messages
 */
public record AnimationChannel(int node, int transformIndex, int valueOffset, KeyframeTrack track, String target) {
    /**
     * Number of values the channel drives (the track's width).
     *
     * @return the number of consecutive element values driven, at least 1
     */
    public int valueCount() {
        return track.width();
    }
}
