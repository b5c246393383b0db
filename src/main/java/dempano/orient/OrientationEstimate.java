package dempano.orient;

/**
 * Where a photo's camera pointed, as found by matching its skyline, and how sure the match is.
 *
 * <p>Confidence: the residuals are the differences, in photo pixels, between the photo's skyline and the rendered
 * skyline projected with the estimate (one per sampled photo column). The truncations and the scores are those of
 * the image matched in: a large photo is matched scaled down ({@link MatchImage}), and its residual then scaled back
 * ({@link #withResidualScaled}). {@code score} is their mean truncated
 * absolute value divided by the truncation {@link OrientationEstimator#TRUNCATION_PX} (0 = every sample on the
 * rendered skyline, 1 = none within the truncation). {@code marginScore} is the score of the best other heading
 * (a separately refined local optimum more than {@link OrientationEstimator#DISTINCT_HEADING_DEG} away) minus
 * the best score: near 0, two headings explain the skyline about equally well. {@code unsure} is set when the
 * margin is below {@link OrientationEstimator#UNSURE_MARGIN} or fewer than
 * {@link OrientationEstimator#UNSURE_INLIER_SHARE} of the samples fit.
 *
 * @param headingDeg        optical axis, degrees clockwise from true north, [0, 360)
 * @param pitchDeg          optical axis above the horizontal, degrees
 * @param rollDeg           degrees, positive clockwise as the photographer sees it
 * @param hfovDeg           horizontal field of view, degrees
 * @param residualPx        root mean square of the fitting residuals (within the truncation), photo pixels
 * @param inlierShare       weighted share of skyline samples within the truncation, [0, 1]
 * @param score             see above, [0, 1]; with inner edges matched, the weighted mean over skyline samples and
 *                          edge points (edges weighted {@link OrientationEstimator#EDGE_WEIGHT} in all)
 * @param edgeScore         mean truncated distance of the photo's inner edge points to the rendered depth edges,
 *                          over the truncation, [0, 1] (texture edges keep it well above 0); NaN when no edges were
 *                          matched
 * @param second            the best other pose (heading more than {@link OrientationEstimator#DISTINCT_HEADING_DEG}
 *                          away, refined as the best was), searched over every heading even when a prior or a pinned
 *                          heading restricts the estimate; null when there was none
 * @param marginScore       second score − best score; NaN when there was no other heading; negative where a pinned
 *                          heading or a prior holds a pose that fits worse than one outside it (unsure)
 * @param unsure            whether the match should not be trusted (see above)
 * @param samples           skyline samples used
 * @param seconds           time spent matching (not rendering), seconds
 * @param altitudeOffsetMetres how much higher the eye was than assumed, metres, as the skyline's distances tell it
 *                          (a near ridge moves against a far one as the eye rises); NaN where not estimated: the
 *                          altitude pinned, the offset not constrained (its standard error above
 *                          {@link OrientationEstimator#ALTITUDE_SIGMA_MAX_METRES}) or not significant, or the estimate
 *                          unsure from every eye tried. When given, the pose and the residual, share and score are
 *                          those of the pose fitted with it; the margin and the unsure flag compare headings at the
 *                          assumed eye when the estimate was confident there, else at the eye found (see
 *                          {@link OrientationEstimator#withAltitude}). With a NaN standard error, the eye the pose was
 *                          found from, not a measurement: one of {@link OrientationEstimator#RAISED_EYES_METRES}, from
 *                          which the photo fits confidently and better than from the assumed eye while the skyline
 *                          does not measure the altitude
 * @param altitudeSigmaMetres the offset's standard error, metres: the larger of the formal one (from the fit's
 *                          residuals, at least {@link OrientationEstimator#ALTITUDE_RESIDUAL_FLOOR_PX} px each) and the
 *                          delete-a-block jackknife's ({@link OrientationEstimator#ALTITUDE_JACKKNIFE_BLOCKS} blocks of
 *                          the skyline), which counts errors alike over neighbouring skyline samples (on the benchmark, 39 of 45 offsets within two of it);
 *                          NaN where not estimated,
 *                          or where the offset is an eye searched from and not measured (see above)
 */
public record OrientationEstimate(double headingDeg, double pitchDeg, double rollDeg, double hfovDeg,
                                  double residualPx, double inlierShare, double score, double edgeScore,
                                  Pose second,
                                  double marginScore, boolean unsure, int samples, double seconds,
                                  double altitudeOffsetMetres, double altitudeSigmaMetres) {
    /**
     * A camera pose as the estimator fits it.
     *
     * @param headingDeg optical axis, degrees clockwise from true north
     * @param pitchDeg   optical axis above the horizontal, degrees
     * @param rollDeg    degrees, positive clockwise as the photographer sees it
     * @param hfovDeg    horizontal field of view, degrees
     */
    public record Pose(double headingDeg, double pitchDeg, double rollDeg, double hfovDeg) {
    }

    /** The estimated pose. */
    public Pose pose() {
        return new Pose(headingDeg, pitchDeg, rollDeg, hfovDeg);
    }

    /** The best other heading, degrees; NaN when there was none. */
    public double secondHeadingDeg() {
        return second == null ? Double.NaN : second.headingDeg();
    }

    /**
     * The same estimate with the residual multiplied by {@code photoRowsPerRow}: from the pixels of the image matched
     * in to those of the photo it was scaled from ({@link MatchImage#scale()}). Everything else is unitless or in
     * degrees.
     */
    public OrientationEstimate withResidualScaled(double photoRowsPerRow) {
        return new OrientationEstimate(headingDeg, pitchDeg, rollDeg, hfovDeg, residualPx * photoRowsPerRow, inlierShare,
                score, edgeScore, second, marginScore, unsure, samples, seconds, altitudeOffsetMetres, altitudeSigmaMetres);
    }

    /**
     * The same estimate with an eye's altitude offset and its standard error, metres, and the time spent matching in
     * all, seconds.
     */
    public OrientationEstimate withAltitudeOffset(double metres, double sigmaMetres, double totalSeconds) {
        return new OrientationEstimate(headingDeg, pitchDeg, rollDeg, hfovDeg, residualPx, inlierShare, score, edgeScore,
                second, marginScore, unsure, samples, totalSeconds, metres, sigmaMetres);
    }

    /** One line for a log. */
    public String summary() {
        return String.format(java.util.Locale.ROOT, "heading %.2f°, pitch %.2f°, roll %.2f°, hfov %.2f°;"
                        + " residual %.2f px, %.0f %% of %d skyline samples fit, edge score %.3f, margin %.3f over heading %.1f°%s",
                headingDeg, pitchDeg, rollDeg, hfovDeg, residualPx, 100 * inlierShare, samples, edgeScore, marginScore,
                secondHeadingDeg(), unsure ? " — UNSURE" : "") + (Double.isNaN(altitudeOffsetMetres) ? ""
                : Double.isNaN(altitudeSigmaMetres) ? String.format(java.util.Locale.ROOT,
                        "; found from an eye %+.0f m from the altitude assumed (not measured: the skyline does not tell)",
                        altitudeOffsetMetres)
                : String.format(java.util.Locale.ROOT, "; eye %+.1f ± %.1f m from the altitude assumed", altitudeOffsetMetres,
                altitudeSigmaMetres));
    }
}
