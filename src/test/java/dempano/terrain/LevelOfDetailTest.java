package dempano.terrain;

import dempano.dem.Triangulation;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Deviations of coarse levels against closed forms; the level chosen against the pixel bound. */
class LevelOfDetailTest {
    static float[] grid(int n, Height h) {
        float[] a = new float[(n + 1) * (n + 1)];
        for (int i = 0; i <= n; i++) {
            for (int j = 0; j <= n; j++) {
                a[i * (n + 1) + j] = (float) h.at(i, j);
            }
        }
        return a;
    }

    interface Height {
        double at(int row, int col);
    }

    @Test
    void aPlaneLosesNothingAtAnyLevel() {
        float[] h = grid(64, (i, j) -> 100 + 3 * i - 2 * j);
        double[] dev = LevelOfDetail.deviationsMetres(h, 65, 0, 0, 64);
        assertEquals(7, dev.length);
        for (double d : dev) {
            assertEquals(0, d, 1e-9);
        }
        // Nothing lost: the coarsest level even right at the eye.
        assertEquals(6, LevelOfDetail.chooseLevel(dev, 1, 20, 0.5));
    }

    @Test
    void aParabolaDeviatesByTheChordSag() {
        // h = a·j²: the chord over [0, s] lies a·(s/2)² above the parabola at its middle.
        double a = 0.25;
        float[] h = grid(64, (i, j) -> a * j * j);
        double[] dev = LevelOfDetail.deviationsMetres(h, 65, 0, 0, 64);
        assertEquals(0, dev[0]);
        for (int level = 1; level <= 6; level++) {
            double s = 1 << level;
            assertEquals(a * (s / 2) * (s / 2), dev[level], 1e-3, "level " + level);
        }
    }

    @Test
    void aSpikeBetweenCoarseSamplesIsSeenAtEveryCoarseLevel() {
        float[] h = grid(64, (i, j) -> i == 33 && j == 17 ? 250 : 0);
        double[] dev = LevelOfDetail.deviationsMetres(h, 65, 0, 0, 64);
        assertEquals(0, dev[0]);
        for (int level = 1; level <= 6; level++) {
            assertEquals(250, dev[level], 1e-9, "level " + level);
        }
        // A patch inside a larger grid: offsets are honoured.
        float[] big = grid(128, (i, j) -> i == 64 + 33 && j == 64 + 17 ? 250 : 0);
        assertEquals(250, LevelOfDetail.deviationsMetres(big, 129, 64, 64, 64)[3], 1e-9);
        assertEquals(0, LevelOfDetail.deviationsMetres(big, 129, 0, 0, 64)[3], 1e-9);
    }

    @Test
    void interpolationIsExactAtCornersAndLinearOnEachTriangle() {
        for (boolean split : new boolean[] {true, false}) {
            assertEquals(1, Triangulation.height(split, 1, 2, 3, 4, 0, 0), 1e-12);
            assertEquals(2, Triangulation.height(split, 1, 2, 3, 4, 0, 1), 1e-12);
            assertEquals(3, Triangulation.height(split, 1, 2, 3, 4, 1, 0), 1e-12);
            assertEquals(4, Triangulation.height(split, 1, 2, 3, 4, 1, 1), 1e-12);
        }
        // Not a plane (nw + se ≠ ne + sw): the centre lies on the diagonal that splits the cell.
        assertEquals((0 + 10) / 2.0, Triangulation.height(true, 0, 0, 0, 10, 0.5, 0.5), 1e-12);
        assertEquals((0 + 0) / 2.0, Triangulation.height(false, 0, 0, 0, 10, 0.5, 0.5), 1e-12);
    }

    @Test
    void levelFollowsTheScreenErrorBound() {
        double[] dev = {0, 10, 20, 40, 80};
        // 0.5 px at 20 px/deg is 0.025° = 4.363e-4 rad.
        double rad = 0.5 / 20 * Math.PI / 180;
        assertEquals(0, LevelOfDetail.chooseLevel(dev, 9.99 / rad, 20, 0.5));
        assertEquals(1, LevelOfDetail.chooseLevel(dev, 10.01 / rad, 20, 0.5));
        assertEquals(2, LevelOfDetail.chooseLevel(dev, 39.9 / rad, 20, 0.5));
        assertEquals(4, LevelOfDetail.chooseLevel(dev, 1e9, 20, 0.5));
        assertEquals(0, LevelOfDetail.chooseLevel(dev, 1e9, 20, 0), "0 px = full resolution");
        // A level beyond a failing one is not taken even if it happens to hold the bound.
        assertEquals(0, LevelOfDetail.chooseLevel(new double[] {0, 50, 1}, 10 / rad, 20, 0.5));
    }

