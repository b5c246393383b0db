package dempano.orient;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.camera.CameraOrientation;
import java.util.function.DoubleUnaryOperator;
import org.junit.jupiter.api.Test;

/**
 * The altitude refinement against terrain whose skyline is known in closed form from any eye height: a near ridge
 * line 2.5 km away in front of a far range 25 km away (flat earth, heights relative to the assumed eye).
 */
class AltitudeRefinementTest {
    static final int W = 480, H = 320;
    static final double NEAR_METRES = 2500, FAR_METRES = 25_000;

    static double nearHeight(double azDeg) {
        double a = Math.toRadians(azDeg);
        return 200 + 80 * Math.sin(3 * a) + 40 * Math.sin(11 * a + 1);
    }

    static double farHeight(double azDeg) {
        double a = Math.toRadians(azDeg);
        return 1800 + 400 * Math.sin(5 * a + 0.4) + 250 * Math.sin(23 * a + 2.1);
    }

    /** Skyline elevation, degrees, seen from an eye {@code raised} metres above the assumed one. */
    static DoubleUnaryOperator horizon(double raised) {
        return horizon(AltitudeRefinementTest::nearHeight, AltitudeRefinementTest::farHeight, raised);
    }

    static DoubleUnaryOperator horizon(DoubleUnaryOperator near, DoubleUnaryOperator far, double raised) {
        return az -> Math.toDegrees(Math.max(Math.atan2(near.applyAsDouble(az) - raised, NEAR_METRES),
                Math.atan2(far.applyAsDouble(az) - raised, FAR_METRES)));
    }

    /** The reference as a 10 px/° panorama renders it from that eye: rows 0.1° apart, the skyline's distance per column. */
    static OrientationEstimator.Reference reference(double raised, boolean farOnly) {
        return reference(AltitudeRefinementTest::nearHeight, AltitudeRefinementTest::farHeight, raised, farOnly);
    }

    static OrientationEstimator.Reference reference(DoubleUnaryOperator nearHeight, DoubleUnaryOperator farHeight,
                                                    double raised, boolean farOnly) {
        double ppd = 10, top = 45;
        int n = 3600;
        double[] el = new double[n], d = new double[n];
        for (int c = 0; c < n; c++) {
            double az = (c + 0.5) / ppd;
            double nh = nearHeight.applyAsDouble(az), fh = farHeight.applyAsDouble(az);
            double near = Math.atan2(nh - raised, NEAR_METRES), far = Math.atan2(fh - raised, FAR_METRES);
            double e = Math.toDegrees(farOnly ? far : Math.max(near, far));
            int r = (int) Math.ceil((top - e) * ppd - 0.5);
            el[c] = top - r / ppd;
            d[c] = !farOnly && near > far ? Math.hypot(NEAR_METRES, nh - raised) : Math.hypot(FAR_METRES, fh - raised);
        }
        return new OrientationEstimator.Reference(new HorizonProfile(el, d, ppd), null);
    }

    /**
     * A photo's skyline from an eye {@code truth} metres above the assumed one, looking at {@code heading} (pitch 2°,
     * roll −1.5°, 55° field of view), the reference from the assumed eye, and the estimate made there.
     */
    record Photo(Skyline sky, OrientationEstimator.Reference at0, OrientationEstimate pinned) {
        static final OrientationPriors PRIORS = OrientationPriors.NONE.withAltitudeFree(true);

        static Photo of(double truth, double heading) {
            Skyline sky = SyntheticSkyline.project(horizon(truth), W, H, new CameraOrientation(heading, 2, -1.5), 55);
            OrientationEstimator.Reference at0 = reference(0, false);
            return new Photo(sky, at0, OrientationEstimator.estimate(sky, PhotoEdges.NONE, at0.profile(), null, PRIORS));
        }

        /** The estimate refined with the altitude, the reference from other eyes rendered by {@code raised}. */
        OrientationEstimate refined(OrientationEstimator.RaisedReference raised) {
            return OrientationEstimator.withAltitude(pinned, sky, PhotoEdges.NONE, at0, raised, PRIORS);
        }
    }

