package dempano.orient;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.camera.CameraOrientation;
import org.junit.jupiter.api.Test;

/** The estimator against skylines projected from an analytic horizon with known poses. */
class OrientationEstimatorTest {
    static final int W = 480, H = 320;

    static double headingError(OrientationEstimate e, double truth) {
        return OrientationEstimator.headingGap(e.headingDeg(), truth);
    }

    @Test
    void findsHeadingPitchRollAndFovFromAnExactSkyline() {
        HorizonProfile profile = SyntheticSkyline.profile(SyntheticSkyline::ridge, 10);
        double[][] poses = {{123.4, 4, -3, 50}, {301.7, -2, 2.5, 25}, {12.2, 8, 4, 85}};
        for (double[] p : poses) {
            Skyline sky = SyntheticSkyline.project(SyntheticSkyline::ridge, W, H, new CameraOrientation(p[0], p[1], p[2]), p[3]);
            OrientationEstimate e = OrientationEstimator.estimate(sky, profile, OrientationPriors.NONE);
            String what = e.summary() + " for truth " + java.util.Arrays.toString(p);
            // Profile sampled at 0.1°, linear between samples: its error bounds what can be recovered.
            assertTrue(headingError(e, p[0]) < 0.05, what);
            assertEquals(p[1], e.pitchDeg(), 0.05, what);
            assertEquals(p[2], e.rollDeg(), 0.1, what);
            assertEquals(p[3], e.hfovDeg(), 0.005 * p[3], what);
            assertTrue(e.residualPx() < 0.5, what);
            assertFalse(e.unsure(), what);
        }
    }

    @Test
    void skylineHiddenOverAThirdOfTheColumnsStillMatches() {
        HorizonProfile profile = SyntheticSkyline.profile(SyntheticSkyline::ridge, 10);
        Skyline sky = SyntheticSkyline.project(SyntheticSkyline::ridge, W, H, new CameraOrientation(211, 2, 1), 40);
        double[] rows = sky.rowPx();
        for (int x = 0; x < W; x++) {
            // Three "trees": the found edge sits 15–60 px above the true skyline.
            if (x % 160 < 53 && !Double.isNaN(rows[x])) {
                rows[x] = Math.max(0, rows[x] - 15 - 45 * Math.abs(Math.sin(x * 0.07)));
            }
        }
        Skyline occluded = new Skyline(W, H, rows, sky.weight());
        OrientationEstimate e = OrientationEstimator.estimate(occluded, profile, OrientationPriors.NONE);
        assertTrue(headingError(e, 211) < 0.1, e.summary());
        assertEquals(40, e.hfovDeg(), 0.4, e.summary());
        assertTrue(e.inlierShare() > 0.6 && e.inlierShare() < 0.72, e.summary());
    }

    @Test
    void aPeriodicHorizonIsFlaggedUnsure() {
        // Period 30°: twelve headings explain the photo equally well.
        java.util.function.DoubleUnaryOperator periodic = az -> 5 + 3 * Math.sin(Math.toRadians(12 * az));
        HorizonProfile profile = SyntheticSkyline.profile(periodic, 10);
        Skyline sky = SyntheticSkyline.project(periodic, W, H, new CameraOrientation(100, 0, 0), 20);
        OrientationEstimate e = OrientationEstimator.estimate(sky, profile, OrientationPriors.NONE);
        assertTrue(e.unsure(), e.summary());
        assertTrue(e.marginScore() < 0.02, e.summary());
        assertEquals(0, Math.IEEEremainder(e.headingDeg() - 100, 30), 0.05, e.summary());
    }

    @Test
    void pinnedValuesStayPinnedAndAHeadingPriorLimitsTheSearch() {
        HorizonProfile profile = SyntheticSkyline.profile(SyntheticSkyline::ridge, 10);
        Skyline sky = SyntheticSkyline.project(SyntheticSkyline::ridge, W, H, new CameraOrientation(77, 3, 0), 35);
        OrientationPriors priors = OrientationPriors.NONE.withHeading(85, 15).withRollDeg(0).withHfovRangeDeg(35, 35);
        OrientationEstimate e = OrientationEstimator.estimate(sky, profile, priors);
        assertEquals(0, e.rollDeg());
        assertEquals(35, e.hfovDeg());
        assertEquals(77, e.headingDeg(), 0.05, e.summary());
        assertEquals(3, e.pitchDeg(), 0.05, e.summary());
    }

