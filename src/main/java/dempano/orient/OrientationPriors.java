package dempano.orient;

/**
 * What is known before matching: each angle either pinned (a number) or free within bounds.
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
 */
public record OrientationPriors(double headingDeg, double headingRangeDeg, double pitchDeg, double rollDeg,
                                double hfovMinDeg, double hfovMaxDeg, double pitchLimitDeg, double rollLimitDeg) {
    /** Default bounds: pitch ± 15°, roll ± 8°, horizontal FOV 15°–100°. */
    public static final OrientationPriors NONE = new OrientationPriors(Double.NaN, 180, Double.NaN, Double.NaN,
            15, 100, 15, 8);

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
        return new OrientationPriors(centreDeg, rangeDeg, pitchDeg, rollDeg, hfovMinDeg, hfovMaxDeg, pitchLimitDeg, rollLimitDeg);
    }

    public OrientationPriors withPitchDeg(double v) {
        return new OrientationPriors(headingDeg, headingRangeDeg, v, rollDeg, hfovMinDeg, hfovMaxDeg, pitchLimitDeg, rollLimitDeg);
    }

    public OrientationPriors withRollDeg(double v) {
        return new OrientationPriors(headingDeg, headingRangeDeg, pitchDeg, v, hfovMinDeg, hfovMaxDeg, pitchLimitDeg, rollLimitDeg);
    }

    public OrientationPriors withHfovRangeDeg(double min, double max) {
        return new OrientationPriors(headingDeg, headingRangeDeg, pitchDeg, rollDeg, min, max, pitchLimitDeg, rollLimitDeg);
    }

    boolean headingPinned() {
        return !Double.isNaN(headingDeg) && headingRangeDeg == 0;
    }

    boolean hfovPinned() {
        return hfovMaxDeg == hfovMinDeg;
    }
}