    @Test
    void patchSideMustBeAPowerOfTwo() {
        assertThrows(IllegalArgumentException.class, () -> LevelOfDetail.deviationsMetres(new float[49], 7, 0, 0, 6));
    }

    @Test
    void chordSagMatchesTheCircleItCuts() {
        // A chord of length L on a circle of radius R lies R − √(R² − L²/4) ≈ L²/8R below the arc.
        double side = 5_000, r = 6_356_000, chord = Math.sqrt(2) * side;
        assertEquals(r - Math.sqrt(r * r - chord * chord / 4), LevelOfDetail.chordSagMetres(side, 0.13), 1e-3);
        assertEquals(LevelOfDetail.chordSagMetres(side, 0), LevelOfDetail.chordSagMetres(side, 0.13), 0, "k > 0 never lowers it");
        assertEquals(1.5 * LevelOfDetail.chordSagMetres(side, 0), LevelOfDetail.chordSagMetres(side, -0.5), 1e-9);
    }

    static final double R = LevelOfDetail.MIN_RADIUS_OF_CURVATURE_METRES;

    /**
     * L · sin θ exactly, for a straight ray of length L from an eye at H to level ground at h, d along
     * the ground (arc), on a sphere of radius R' = R/(1 − k): (R' + H) cos φ − (R' + h), φ = d/R'.
     * It is what the distance error δ / (L sin θ) divides by.
     */
    static double exactRangeTimesSinIncidence(double eye, double ground, double d, double k) {
        double r = R / (1 - k), phi = d / r;
        return (r + eye) * Math.cos(phi) - (r + ground);
    }

    static double exactRange(double eye, double ground, double d, double k) {
        double r = R / (1 - k), phi = d / r;
        return Math.sqrt(Math.pow(r + eye, 2) + Math.pow(r + ground, 2) - 2 * (r + eye) * (r + ground) * Math.cos(phi));
    }

    @Test
    void levelGroundIncidenceMatchesTheSphere() {
        for (double k : new double[] {0, 0.13, -0.2}) {
            for (double eye : new double[] {2, 100, 2000}) {
                for (double ground : new double[] {0, 50}) {
                    for (double d : new double[] {500, 5_000, 30_000, 100_000}) {
                        double exact = exactRangeTimesSinIncidence(eye, ground, d, k);
                        double approx = d * LevelOfDetail.sinIncidenceLowerBound(eye, ground, d, k);
                        // Second order: what is left out is H·φ²/2 and (R' + H)·φ⁴/24 (φ = d/R'), 4e-4 of
                        // d · sin θ or 5 cm at most here (H 2 km or k −0.2, d 100 km).
                        double r = R / (1 - k), phi = d / r;
                        double rest = eye * phi * phi / 2 + (r + eye) * Math.pow(phi, 4) / 24;
                        assertEquals(exact, approx, 1.01 * rest + 1e-9, "H " + eye + " h " + ground + " d " + d + " k " + k);
                        assertTrue(rest < 5e-4 * Math.abs(exact) + 0.05, "rest " + rest);
                    }
                }
            }
        }
        // The sea horizon from 2 m: √(2RH) away, the incidence is 0 (and negative beyond).
        double horizon = Math.sqrt(2 * R * 2);
        assertEquals(0, LevelOfDetail.sinIncidenceLowerBound(2, 0, horizon, 0), 1e-12);
        assertTrue(LevelOfDetail.sinIncidenceLowerBound(2, 0, horizon * 1.1, 0) < 0);
        assertEquals(Double.POSITIVE_INFINITY, LevelOfDetail.sinIncidenceLowerBound(2, 0, 0, 0.13));
        assertEquals(Double.NEGATIVE_INFINITY, LevelOfDetail.sinIncidenceLowerBound(2, 5, 0, 0.13));
    }

    /** Deviations of a flat patch of SRTM3 cells: chord sag only. */
    static double[] flatDeviations(double k) {
        double[] dev = new double[7];
        for (int level = 1; level < 7; level++) {
            dev[level] = LevelOfDetail.chordSagMetres((1 << level) * 92.6, k);
        }
        return dev;
    }

    static LevelOfDetail.Sight sight(double near, double far, double high, double rise, double eye, double k) {
        return new LevelOfDetail.Sight(near, far, high, rise, eye, k);
    }

