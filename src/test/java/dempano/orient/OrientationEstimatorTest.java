package dempano.orient;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.camera.CameraOrientation;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

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

    /**
     * Rolled photos (3–5°) with flat-topped occluders over 3 of 10 column slots, 8–45 px above the skyline, as in the
     * orientation benchmark: the coarse fit must start from a roll near the truth. A single start at roll 0 (the search
     * before start rolls) left the photos' edges beyond its first threshold and settled on level poses that fit nothing:
     * these four photos came out 7°–148° off.
     */
    @ParameterizedTest(name = "draw {0}")
    @ValueSource(ints = {2, 7, 31, 47})
    void rolledSkylinesWithOccludersStillMatch(int draw) {
        HorizonProfile profile = SyntheticSkyline.profile(SyntheticSkyline::ridge, 10);
        java.util.Random rnd = new java.util.Random(draw);
        double heading = 360 * rnd.nextDouble(), pitch = -10 + 20 * rnd.nextDouble();
        double roll = (rnd.nextBoolean() ? 1 : -1) * (3 + 2 * rnd.nextDouble()), hfov = 40 + 50 * rnd.nextDouble();
        Skyline sky = SyntheticSkyline.project(SyntheticSkyline::ridge, W, H, new CameraOrientation(heading, pitch, roll), hfov);
        double[] rows = sky.rowPx();
        java.util.List<Integer> slots = new java.util.ArrayList<>(java.util.List.of(0, 1, 2, 3, 4, 5, 6, 7, 8, 9));
        java.util.Collections.shuffle(slots, rnd);
        for (int k = 0; k < 3; k++) {
            int x0 = slots.get(k) * W / 10, x1 = (slots.get(k) + 1) * W / 10;
            double top = H;
            for (int x = x0; x < x1; x++) {
                top = Double.isNaN(rows[x]) ? top : Math.min(top, rows[x]);
            }
            top = Math.max(2, top - 8 - rnd.nextInt(38));
            for (int x = x0; x < x1; x++) {
                rows[x] = top;
            }
        }
        OrientationEstimate e = OrientationEstimator.estimate(new Skyline(W, H, rows, sky.weight()), profile, OrientationPriors.NONE);
        String what = String.format(java.util.Locale.ROOT, "%s for truth %.2f° %.2f° %.2f° fov %.1f°", e.summary(), heading,
                pitch, roll, hfov);
        assertTrue(headingError(e, heading) < 0.05, what);
        assertEquals(roll, e.rollDeg(), 0.1, what);
        assertEquals(hfov, e.hfovDeg(), 0.005 * hfov, what);
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
    void aPinnedHeadingThatTheSkylineContradictsIsFlaggedUnsureWithTheHeadingItFits() {
        // A compass 8° off, taken as the heading: pitch, roll and FOV fitted to it fit half the skyline, which the
        // inlier rule alone passed. The best pose at any other heading fits far better: a negative margin, unsure.
        HorizonProfile profile = SyntheticSkyline.profile(SyntheticSkyline::ridge, 10);
        double truth = 77;
        Skyline sky = SyntheticSkyline.project(SyntheticSkyline::ridge, W, H, new CameraOrientation(truth, 3, -1), 50);
        OrientationEstimate wrong = OrientationEstimator.estimate(sky, profile, OrientationPriors.NONE.withHeading(truth + 8, 0));
        assertEquals(truth + 8, wrong.headingDeg(), 1e-9);
        assertTrue(wrong.unsure(), wrong.summary());
        assertTrue(wrong.marginScore() < 0, wrong.summary());
        assertEquals(truth, wrong.secondHeadingDeg(), 0.05, wrong.summary());
        // Pinned where the skyline agrees, it stays confident: the best other heading fits far worse.
        OrientationEstimate right = OrientationEstimator.estimate(sky, profile, OrientationPriors.NONE.withHeading(truth, 0));
        assertFalse(right.unsure(), right.summary());
        assertTrue(right.marginScore() >= OrientationEstimator.UNSURE_MARGIN, right.summary());
        assertEquals(50, right.hfovDeg(), 0.25, right.summary());
        // A prior of ± 5° that holds no heading the skyline fits: the estimate is the best within it, and unsure.
        OrientationEstimate narrow = OrientationEstimator.estimate(sky, profile, OrientationPriors.NONE.withHeading(truth + 12, 5));
        assertTrue(headingError(narrow, truth) > 3, narrow.summary());
        assertTrue(narrow.unsure(), narrow.summary());
    }

    @Test
    void theCoarsePoolHoldsEveryFovBinAndTheTruthInItsOwn() {
        HorizonProfile profile = SyntheticSkyline.profile(SyntheticSkyline::ridge, 10);
        double truthHeading = 123.4, truthFov = 40;
        Skyline sky = SyntheticSkyline.project(SyntheticSkyline::ridge, W, H, new CameraOrientation(truthHeading, 4, -3), truthFov);
        OrientationEstimator.Samples s = OrientationEstimator.Samples.of(sky, OrientationEstimator.COARSE_SAMPLES);
        OrientationEstimator.CoarsePool coarse = OrientationEstimator.coarse(s, W, H, profile, OrientationPriors.NONE, 6);
        java.util.List<OrientationEstimator.Hypothesis> pool = coarse.perBin();
        // 15°–100° in bins of ratio 1.25: ln(100/15)/ln(1.25) = 8.5, so bins 0..8.
        java.util.Set<Integer> bins = new java.util.TreeSet<>();
        for (OrientationEstimator.Hypothesis h : pool) {
            int b = OrientationEstimator.fovBin(h.hfovDeg(), OrientationPriors.NONE);
            bins.add(b);
            // Each pose's FOV lies in its bin: [15·1.25^b, 15·1.25^(b+1)).
            assertTrue(h.hfovDeg() >= 15 * Math.pow(1.25, b) - 1e-9 && h.hfovDeg() < 15 * Math.pow(1.25, b + 1), h.toString());
        }
        assertEquals(java.util.Set.of(0, 1, 2, 3, 4, 5, 6, 7, 8), bins);
        int trueBin = OrientationEstimator.fovBin(truthFov, OrientationPriors.NONE);
        OrientationEstimator.Hypothesis inBin = pool.stream()
                .filter(h -> OrientationEstimator.fovBin(h.hfovDeg(), OrientationPriors.NONE) == trueBin)
                .min(java.util.Comparator.comparingDouble(OrientationEstimator.Hypothesis::score)).orElseThrow();
        assertTrue(OrientationEstimator.headingGap(inBin.headingDeg(), truthHeading) <= 0.25, inBin.toString());
        assertEquals(truthFov, inBin.hfovDeg(), 0.015 * truthFov, inBin.toString());
        // The truth is the best of the whole pool too, and of the search over all FOVs.
        assertEquals(inBin, pool.get(0));
        assertEquals(inBin, coarse.global().get(0));
        assertEquals(6, coarse.global().size());
    }

    @Test
    void chooseKeepsTheFirstThenTwoDistinctHeadingsPerFovBin() {
        // Ranked pool (score ascending): bins by FOV 20 → 1, 30 → 3, 50 → 5, 80 → 7 (floor(ln(fov / 15) / ln 1.25)).
        java.util.List<OrientationEstimator.Hypothesis> ranked = java.util.List.of(
                new OrientationEstimator.Hypothesis(10, 0, 0, 20, 0.1),
                new OrientationEstimator.Hypothesis(11, 0, 0, 30, 0.2),   // same heading as the first (gap 1° ≤ 2°)
                new OrientationEstimator.Hypothesis(50, 0, 0, 20, 0.3),
                new OrientationEstimator.Hypothesis(90, 0, 0, 50, 0.4),
                new OrientationEstimator.Hypothesis(91, 0, 0, 50, 0.5),   // bin 5's second, but 1° from its first
                new OrientationEstimator.Hypothesis(200, 0, 0, 50, 0.6),  // bin 5's second distinct
                new OrientationEstimator.Hypothesis(300, 0, 0, 50, 0.7),  // bin 5 full
                new OrientationEstimator.Hypothesis(250, 0, 0, 20, 0.8),  // bin 1 full (10°, 50°)
                new OrientationEstimator.Hypothesis(120, 0, 0, 80, 0.9));
        java.util.List<OrientationEstimator.Hypothesis> out = OrientationEstimator.choose(
                java.util.List.of(ranked.get(0), ranked.get(2)), ranked, OrientationPriors.NONE);
        // first: 10° and 50° (the search over all FOVs); then per bin up to two distinct: bin 3 gets 11° (its only one),
        // bin 5 gets 90° and 200°, bin 7 gets 120°.
        assertEquals(java.util.List.of(ranked.get(0), ranked.get(2), ranked.get(1), ranked.get(3), ranked.get(5),
                ranked.get(8)), out);
    }

    @Test
    void aFieldOfViewOutsideThePriorIsFlaggedUnsure() {
        HorizonProfile profile = SyntheticSkyline.profile(SyntheticSkyline::ridge, 10);
        Skyline sky = SyntheticSkyline.project(SyntheticSkyline::ridge, W, H, new CameraOrientation(123.4, 4, -3), 85);
        OrientationPriors narrow = OrientationPriors.NONE.withHfovRangeDeg(20, 60);
        // The true FOV cannot be reached: whatever pose fits best, it is not a confident one.
        OrientationEstimate e = OrientationEstimator.estimate(sky, profile, narrow);
        assertTrue(e.unsure(), e.summary());
        // Refinement may leave the prior by 3 %: 20 × 0.97 = 19.4°, 60 × 1.03 = 61.8° are the bounds.
        assertTrue(OrientationEstimator.onFovBound(61.8, narrow));
        assertTrue(OrientationEstimator.onFovBound(19.4, narrow));
        assertFalse(OrientationEstimator.onFovBound(61.5, narrow));
        assertFalse(OrientationEstimator.onFovBound(19.6, narrow));
        assertFalse(OrientationEstimator.onFovBound(61.8, OrientationPriors.NONE.withHfovRangeDeg(61.8, 61.8)));
        OrientationEstimate inside = OrientationEstimator.estimate(sky, profile, OrientationPriors.NONE.withHfovRangeDeg(20, 95));
        assertEquals(85, inside.hfovDeg(), 0.5, inside.summary());
        assertFalse(inside.unsure(), inside.summary());
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

    /** The ridge with a ripple of period 0.8° and ±0.4° (about ±5 photo pixels at a 40° lens) added. */
    static double rippled(double azDeg) {
        return SyntheticSkyline.ridge(azDeg) + 0.4 * Math.sin(2 * Math.PI * azDeg / 0.8);
    }

    @Test
    void polishLeavesANeighbouringRippleMinimumForTheTruePose() {
        HorizonProfile profile = SyntheticSkyline.profile(OrientationEstimatorTest::rippled, 40);
        double truth = 217.3, pitch = 2, roll = -1, fov = 40;
        Skyline sky = SyntheticSkyline.project(OrientationEstimatorTest::rippled, W, H, new CameraOrientation(truth, pitch, roll), fov);
        OrientationEstimator.Samples fine = OrientationEstimator.Samples.of(sky, OrientationEstimator.FINE_SAMPLES);
        OrientationEstimator.Target target = new OrientationEstimator.Target(fine, PhotoEdges.NONE, null, 0, null);
        // Started one ripple period off, the refinement alone stays in that period's minimum (the precondition).
        OrientationEstimator.Hypothesis stuck = OrientationEstimator.refine(new OrientationEstimator.Hypothesis(
                truth + 0.8, pitch, roll, fov, Double.NaN), target, W, H, profile, OrientationPriors.NONE);
        assertTrue(OrientationEstimator.headingGap(stuck.headingDeg(), truth) > 0.5, "refined to " + stuck);
        OrientationEstimator.Hypothesis polished = OrientationEstimator.polish(stuck, target, W, H, profile, OrientationPriors.NONE);
        assertTrue(OrientationEstimator.headingGap(polished.headingDeg(), truth) < 0.05, "polished to " + polished);
        assertEquals(fov, polished.hfovDeg(), 0.01 * fov, "polished to " + polished);
        assertTrue(polished.score() < stuck.score(), polished + " vs " + stuck);
    }

    @Test
    void polishNeverWorsensTheScoreNorLeavesTheDistinctHeadingGap() {
        HorizonProfile profile = SyntheticSkyline.profile(OrientationEstimatorTest::rippled, 40);
        Skyline sky = SyntheticSkyline.project(OrientationEstimatorTest::rippled, W, H, new CameraOrientation(80, 0, 0), 30);
        OrientationEstimator.Samples fine = OrientationEstimator.Samples.of(sky, OrientationEstimator.FINE_SAMPLES);
        OrientationEstimator.Target target = new OrientationEstimator.Target(fine, PhotoEdges.NONE, null, 0, null);
        for (double start : new double[]{80, 80.8, 83, 200}) {
            OrientationEstimator.Hypothesis r = OrientationEstimator.refine(new OrientationEstimator.Hypothesis(
                    start, 0, 0, 30, Double.NaN), target, W, H, profile, OrientationPriors.NONE);
            OrientationEstimator.Hypothesis p = OrientationEstimator.polish(r, target, W, H, profile, OrientationPriors.NONE);
            assertTrue(p.score() <= r.score(), p + " vs " + r);
            assertTrue(OrientationEstimator.headingGap(p.headingDeg(), r.headingDeg()) <= OrientationEstimator.DISTINCT_HEADING_DEG, p + " vs " + r);
        }
    }
}