    @Test
    void tooLittleSkylineIsAClearError() {
        HorizonProfile profile = SyntheticSkyline.profile(SyntheticSkyline::ridge, 10);
        double[] rows = new double[W];
        java.util.Arrays.fill(rows, Double.NaN);
        Skyline none = new Skyline(W, H, rows, new double[W]);
        IllegalArgumentException ex = assertThrows(IllegalArgumentException.class,
                () -> OrientationEstimator.estimate(none, profile, OrientationPriors.NONE));
        assertTrue(ex.getMessage().contains("too little skyline"), ex.getMessage());
    }

    /** Edge flags of an analytic curve on a panorama grid (row whose top boundary is nearest the curve). */
    static SilhouetteField field(java.util.function.DoubleUnaryOperator curve, double ppd, double topDeg, int h) {
        int w = (int) Math.round(360 * ppd);
        boolean[] edge = new boolean[w * h];
        for (int c = 0; c < w; c++) {
            int r = (int) Math.round((topDeg - curve.applyAsDouble((c + 0.5) / ppd)) * ppd);
            if (r >= 0 && r < h) {
                edge[r * w + c] = true;
            }
        }
        return new SilhouetteField(edge, w, h, ppd, topDeg);
    }

    @Test
    void innerEdgesPickTheRightHeadingOfAPeriodicSkyline() {
        java.util.function.DoubleUnaryOperator periodic = az -> 5 + 3 * Math.sin(Math.toRadians(12 * az));
        java.util.function.DoubleUnaryOperator inner = az -> SyntheticSkyline.ridge(az) - 9;
        HorizonProfile profile = SyntheticSkyline.profile(periodic, 10);
        SilhouetteField f = field(inner, 10, 20, 400);
        CameraOrientation truth = new CameraOrientation(100, 1, -1);
        Skyline sky = SyntheticSkyline.project(periodic, W, H, truth, 40);
        Skyline ridge = SyntheticSkyline.project(inner, W, H, truth, 40);
        int n = 0;
        double[] x = new double[W], y = new double[W];
        for (int c = 0; c < W; c += 2) {
            if (!Double.isNaN(ridge.row(c))) {
                x[n] = c;
                y[n++] = Math.round(ridge.row(c)); // photo edge points are whole pixels
            }
        }
        PhotoEdges edges = new PhotoEdges(java.util.Arrays.copyOf(x, n), java.util.Arrays.copyOf(y, n));
        OrientationEstimate e = OrientationEstimator.estimate(sky, edges, profile, f, OrientationPriors.NONE);
        assertTrue(headingError(e, 100) < 0.1, e.summary());
        assertEquals(40, e.hfovDeg(), 0.4, e.summary());
        assertTrue(e.edgeScore() < 0.3, e.summary());
        assertTrue(e.marginScore() > 0.1, e.summary());
    }

    @Test
    void theFineStageOnCameraRendersMatchesTheTruePoseToAHundredthOfADegree() {
        // The panorama's skyline in 0.1° rows (10 px/°), as rendered; a 20° lens makes a row 2.4 photo pixels.
        HorizonProfile profile = SyntheticSkyline.renderedProfile(SyntheticSkyline::ridge, 10, 45);
        double[][] poses = {{123.4, 4, -3, 20}, {301.7, -2, 2.5, 30}, {47.9, 6, 1.5, 24}};
        double coarseWorst = 0, fineWorst = 0;
        for (double[] p : poses) {
            Skyline sky = SyntheticSkyline.project(SyntheticSkyline::ridge, W, H, new CameraOrientation(p[0], p[1], p[2]), p[3]);
            OrientationEstimate coarse = OrientationEstimator.estimate(sky, PhotoEdges.NONE, profile, null, OrientationPriors.NONE);
            OrientationEstimate fine = OrientationEstimator.estimate(sky, PhotoEdges.NONE, profile, null, OrientationPriors.NONE,
                    SyntheticSkyline.camera(SyntheticSkyline::ridge));
            String what = fine.summary() + " (panorama only: " + coarse.summary() + ") for truth " + java.util.Arrays.toString(p);
            coarseWorst = Math.max(coarseWorst, headingError(coarse, p[0]));
            fineWorst = Math.max(fineWorst, headingError(fine, p[0]));
            // Renders at twice the photo's pixels per degree: a quarter of a photo pixel is 0.01° at 20°.
            assertTrue(headingError(fine, p[0]) < 0.01, what);
            assertEquals(p[1], fine.pitchDeg(), 0.01, what);
            assertEquals(p[2], fine.rollDeg(), 0.03, what);
            assertEquals(p[3], fine.hfovDeg(), 0.001 * p[3], what);
            assertTrue(fine.residualPx() < 0.3, what);
            assertFalse(fine.unsure(), what);
        }
        System.out.printf(java.util.Locale.ROOT, "worst heading error: panorama only %.4f°, fine stage %.4f°%n", coarseWorst, fineWorst);
    }
}