    @Test
    void flatSeaPatchesHoldTheDistanceBoundWhereverSeenAboveTheGrazingFloor() {
        double eps = LevelOfDetail.DEFAULT_MAX_DISTANCE_ERROR, ppd = 20, floor = Math.sin(Math.toRadians(1 / ppd));
        int refined = 0, checkedPoints = 0;
        for (double k : new double[] {0, 0.13}) {
            double[] dev = flatDeviations(k);
            for (double eye : new double[] {2, 10, 100, 1000}) {
                for (double near : new double[] {300, 1_000, 3_000, 10_000, 30_000, 60_000}) {
                    double far = near + 8_000; // an SRTM3 patch's diagonal
                    int level = LevelOfDetail.chooseLevel(dev, sight(near, far, 0, 0, eye, k), ppd, 0.5, eps);
                    int angular = LevelOfDetail.chooseLevel(dev, near, ppd, 0.5);
                    assertTrue(level <= angular);
                    refined += level < angular ? 1 : 0;
                    for (int i = 0; i <= 200; i++) {
                        double d = near + (far - near) * i / 200;
                        double product = exactRangeTimesSinIncidence(eye, 0, d, k);
                        if (product / exactRange(eye, 0, d, k) < floor) {
                            continue; // grazing: the horizon's exception
                        }
                        checkedPoints++;
                        double relative = dev[level] / product;
                        assertTrue(relative <= eps * 1.001, String.format(
                                "H %.0f m, patch %.0f–%.0f m, k %.2f: level %d errs %.2e at %.0f m", eye, near, far, k,
                                level, relative, d));
                    }
                }
            }
        }
        assertTrue(refined >= 10, "the distance bound refines patches the angle alone would coarsen: " + refined);
        assertTrue(checkedPoints > 5_000, "points checked: " + checkedPoints);
    }

