package org.skinlab.model;

/**
 * What {@code <asset>} says about the document's frame. Recorded as written: converting to the
 * app's frame (up axis, metres) is a separate, explicit step, so the model stays comparable to
 * other tools that read the same file.
 *
 * @param upAxis        the up axis, {@link UpAxis#Y_UP} when not given
 * @param unitMeter     length of one document unit in metres, 1.0 when not given
 * @param unitName      the unit's name, "meter" when not given
 * @param authoringTool the first {@code <authoring_tool>}, or null
 * @param present       false when the file has no {@code <asset>} at all (tolerated, with a warning)
 */
public record AssetInfo(UpAxis upAxis, double unitMeter, String unitName, String authoringTool, boolean present) {
}