    @Test
    void anEyeTwentyMetresHigherIsFoundAndThePoseWithIt() {
        double heading = 77.7, pitch = 2, roll = -1.5, hfov = 55, truth = 20;
        Skyline sky = SyntheticSkyline.project(horizon(truth), W, H, new CameraOrientation(heading, pitch, roll), hfov);
        OrientationPriors priors = OrientationPriors.NONE.withAltitudeFree(true);
        OrientationEstimator.Reference at0 = reference(0, false);
        OrientationEstimate pinned = OrientationEstimator.estimate(sky, PhotoEdges.NONE, at0.profile(), null, priors);
        assertFalse(pinned.unsure(), pinned.summary());
        int[] renders = {0};
        OrientationEstimate e = OrientationEstimator.withAltitude(pinned, sky, PhotoEdges.NONE, at0, m -> {
            renders[0]++;
            return reference(m, false);
        }, priors);
        String what = e.summary() + " (altitude pinned: " + pinned.summary() + ")";
        assertEquals(truth, e.altitudeOffsetMetres(), 2, what);
        assertTrue(e.altitudeSigmaMetres() > 0 && e.altitudeSigmaMetres() <= OrientationEstimator.ALTITUDE_SIGMA_MAX_METRES, what);
        assertTrue(OrientationEstimator.headingGap(e.headingDeg(), heading) < 0.05, what);
        assertEquals(pitch, e.pitchDeg(), 0.05, what);
        assertEquals(hfov, e.hfovDeg(), 0.005 * hfov, what);
        assertTrue(e.residualPx() < pinned.residualPx() / 2, what);
        // Pinned at the wrong altitude, the pitch takes up the near ridge's drop and misses the far range's.
        assertTrue(Math.abs(pinned.pitchDeg() - pitch) > 0.1 || OrientationEstimator.headingGap(pinned.headingDeg(), heading) > 0.1
                || Math.abs(pinned.hfovDeg() - hfov) > 0.01 * hfov, what);
        assertTrue(renders[0] >= 1 && renders[0] <= OrientationEstimator.ALTITUDE_RENDERS, "renders " + renders[0]);
    }

    /**
     * {offset metres, standard error metres, whether it is told apart from none}: the benchmark's offsets wrongly kept
     * at the true eye (−0.7 … −1.6 m at 0.2 … 0.5 m), offsets at the 2 m floor and at two standard errors, a standard
     * error over the 5 m cap, NaN.
     */
    static final double[][] OFFSET_DECISIONS = {
        {-1.6, 0.47, 0}, {-0.7, 0.19, 0}, {1.99, 0.1, 0}, {2.0, 0.1, 1}, {-2.0, 0.1, 1}, {3.9, 2, 0}, {4.0, 2, 1},
        {25, 1.7, 1}, {30, 5.01, 0}, {30, 5, 1}, {Double.NaN, 1, 0}, {10, Double.NaN, 0}};

    @Test
    void anOffsetIsKeptAtTwoStandardErrorsAndTwoMetresFromNone() {
        for (double[] row : OFFSET_DECISIONS) {
            assertEquals(row[2] == 1, OrientationEstimator.measuresOffset(row[0], row[1]), java.util.Arrays.toString(row));
        }
    }

    @Test
    void anEstimateUnsureBecauseTheEyeIsWrongIsMadeAgainFromTheEyeFound() {
        // 30 m higher than assumed: at the assumed eye no heading fits the near ridge and the far range together
        // (the best 0.7° off, margin under the threshold); from the eye the best pose proposes, the whole search is
        // made again and is confident.
        double heading = 77.7, truth = 30;
        Photo photo = Photo.of(truth, heading);
        OrientationEstimate pinned = photo.pinned();
        assertTrue(pinned.unsure(), pinned.summary());
        assertTrue(OrientationEstimator.headingGap(pinned.headingDeg(), heading) > 0.3, pinned.summary());
        OrientationEstimate e = photo.refined(m -> reference(m, false));
        String what = e.summary() + " (altitude pinned: " + pinned.summary() + ")";
        assertFalse(e.unsure(), what);
        assertEquals(truth, e.altitudeOffsetMetres(), 3, what);
        assertTrue(OrientationEstimator.headingGap(e.headingDeg(), heading) < 0.1, what);
        assertTrue(e.marginScore() >= OrientationEstimator.UNSURE_MARGIN, what);
        assertTrue(e.second() != null && OrientationEstimator.headingGap(e.secondHeadingDeg(), heading)
                > OrientationEstimator.DISTINCT_HEADING_DEG, what);
    }