    @Test
    void theHorizonAndGroundReachingTheEyeAreExceptedButAPatchReachingTheHorizonIsBoundAtTheFloor() {
        double floor = Math.sin(Math.toRadians(1 / 20.0));
        // Wholly beyond the 2 m sea horizon (5.0 km): no distance bound.
        assertEquals(Double.POSITIVE_INFINITY,
                LevelOfDetail.allowedDeviationForDistanceMetres(sight(6_000, 14_000, 0, 0, 2, 0), 20, 0.002));
        // Level terrain above the eye: only slopes facing the eye are seen; the angle decides.
        double[] dev = {0, 1, 2, 4, 8, 16, 32};
        LevelOfDetail.Sight above = sight(5_000, 13_000, 2_500, 0, 1_000, 0.13);
        assertEquals(Double.POSITIVE_INFINITY, LevelOfDetail.allowedDeviationForDistanceMetres(above, 20, 0.002));
        assertEquals(LevelOfDetail.chooseLevel(dev, 5_000, 20, 0.5), LevelOfDetail.chooseLevel(dev, above, 20, 0.5, 0.002));
        // Terrain reaching the eye's altitude, whatever low ground it also holds: its grazing parts are its silhouettes.
        assertEquals(Double.POSITIVE_INFINITY, LevelOfDetail.allowedDeviationForDistanceMetres(
                sight(5_000, 13_000, 1_100, 0, 1_000, 0.13), 20, 0.002));
        // The sea from 1 to 9 km seen from 2 m reaches past its horizon (5.0 km): bound where it is seen at
        // the floor, d* (2/d − d/2R = floor, by bisection), by ε · d* · floor.
        double lo = 1_000, hi = 9_000;
        for (int i = 0; i < 100; i++) {
            double mid = (lo + hi) / 2;
            if (2 / mid - mid / (2 * R) > floor) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        assertTrue(lo > 1_900 && lo < 2_000, "d* " + lo);
        assertEquals(0.002 * lo * floor,
                LevelOfDetail.allowedDeviationForDistanceMetres(sight(1_000, 9_000, 0, 0, 2, 0), 20, 0.002), 1e-9);
    }

    @Test
    void aSteepSlopeFacingTheEyeIsLeftToTheAngularBound() {
        double[] dev = {0, 1, 2, 4, 8, 16, 32};
        int angular = LevelOfDetail.chooseLevel(dev, 5_000, 20, 0.5);
        assertTrue(angular >= 1);
        // A face rising 1:2 away from an eye above it.
        LevelOfDetail.Sight facing = sight(5_000, 13_000, 3_000, 0.5, 3_500, 0.13);
        assertEquals(angular, LevelOfDetail.chooseLevel(dev, facing, 20, 0.5, 0.002));
        // The same heights with level (or turned away) parts somewhere: refined.
        LevelOfDetail.Sight mixed = sight(5_000, 13_000, 3_000, 0, 3_500, 0.13);
        assertTrue(LevelOfDetail.chooseLevel(dev, mixed, 20, 0.5, 0.002) < angular);
    }

    @Test
    void zeroBoundsGiveFullResolutionOrTheAngleAlone() {
        double[] dev = flatDeviations(0.13);
        LevelOfDetail.Sight sea = sight(10_000, 18_000, 0, 0, 100, 0.13);
        assertEquals(0, LevelOfDetail.chooseLevel(dev, sea, 20, 0, 0.002), "0 px = full resolution");
        assertEquals(LevelOfDetail.chooseLevel(dev, 10_000, 20, 0.5), LevelOfDetail.chooseLevel(dev, sea, 20, 0.5, 0));
        // The patch under the eye: no distance bound can hold; full resolution, unless nothing is lost (a plane).
        LevelOfDetail.Sight under = sight(0, 8_000, 0, 0, 100, 0.13);
        assertEquals(0, LevelOfDetail.chooseLevel(dev, under, 20, 0.5, 0.002));
        assertEquals(6, LevelOfDetail.chooseLevel(new double[7], under, 20, 0.5, 0.002));
    }

    @Test
    void riseAwayFromTheEyeOfAPlane() {
        // A plane rising 0.3 m per metre northwards (each sample 0.3·90 m above its southern neighbour).
        double spacing = 90, slack = 0.02;
        double[] east = {0, 0}, south = {-27, -27};
        double[] southOfEye = corners(-2_000, 10_000, 4_000);   // patch north of the eye
        double[] northOfEye = corners(-2_000, -14_000, 4_000);  // patch south of the eye
        double[] eastOfEye = corners(10_000, -2_000, 4_000);
        assertEquals(0.3 * Math.cos(Math.atan2(2_000, 10_000)) - slack * 0.3,
                LevelOfDetail.riseAwayFromEye(east, south, spacing, spacing, southOfEye, slack), 1e-9,
                "the least over the corners: the one most to the side");
        assertEquals(0, LevelOfDetail.riseAwayFromEye(east, south, spacing, spacing, northOfEye, slack), "turned away");
        assertEquals(0, LevelOfDetail.riseAwayFromEye(east, south, spacing, spacing, eastOfEye, slack), "side on");
        assertEquals(0, LevelOfDetail.riseAwayFromEye(east, south, spacing, spacing, corners(-2_000, -2_000, 4_000), slack),
                "the eye over the patch");
        // Any step against the direction (a gully) makes it 0.
        assertEquals(0, LevelOfDetail.riseAwayFromEye(east, new double[] {-27, 5}, spacing, spacing, southOfEye, slack));
    }

    /**
     * The definition, sample by sample (the implementation before it went cell by cell): the largest
     * |height − coarse surface| over the full-resolution samples, per level.
     */
    static double[] deviationsBySample(float[] heights, int stride, int row0, int col0, int intervals) {
        int levels = Integer.numberOfTrailingZeros(intervals);
        double[] dev = new double[levels + 1];
        for (int level = 1; level <= levels; level++) {
            int s = 1 << level;
            double worst = 0;
            for (int i = 0; i <= intervals; i++) {
                int ci = Math.min(i / s, intervals / s - 1);
                double v = (i - ci * s) / (double) s;
                for (int j = 0; j <= intervals; j++) {
                    int cj = Math.min(j / s, intervals / s - 1);
                    double u = (j - cj * s) / (double) s;
                    int rn = row0 + ci * s, rs = rn + s, cw = col0 + cj * s, ce = cw + s;
                    double coarse = Triangulation.height(Triangulation.splitsNorthWestToSouthEast(ci, cj),
                            heights[rn * stride + cw], heights[rn * stride + ce], heights[rs * stride + cw],
                            heights[rs * stride + ce], v, u);
                    worst = Math.max(worst, Math.abs(heights[(row0 + i) * stride + col0 + j] - coarse));
                }
            }
            dev[level] = worst;
        }
        return dev;
    }

    @Test
    void deviationsAreBitForBitThoseOfTheSampleBySampleDefinition() {
        java.util.Random random = new java.util.Random(19);
        for (int trial = 0; trial < 200; trial++) {
            int intervals = 1 << (1 + random.nextInt(6)), stride = intervals + 1 + random.nextInt(5);
            int rows = intervals + 1 + random.nextInt(5);
            float[] h = new float[rows * stride];
            double scale = random.nextBoolean() ? 1 : 3000;
            for (int k = 0; k < h.length; k++) {
                h[k] = trial % 3 == 0 ? (float) Math.rint(random.nextGaussian() * scale) : (float) (random.nextGaussian() * scale);
            }
            int row0 = random.nextInt(rows - intervals), col0 = random.nextInt(stride - intervals);
            double[] expected = deviationsBySample(h, stride, row0, col0, intervals);
            double[] got = LevelOfDetail.deviationsMetres(h, stride, row0, col0, intervals);
            assertEquals(expected.length, got.length);
            for (int l = 0; l < got.length; l++) {
                assertEquals(Double.doubleToRawLongBits(expected[l]), Double.doubleToRawLongBits(got[l]),
                        "trial " + trial + " level " + l + ": " + expected[l] + " vs " + got[l]);
            }
        }
    }

    /** A square patch's corners, (east, north) pairs, from its south-west corner and side. */
    static double[] corners(double west, double south, double side) {
        return new double[] {west, south + side, west + side, south + side, west, south, west + side, south};
    }
}
