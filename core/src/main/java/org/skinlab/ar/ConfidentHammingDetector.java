package org.skinlab.ar;

import boofcv.abst.filter.binary.InputToBinary;
import boofcv.alg.fiducial.square.DetectFiducialSquareHamming;
import boofcv.alg.fiducial.square.FoundFiducial;
import boofcv.alg.shapes.polygon.DetectPolygonBinaryGrayRefine;
import boofcv.factory.fiducial.ConfigFiducialHammingDetector;
import boofcv.factory.fiducial.ConfigHammingMarker;
import boofcv.factory.filter.binary.FactoryThresholdBinary;
import boofcv.factory.shape.FactoryShapeDetector;
import boofcv.struct.image.GrayF32;
import boofcv.struct.image.GrayU8;
import org.ddogleg.struct.DogArray;
import org.ddogleg.struct.DogArray_I32;

/**
 * BoofCV's square-marker detector (its contours, quadrilaterals, undistorted squares and corner
 * orientation) with our decision on which squares are markers. {@link CodeReader} reads each
 * square's bits with a confidence each and finds the code whose wrong bits cost least; the square
 * is a marker when
 * <ol>
 * <li>the wrong bits' confidences sum to at most {@code maxWeightedErrors}: a wrong crisp bit
 * costs about 1, a wrong bit smeared by blur little, and</li>
 * <li>at most {@code maxUncertainBits} bits are uncertain: a square whose inside is gray mush (a
 * texture, a photo, a blurred pattern) does not show a code, whatever code it is nearest to.</li>
 * </ol>
 * Clutter that looks like a marker (a black-bordered square of random bits, another dictionary's
 * code, a checkerboard's square) has crisp cells, so its wrong bits are expensive; a far, tilted
 * marker's wrong bits come from blur, so they are cheap. BoofCV's own rule (wrong bits plus half
 * the count of ambiguous bits, wrong or right, at most {@code minimumHamming}) charges a small
 * marker for every smeared bit, and with a cap low enough to keep clutter out it loses markers
 * whose bits all read right.
 *
 * <p>BoofCV then matches the square again its own way (that orients the corners); a square is kept
 * only when BoofCV's code is ours. One instance per thread.
 */
final class ConfidentHammingDetector extends DetectFiducialSquareHamming<GrayU8> {
    private final CodeReader reader;
    private final double maxWeightedErrors;
    private final int maxUncertainBits;
    /** Per square we accepted, in BoofCV's order of found markers, the code we read. */
    private final DogArray_I32 accepted = new DogArray_I32();

    /**
     * @param dictionary        the markers' codes
     * @param maxWeightedErrors the most the wrong bits' confidences may sum to
     * @param maxUncertainBits  the most bits of confidence at most {@link CodeReader#UNCERTAIN}
     */
    static ConfidentHammingDetector create(MarkerDictionary dictionary, double maxWeightedErrors, int maxUncertainBits) {
        ConfigHammingMarker code = dictionary.config();
        ConfigFiducialHammingDetector c = new ConfigFiducialHammingDetector();
        return new ConfidentHammingDetector(code, c, FactoryThresholdBinary.threshold(c.configThreshold, GrayU8.class),
                FactoryShapeDetector.polygon(c.squareDetector, GrayU8.class), maxWeightedErrors, maxUncertainBits);
    }

    private ConfidentHammingDetector(ConfigHammingMarker code, ConfigFiducialHammingDetector config,
            InputToBinary<GrayU8> binary, DetectPolygonBinaryGrayRefine<GrayU8> squares, double maxWeightedErrors,
            int maxUncertainBits) {
        super(code, config.minimumBlackBorderFraction, binary, squares, GrayU8.class);
        reader = new CodeReader(code);
        this.maxWeightedErrors = maxWeightedErrors;
        this.maxUncertainBits = maxUncertainBits;
        // BoofCV's own match only orients the square we accepted: any code within the correctable
        // distance, no charge for ambiguous bits (our rule has judged them).
        description.minimumHamming = (code.minimumHamming - 1) / 2;
        setAmbiguousPenaltyFrac(0);
    }

    @Override
    public void process(GrayU8 gray) {
        accepted.reset();
        super.process(gray);
        // Keep what both read as the same code.
        DogArray<FoundFiducial> found = getFound();
        for (int i = found.size - 1; i >= 0; i--) {
            if (found.get(i).id != accepted.get(i)) {
                found.remove(i);
            }
        }
    }

    @Override
    protected boolean processSquare(GrayF32 square, Result result, double edgeInside, double edgeOutside) {
        if (!reader.read(square, edgeInside, edgeOutside) || reader.cost() > maxWeightedErrors
                || reader.uncertain() > maxUncertainBits) {
            return false;
        }
        int id = reader.id();
        if (!super.processSquare(square, result, edgeInside, edgeOutside)) {
            return false;
        }
        accepted.add(id);
        return true;
    }
}