    /**
     * Eyes so far off that no pose of the assumed eye is near the truth, found by the last-resort search: {true eye
     * offset metres, heading degrees, the searched eye that finds it, metres}.
     * <ul>
     *   <li>30 m higher than assumed, looking at 185°: from the assumed eye the best pose is 127° off and the second-best
     *       7° off, and the fits from them go down, not up, and are not kept; the search made from the eye raised 20 m
     *       finds the pose, the fit from there the eye. (Session 24 had this at 310°, where the best pose was 141° off;
     *       since the altitude's standard error counts errors alike over neighbouring samples, the wrong pose's fit is
     *       no longer kept there, and the second-best's finds the eye before any raised search.)</li>
     *   <li>30 m lower than assumed (an altitude given too high, as an EXIF GPS altitude), looking at 85°: the best pose
     *       is 109° off, the second-best 133° off, nothing is found from the raised eye 20 m up, and the search from
     *       20 m lower finds the pose, the fit from there the eye.</li>
     * </ul>
     */
    static final double[][] FAR_OFF_EYES = {{30, 185, 20}, {-30, 85, -20}};

    @Test
    void anEyeSoFarOffThatNoPoseOfTheAssumedEyeIsNearIsFoundByASearchFromAnotherEye() {
        for (double[] c : FAR_OFF_EYES) {
            double truth = c[0], heading = c[1], searched = c[2];
            Photo photo = Photo.of(truth, heading);
            OrientationEstimate pinned = photo.pinned();
            assertTrue(pinned.unsure(), pinned.summary());
            assertTrue(OrientationEstimator.headingGap(pinned.headingDeg(), heading) > 90, pinned.summary());
            java.util.List<Double> eyes = new java.util.ArrayList<>();
            OrientationEstimate e = photo.refined(m -> {
                eyes.add(m);
                return reference(m, false);
            });
            String what = "eye " + truth + " m off: " + e.summary() + " (altitude pinned: " + pinned.summary()
                    + "); eyes rendered " + eyes;
            assertFalse(e.unsure(), what);
            assertTrue(OrientationEstimator.headingGap(e.headingDeg(), heading) < 0.1, what);
            assertEquals(truth, e.altitudeOffsetMetres(), 2, what);
            assertTrue(eyes.contains(searched), what);
        }
    }

    @Test
    void loweredEyesAreRefusedAtTheGroundAndOnlyRaisedOnesSearched() {
        // The same photo with the eye assumed at the ground (the renderer refuses every lower eye): the lowered eyes
        // are asked for and refused, nothing else changes, and no answer is made sure by them.
        double heading = 85, truth = -30;
        Photo photo = Photo.of(truth, heading);
        OrientationEstimate pinned = photo.pinned();
        java.util.List<Double> refused = new java.util.ArrayList<>();
        OrientationEstimate e = photo.refined(m -> {
            if (m < 0) {
                refused.add(m);
                throw new IllegalArgumentException("the eye would be below the DEM surface");
            }
            return reference(m, false);
        });
        assertTrue(refused.containsAll(OrientationEstimator.RAISED_EYES_METRES.stream().map(m -> -m).toList()),
                "refused " + refused);
        assertTrue(e.unsure() || OrientationEstimator.headingGap(e.headingDeg(), heading) < 0.5, e.summary());
    }

    /** Far ridges that repeat every 120°: from the assumed eye, three headings fit any photo about equally. */
    static final DoubleUnaryOperator REPEATING_FAR = az -> 1800 + 400 * Math.sin(Math.toRadians(6 * az) + 0.4)
            + 250 * Math.sin(Math.toRadians(21 * az) + 2.1);

    /**
     * A reference whose skyline is {@code elevationDeg} (as a 10 px/° panorama's rows quantize it) and lies all
     * {@link #FAR_METRES} away, whatever the eye: one whose altitude the skyline cannot measure.
     */
    static OrientationEstimator.Reference allFar(DoubleUnaryOperator elevationDeg) {
        double ppd = 10, top = 45;
        double[] el = new double[3600], d = new double[3600];
        for (int c = 0; c < el.length; c++) {
            int r = (int) Math.ceil((top - elevationDeg.applyAsDouble((c + 0.5) / ppd)) * ppd - 0.5);
            el[c] = top - r / ppd;
            d[c] = FAR_METRES;
        }
        return new OrientationEstimator.Reference(new HorizonProfile(el, d, ppd), null);
    }

