package dempano.orient;

import dempano.camera.CameraIntrinsics;

/**
 * What is known before matching: each angle either pinned (a number) or free within bounds, and the lens.
 *
 * @param headingDeg       centre of the heading prior, degrees clockwise from true north; NaN = any heading
 * @param headingRangeDeg  the heading lies within ± this of {@code headingDeg}, degrees, (0, 180]; ignored when
 *                         the heading is NaN; 0 pins the heading
 * @param pitchDeg         pitch pinned to this, degrees positive up; NaN = free within ± {@code pitchLimitDeg}
 * @param rollDeg          roll pinned to this, degrees; NaN = free within ± {@code rollLimitDeg}
 * @param hfovMinDeg       smallest horizontal field of view searched, degrees, (0, 180)
 * @param hfovMaxDeg       largest, degrees, ≥ min (equal = pinned)
 * @param pitchLimitDeg    bound on a free pitch, degrees, (0, 60]
 * @param rollLimitDeg     bound on a free roll, degrees, (0, 45]
 * @param lens             the camera's known shape, at the size of the image matched in: principal point, pixel aspect (fy / fx) and
 *                         lens distortion; its focal length is not used: each field of view tried sets fx =
 *                         (w / 2) / tan(hfov / 2), fy in proportion (so a field of view here, as {@code --hfov-deg}
 *                         with {@code --distortion}, is that of the undistorted image). Null: a distortion-free
 *                         camera with square pixels and the principal point at the image centre
 * @param altitudeFree     whether the eye's altitude may be off: a confident estimate is then refined again with an
 *                         altitude offset, kept where the skyline's distances constrain it (see
 *                         {@link OrientationEstimator#ALTITUDE_SIGMA_MAX_METRES})
 */
public record OrientationPriors(double headingDeg, double headingRangeDeg, double pitchDeg, double rollDeg,
                                double hfovMinDeg, double hfovMaxDeg, double pitchLimitDeg, double rollLimitDeg,
                                CameraIntrinsics lens, boolean altitudeFree) {
    /** Default bounds: pitch ± 15°, roll ± 8°, horizontal FOV 15°–100°; a centred pinhole camera; the altitude pinned. */
    public static final OrientationPriors NONE = new OrientationPriors(Double.NaN, 180, Double.NaN, Double.NaN,
            15, 100, 15, 8, null, false);

    public OrientationPriors {
        if (!Double.isNaN(headingDeg) && !(Double.isFinite(headingDeg) && headingRangeDeg >= 0 && headingRangeDeg <= 180)) {
            throw new IllegalArgumentException("heading prior needs a finite centre and a range in [0°, 180°], got "
                    + headingDeg + "° ± " + headingRangeDeg + "°");
        }
        if (!(hfovMinDeg > 0 && hfovMaxDeg >= hfovMinDeg && hfovMaxDeg < 180)) {
            throw new IllegalArgumentException("field-of-view range must satisfy 0 < min ≤ max < 180°, got "
                    + hfovMinDeg + "°–" + hfovMaxDeg + "°");
        }
        if (!(pitchLimitDeg > 0 && pitchLimitDeg <= 60) || !(rollLimitDeg > 0 && rollLimitDeg <= 45)) {
            throw new IllegalArgumentException("pitch limit must be in (0°, 60°] and roll limit in (0°, 45°], got "
                    + pitchLimitDeg + "° and " + rollLimitDeg + "°");
        }
        if (!Double.isNaN(pitchDeg) && !(pitchDeg >= -90 && pitchDeg <= 90) || Double.isInfinite(rollDeg)) {
            throw new IllegalArgumentException("pinned pitch must be in [-90°, 90°] and roll finite, got "
                    + pitchDeg + "° and " + rollDeg + "°");
        }
    }

    public OrientationPriors withHeading(double centreDeg, double rangeDeg) {
        return new OrientationPriors(centreDeg, rangeDeg, pitchDeg, rollDeg, hfovMinDeg, hfovMaxDeg, pitchLimitDeg, rollLimitDeg, lens, altitudeFree);
    }

    public OrientationPriors withPitchDeg(double v) {
        return new OrientationPriors(headingDeg, headingRangeDeg, v, rollDeg, hfovMinDeg, hfovMaxDeg, pitchLimitDeg, rollLimitDeg, lens, altitudeFree);
    }

    public OrientationPriors withRollDeg(double v) {
        return new OrientationPriors(headingDeg, headingRangeDeg, pitchDeg, v, hfovMinDeg, hfovMaxDeg, pitchLimitDeg, rollLimitDeg, lens, altitudeFree);
    }

    public OrientationPriors withHfovRangeDeg(double min, double max) {
        return new OrientationPriors(headingDeg, headingRangeDeg, pitchDeg, rollDeg, min, max, pitchLimitDeg, rollLimitDeg, lens, altitudeFree);
    }

    /** The same priors for a camera of this shape (see {@code lens}); null for a centred pinhole camera. */
    public OrientationPriors withLens(CameraIntrinsics v) {
        return new OrientationPriors(headingDeg, headingRangeDeg, pitchDeg, rollDeg, hfovMinDeg, hfovMaxDeg, pitchLimitDeg,
                rollLimitDeg, v, altitudeFree);
    }

    /** The same priors with the eye's altitude free (or pinned) as {@code altitudeFree} says. */
    public OrientationPriors withAltitudeFree(boolean v) {
        return new OrientationPriors(headingDeg, headingRangeDeg, pitchDeg, rollDeg, hfovMinDeg, hfovMaxDeg, pitchLimitDeg,
                rollLimitDeg, lens, v);
    }

    boolean headingPinned() {
        return !Double.isNaN(headingDeg) && headingRangeDeg == 0;
    }

    boolean hfovPinned() {
        return hfovMaxDeg == hfovMinDeg;
    }
}
