package org.skinlab.android.logic;

import org.skinlab.mixer.Mixer;

/**
 * Keeps a character that root motion walks within a {@link MarkerArea} by turning it back towards
 * the centre, a little each simulation step: the placement's heading changes by at most
 * {@link #MAX_TURN_RADIANS} a step, never at once.
 *
 * <p>The rule, per step: the direction of travel is the placement's move since the last step (so
 * any clip's forward axis and its own turning count). Turning at the step's rate the character
 * would walk a circle of radius rho = step length / turn; the turn per step is chosen so that rho
 * is {@link #TURN_RADIUS_OVER_AREA} of the area's radius R (capped at {@link #MAX_TURN_RADIANS}),
 * the same path at any speed. A character heading straight out and turning from distance r
 * reaches at most sqrt(r^2 + rho^2) + rho from the centre, which is R for r = sqrt(R^2 - 2 R rho)
 * (with R a step less, for the steps' chords): inside that inner radius it walks straight; beyond it, it turns towards the centre by the
 * step's turn, or by less once the centre is nearly ahead. So a clip whose step stays under
 * {@code MAX_TURN_RADIANS * TURN_RADIUS_OVER_AREA * R} never leaves the circle; a faster one (rho
 * beyond R / 2, the inner radius then zero) turns towards the centre all the time and leaves it by
 * up to about 2 rho - R before it comes back.
 *
 * <p>Not thread-safe: one simulation thread calls {@link #steer} (inside
 * {@code SkeletalAnimatedMesh.direct}, once a step).
 */
public final class MarkerSteering {
    /** The most the heading turns in one step: at 60 steps a second, one turn a second. */
    public static final double MAX_TURN_RADIANS = Math.toRadians(6);
    /** The turning circle's radius over the area's (below 1/2, so that the inner radius exists). */
    public static final double TURN_RADIUS_OVER_AREA = 0.4;

    private final double ux;
    private final double uy;
    private final double uz;
    private final double radius;
    private final double[] position = new double[4];
    private boolean hasLast;
    private double lastX;
    private double lastY;
    private double lastZ;

    public MarkerSteering(MarkerArea area) {
        double[] up = area.up();
        ux = up[0];
        uy = up[1];
        uz = up[2];
        radius = area.radius();
    }

    /** One step's steering: reads the mixer's placement and turns it if the rule says so. */
    public void steer(Mixer mixer) {
        double turn = turn(mixer.placementPosition(position));
        if (turn != 0) {
            mixer.turnPlacement(turn);
        }
    }

    /**
     * The rule alone: the turn, in radians about the up axis, for a placement now at {@code
     * placement} (x, y, z, heading, as {@code Mixer.placementPosition} gives them) after the
     * placement given to the call before. 0 on the first call and while the character stands.
     */
    public double turn(double[] placement) {
        double x = placement[0];
        double y = placement[1];
        double z = placement[2];
        double height = x * ux + y * uy + z * uz;
        x -= height * ux;
        y -= height * uy;
        z -= height * uz;
        boolean moved = hasLast;
        double dx = x - lastX;
        double dy = y - lastY;
        double dz = z - lastZ;
        hasLast = true;
        lastX = x;
        lastY = y;
        lastZ = z;
        double step = Math.sqrt(dx * dx + dy * dy + dz * dz);
        if (!moved || !(step > 1e-9 * radius)) {
            return 0;
        }
        double maxTurn = Math.min(MAX_TURN_RADIANS, step / (TURN_RADIUS_OVER_AREA * radius));
        double rho = step / maxTurn;
        // One step less than the radius: the turn begins up to a step late, and steps are chords.
        double limit = Math.max(0, radius - step);
        double inner = Math.sqrt(Math.max(0, limit * limit - 2 * limit * rho));
        if (x * x + y * y + z * z <= inner * inner) {
            return 0;
        }
        // The signed angle about up from the direction of travel to the centre (-position).
        double cx = dy * -z - dz * -y;
        double cy = dz * -x - dx * -z;
        double cz = dx * -y - dy * -x;
        double angle = Math.atan2(cx * ux + cy * uy + cz * uz, -(dx * x + dy * y + dz * z));
        return Math.max(-maxTurn, Math.min(maxTurn, angle));
    }

    /** Forgets the last placement (after the placement was reset): the next step only measures. */
    public void reset() {
        hasLast = false;
    }
}