    @Test
    void aPoseConfidentFromBothRaisedEyesIsKeptWithTheEyeSearchedFromWhereTheSkylineCannotMeasureIt() {
        // Stands for a summit whose own slopes (not the far skyline) change as the eye rises: from the assumed eye the
        // view is ambiguous, from the raised eyes the photo's skyline is seen, but all of it 25 km away, so no fit can
        // tell the eye's height (raising it moves every column alike, as pitch does).
        double heading = 123.4;
        Skyline sky = SyntheticSkyline.project(horizon(30), W, H, new CameraOrientation(heading, 1, 0.5), 50);
        OrientationPriors priors = OrientationPriors.NONE.withAltitudeFree(true);
        OrientationEstimator.Reference at0 = reference(REPEATING_FAR, REPEATING_FAR, 0, true);
        OrientationEstimate pinned = OrientationEstimator.estimate(sky, PhotoEdges.NONE, at0.profile(), null, priors);
        assertTrue(pinned.unsure(), pinned.summary());
        OrientationEstimate e = OrientationEstimator.withAltitude(pinned, sky, PhotoEdges.NONE, at0,
                m -> allFar(horizon(30)), priors);
        String what = e.summary() + " (assumed eye: " + pinned.summary() + ")";
        assertFalse(e.unsure(), what);
        assertTrue(OrientationEstimator.headingGap(e.headingDeg(), heading) < 0.1, what);
        assertEquals(OrientationEstimator.RAISED_EYES_METRES.get(0), e.altitudeOffsetMetres(), 0, what);
        assertTrue(Double.isNaN(e.altitudeSigmaMetres()), what);
        assertTrue(e.summary().contains("not measured"), what);
    }

    @Test
    void raisedEyesThatOnlyConfirmTheAssumedEyesHeadingReportNoEye() {
        // The eye is right and the skyline all far: from the assumed eye the photo's stretch fits at its heading and,
        // a little worse, at a near copy 120° away (unsure); from any other eye it fits at its heading alone, a
        // little better (sure). The eyes told nothing apart: the heading was the assumed eye's best already, so no
        // eye is reported (before: "+20 m, not measured", as for a far skyline at Mount Washington seen from the
        // right eye in the benchmark).
        double heading = 123.4;
        DoubleUnaryOperator skyline = horizon(30);
        Skyline sky = SyntheticSkyline.project(skyline, W, H, new CameraOrientation(heading, 1, 0.5), 50);
        DoubleUnaryOperator withCopy = az -> {
            double gap = ((az - heading - 120) % 360 + 540) % 360 - 180; // from the copy's centre, degrees
            double a = Math.toRadians(az);
            return Math.abs(gap) < 40 ? skyline.applyAsDouble(az - 120) + 0.05 * Math.sin(7 * a)
                    : skyline.applyAsDouble(az) + 0.02 * Math.sin(13 * a);
        };
        OrientationPriors priors = OrientationPriors.NONE.withAltitudeFree(true);
        OrientationEstimator.Reference at0 = allFar(withCopy);
        OrientationEstimate pinned = OrientationEstimator.estimate(sky, PhotoEdges.NONE, at0.profile(), null, priors);
        assertTrue(pinned.unsure() && OrientationEstimator.headingGap(pinned.headingDeg(), heading) < 0.2,
                pinned.summary());
        java.util.List<OrientationEstimate> fromOtherEyes = new java.util.ArrayList<>();
        OrientationEstimate e = OrientationEstimator.withAltitude(pinned, sky, PhotoEdges.NONE, at0, m -> {
            OrientationEstimator.Reference r = allFar(skyline);
            fromOtherEyes.add(OrientationEstimator.estimate(sky, PhotoEdges.NONE, r.profile(), null, priors));
            return r;
        }, priors);
        assertTrue(fromOtherEyes.stream().anyMatch(o -> !o.unsure() && o.score() < pinned.score()
                && OrientationEstimator.headingGap(o.headingDeg(), heading) < 0.2), "the other eyes are sure: " + fromOtherEyes);
        assertSame(pinned, e, e.summary());
    }

    @Test
    void aPoseConfidentFromOneRaisedEyeOnlyIsNotKept() {
        // The same, but from every other eye searched the view is turned, each by another angle: no two eyes agree,
        // the estimate stays as it was.
        Skyline sky = SyntheticSkyline.project(horizon(30), W, H, new CameraOrientation(123.4, 1, 0.5), 50);
        OrientationPriors priors = OrientationPriors.NONE.withAltitudeFree(true);
        OrientationEstimator.Reference at0 = reference(REPEATING_FAR, REPEATING_FAR, 0, true);
        OrientationEstimate pinned = OrientationEstimator.estimate(sky, PhotoEdges.NONE, at0.profile(), null, priors);
        assertTrue(pinned.unsure(), pinned.summary());
        DoubleUnaryOperator skyline = horizon(30);
        OrientationEstimate e = OrientationEstimator.withAltitude(pinned, sky, PhotoEdges.NONE, at0,
                m -> allFar(m == OrientationEstimator.RAISED_EYES_METRES.get(0) ? skyline
                        : az -> skyline.applyAsDouble(az + 90 + 1.3 * m)), priors);
        assertSame(pinned, e, e.summary());
    }

    @Test
    void aSkylineAQuarterOfWhichFitsNoPoseIsNotSearchedFromRaisedEyes() {
        // The photo of the test above with 35 % of its columns covered by something standing 40 px above the skyline
        // (trees, a building): an occluder, which no eye explains; the raised eyes are not even rendered.
        Skyline clear = SyntheticSkyline.project(horizon(30), W, H, new CameraOrientation(123.4, 1, 0.5), 50);
        double[] rows = clear.rowPx().clone();
        for (int i = rows.length / 3; i < rows.length / 3 + (int) (0.35 * rows.length); i++) {
            rows[i] = Math.max(0, rows[i] - 40);
        }
        Skyline sky = new Skyline(clear.widthPx(), clear.heightPx(), rows, clear.weight());
        OrientationPriors priors = OrientationPriors.NONE.withAltitudeFree(true);
        OrientationEstimator.Reference at0 = reference(REPEATING_FAR, REPEATING_FAR, 0, true);
        OrientationEstimate pinned = OrientationEstimator.estimate(sky, PhotoEdges.NONE, at0.profile(), null, priors);
        assertTrue(pinned.unsure() && pinned.inlierShare() < OrientationEstimator.RAISED_EYES_MIN_INLIER_SHARE, pinned.summary());
        java.util.List<Double> eyes = new java.util.ArrayList<>();
        OrientationEstimate e = OrientationEstimator.withAltitude(pinned, sky, PhotoEdges.NONE, at0, m -> {
            eyes.add(m);
            return allFar(horizon(30));
        }, priors);
        assertFalse(eyes.stream().anyMatch(OrientationEstimator.RAISED_EYES_METRES::contains), "eyes rendered " + eyes);
        assertTrue(e.unsure(), e.summary());
    }

    @Test
    void aSkylineThatRepeatsStaysUnsureFromAnyEye() {
        // Both ridges repeat every 120°: three headings fit equally from every eye, so a better altitude cannot make
        // the estimate sure, whether the eye was right or 30 m off.
        DoubleUnaryOperator near = az -> 200 + 80 * Math.sin(Math.toRadians(3 * az)) + 40 * Math.sin(Math.toRadians(9 * az) + 1),
                far = az -> 1800 + 400 * Math.sin(Math.toRadians(6 * az) + 0.4) + 250 * Math.sin(Math.toRadians(21 * az) + 2.1);
        OrientationPriors priors = OrientationPriors.NONE.withAltitudeFree(true);
        OrientationEstimator.Reference at0 = reference(near, far, 0, false);
        for (double truth : new double[] {0, 30, 45}) {
            Skyline sky = SyntheticSkyline.project(horizon(near, far, truth), W, H, new CameraOrientation(40, 2, -1.5), 55);
            OrientationEstimate pinned = OrientationEstimator.estimate(sky, PhotoEdges.NONE, at0.profile(), null, priors);
            assertTrue(pinned.unsure(), pinned.summary());
            // From 30 and 45 m up the altitude itself is found (within 3 m): only the heading stays open.
            OrientationEstimator.AltitudeFit fit = OrientationEstimator.altitudeFit(pinned.pose(), sky, at0,
                    m -> reference(near, far, m, false), priors, OrientationEstimator.UNSURE_ALTITUDE_MIN_METRES);
            assertEquals(truth == 0, fit == null, "eye " + truth + " m up: " + fit);
            if (fit != null) {
                assertEquals(truth, fit.offsetMetres(), 3, fit.toString());
            }
            OrientationEstimate e = OrientationEstimator.withAltitude(pinned, sky, PhotoEdges.NONE, at0,
                    m -> reference(near, far, m, false), priors);
            assertSame(pinned, e, "eye " + truth + " m up: " + e.summary());
        }
    }

    @Test
    void anEyeTheRendererRefusesEndsTheRefinementWithTheEstimateAsItWas() {
        // The photo from 10 m lower than assumed; the renderer refuses every eye below the assumed one (as below the
        // DEM's surface).
        Skyline sky = SyntheticSkyline.project(horizon(-10), W, H, new CameraOrientation(77.7, 2, -1.5), 55);
        OrientationPriors priors = OrientationPriors.NONE.withAltitudeFree(true);
        OrientationEstimator.Reference at0 = reference(0, false);
        OrientationEstimate e = OrientationEstimator.estimate(sky, PhotoEdges.NONE, at0.profile(), null, priors);
        assertFalse(e.unsure(), e.summary());
        int[] refusals = {0};
        OrientationEstimate refined = OrientationEstimator.withAltitude(e, sky, PhotoEdges.NONE, at0, m -> {
            if (m < 0) {
                refusals[0]++;
                throw new IllegalArgumentException("the eye would be below the DEM surface");
            }
            return reference(m, false);
        }, priors);
        assertSame(e, refined, refined.summary());
        assertEquals(1, refusals[0]);
        // Allowed down there, it is found.
        OrientationEstimate allowed = OrientationEstimator.withAltitude(e, sky, PhotoEdges.NONE, at0, m -> reference(m, false), priors);
        assertEquals(-10, allowed.altitudeOffsetMetres(), 1.5, allowed.summary());
    }

    @Test
    void aSkylineAllAtOneDistanceLeavesTheAltitudeAlone() {
        // Only the far range: raising the eye moves every sample alike, which the pitch does too.
        Skyline sky = SyntheticSkyline.project(az -> Math.toDegrees(Math.atan2(farHeight(az) - 20, FAR_METRES)), W, H,
                new CameraOrientation(200, 1, 0.5), 45);
        OrientationPriors priors = OrientationPriors.NONE.withAltitudeFree(true);
        OrientationEstimator.Reference at0 = reference(0, true);
        OrientationEstimate e = OrientationEstimator.estimate(sky, PhotoEdges.NONE, at0.profile(), null, priors);
        OrientationEstimate refined = OrientationEstimator.withAltitude(e, sky, PhotoEdges.NONE, at0, m -> reference(m, true), priors);
        assertSame(e, refined, refined.summary());
        assertTrue(Double.isNaN(refined.altitudeOffsetMetres()));
    }

    @Test
    void theFirstOrderProfileRaisesEachColumnByItsOwnDistance() {
        double[] el = new double[3600], d = new double[3600];
        java.util.Arrays.fill(el, 2);
        java.util.Arrays.fill(d, Double.NaN);
        d[0] = 1000;
        d[1] = 10_000;
        HorizonProfile raised = new HorizonProfile(el, d, 10).raised(20);
        double e = Math.toRadians(2);
        assertEquals(Math.toDegrees(Math.atan2(1000 * Math.sin(e) - 20, 1000 * Math.cos(e))), raised.columnElevationDeg(0), 1e-12);
        assertEquals(Math.toDegrees(Math.atan2(10_000 * Math.sin(e) - 20, 10_000 * Math.cos(e))), raised.columnElevationDeg(1), 1e-12);
        assertEquals(2, raised.columnElevationDeg(2), 0); // distance unknown: kept
        assertFalse(new HorizonProfile(el, 10).hasDistances());
        assertTrue(raised.hasDistances());
    }
}
