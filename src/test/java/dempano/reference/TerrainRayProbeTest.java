package dempano.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.Synthetic;
import dempano.dem.MissingTilePolicy;
import dempano.dem.Mosaic;
import dempano.dem.TileSelection;
import dempano.geo.Ellipsoid;
import dempano.geo.EllipsoidRay;
import dempano.geo.LocalFrame;
import dempano.geo.Refraction;
import dempano.geo.Viewpoint;
import java.util.Random;
import org.junit.jupiter.api.Test;

class TerrainRayProbeTest {
    /** A 1°×1° plane DEM at 500 m around 46.5 N 8.5 E, eye 1500 m above it. */
    private static TerrainRayProbe planeProbe(double eyeOffsetMetres, Refraction refraction, double rangeMetres) {
        Mosaic mosaic = Mosaic.of(Synthetic.dem((lat, lon) -> 500, 46, 8, 1, 1),
                TileSelection.around(46.5, 8.5, rangeMetres), MissingTilePolicy.AUTO);
        Viewpoint eye = Viewpoint.onDem(mosaic, 46.5, 8.5, eyeOffsetMetres, 0);
        return new TerrainRayProbe(mosaic, eye, refraction, rangeMetres);
    }

    @Test
    void closedFormGeodeticAgreesWithTheIterativeConversion() {
        TerrainRayProbe probe = planeProbe(1500, Refraction.STANDARD, 30_000);
        Random random = new Random(7);
        double worst = 0;
        for (int i = 0; i < 20_000; i++) {
            double az = random.nextDouble() * 2 * Math.PI, el = Math.toRadians(-20 + 25 * random.nextDouble());
            double e = Math.cos(el) * Math.sin(az), n = Math.cos(el) * Math.cos(az), u = Math.sin(el);
            double t = 10 + random.nextDouble() * 25_000;
            double fast = probe.clearance(e, n, u, t);
            double[] ecef = new double[3];
            new LocalFrame(46.5, 8.5, 2000).enuToEcef(t * e, t * n, t * u, ecef);
            double slow = probe.clearanceNearPole(ecef[0], ecef[1], ecef[2], new double[16]);
            if (Double.isNaN(slow)) {
                assertTrue(Double.isNaN(fast), "off the mosaic for one, not the other");
                continue;
            }
            worst = Math.max(worst, Math.abs(fast - slow));
        }
        assertTrue(worst < 1e-6, "closed form vs iterative height above the surface differ by " + worst + " m");
    }

    /** A ray from the eye of {@link #planeProbe} (1500 m above the plane DEM), with where it truly meets the plane. */
    @FunctionalInterface
    private interface PlaneRayCheck {
        /** e, n, u: ENU unit direction; truthMetres: the closed-form hit; where: the ray, for messages. */
        void check(double el, double e, double n, double u, double truthMetres, String where);
    }

    /**
     * Every ray at elevations −45°…−3° and azimuths azimuthStartDeg + k·45°, with its closed-form hit: with k = 0 the
     * plane DEM at 500 m is the ellipsoid raised by 500 m along the normal, which is not an ellipsoid; but within
     * 20 km the two differ by far less than a millimetre at these incidences, so the ray against an ellipsoid with
     * a and b each 500 m larger is the truth.
     */
    private static void forPlaneRays(double azimuthStartDeg, PlaneRayCheck check) {
        LocalFrame frame = new LocalFrame(46.5, 8.5, 2000);
        double[] origin = new double[3];
        frame.enuToEcef(0, 0, 0, origin);
        for (double elDeg : new double[] {-45, -10, -5, -4, -3}) {
            for (double azDeg = azimuthStartDeg; azDeg < 360; azDeg += 45) {
                double el = Math.toRadians(elDeg), az = Math.toRadians(azDeg);
                double e = Math.cos(el) * Math.sin(az), n = Math.cos(el) * Math.cos(az), u = Math.sin(el);
                double[] dir = new double[3];
                EllipsoidRay.enuDirectionToEcef(frame, origin, e, n, u, new double[3], dir);
                double truth = EllipsoidRay.distanceMetres(origin, dir, Ellipsoid.A_METRES + 500, Ellipsoid.B_METRES + 500);
                check.check(el, e, n, u, truth, "elevation " + elDeg + "°, azimuth " + azDeg + "°");
            }
        }
    }

    @Test
    void hitsAFlatDemWhereTheRayMeetsTheEllipsoidLiftedToItsHeight() {
        TerrainRayProbe probe = planeProbe(1500, new Refraction(0), 40_000);
        forPlaneRays(0, (el, e, n, u, truth, where) ->
                // jME axes: east, up, south.
                assertEquals(truth, probe.firstHitMetres(e, u, -n, 0.5 * truth, 2 * truth), 2e-6 * truth, where));
    }

    /**
     * The stretch intersection against the same closed form: within a stretch that holds the hit it gives the hit
     * (and, to the bit, what the search gives); a stretch short of the hit, one longer than it walks, and one
     * reversed give NaN.
     */
    @Test
    void nearestHitBetweenMeetsTheFlatDemWhereTheSearchDoes() {
        TerrainRayProbe probe = planeProbe(1500, new Refraction(0), 40_000);
        forPlaneRays(10, (el, e, n, u, truth, where) -> {
            double between = probe.nearestHitBetweenMetres(e, u, -n, 0.98 * truth, 1.02 * truth);
            assertEquals(truth, between, 2e-6 * truth, where);
            assertEquals(probe.firstHitMetres(e, u, -n, 0.5 * truth, 2 * truth), between, 0.0, where);
            assertTrue(Double.isNaN(probe.nearestHitBetweenMetres(e, u, -n, 0.5 * truth, 0.99 * truth)), where + ": short of it");
            assertTrue(Double.isNaN(probe.nearestHitBetweenMetres(e, u, -n, 1.01 * truth, 0.99 * truth)), where + ": reversed");
            double tooLong = (TerrainRayProbe.STRAIGHT_PATH_METRES + 10) / Math.cos(el);
            assertTrue(Double.isNaN(probe.nearestHitBetweenMetres(e, u, -n, truth - tooLong / 2, truth + tooLong / 2)),
                    where + ": longer than a straight path");
        });
    }

    @Test
    void findsACrestOneSampleRowWide() {
        // A plane at 500 m with a crest one sample row wide (800 m) 5.0 km north of the eye, cells
        // of 1/600° (185 m north–south, 128 m east–west). A ray aimed 150 m under the crest's top
        // is below the surface for about 185 m around 5.0 km; steps of 10 % from 4.7 km (to
        // 5.17 km) would step over it and meet the plane far behind.
        double crestLat = 46.5 + 3000 / 600.0 / 100; // a sample row, 0.05° north
        Mosaic mosaic = Mosaic.of(Synthetic.dem((lat, lon) -> Math.abs(lat - crestLat) < 1e-6 ? 800 : 500, 46, 8, 1, 1),
                TileSelection.around(46.5, 8.5, 30_000), MissingTilePolicy.AUTO);
        Viewpoint eye = Viewpoint.onDem(mosaic, 46.5, 8.5, 300, 0); // eye at 800 m
        TerrainRayProbe probe = new TerrainRayProbe(mosaic, eye, new Refraction(0), 30_000);
        double crestMetres = 0.05 * Math.PI / 180 * 6_367_000; // meridian arc to the crest, ±0.1 %
        double el = Math.atan2(-150, crestMetres);
        double e = 0, n = Math.cos(el), u = Math.sin(el);
        double fine = probe.firstHitMetres(e, u, -n, 4700, 20_000);
        assertTrue(probe.clearance(e, n, u, 5170) > 0, "at 5.17 km the ray is above the surface again: a step there would miss the crest");
        assertEquals(crestMetres, fine, 200, "the crest is met");
        // On the drawn (planar) triangles, which stand within millimetres of the interpolated heights.
        assertEquals(0, probe.clearance(e, n, u, fine), 0.02, "on the surface");
    }

    @Test
    void aKeptMaximumPyramidServesOnlyTheSameTilesAndNeverHidesAChangedOne() {
        // The crest scene of findsACrestOneSampleRowWide, first without the crest: a probe over the plain
        // plane fills the pyramid blocks along the ray with 500 m. Then the same tile grid with the crest
        // tile: a pyramid served stale (500 m) would prove the ray above the 800 m crest and step over it.
        double crestLat = 46.5 + 3000 / 600.0 / 100;
        TileSelection where = TileSelection.around(46.5, 8.5, 30_000);
        dempano.dem.DemSource plain = Synthetic.dem((lat, lon) -> 500, 46, 8, 1, 1);
        Mosaic flat = Mosaic.of(plain, where, MissingTilePolicy.AUTO);
        Mosaic flatAgain = Mosaic.of(plain, where, MissingTilePolicy.AUTO); // the same tile objects
        Mosaic crested = Mosaic.of(Synthetic.dem((lat, lon) -> Math.abs(lat - crestLat) < 1e-6 ? 800 : 500, 46, 8, 1, 1),
                where, MissingTilePolicy.AUTO);
        double crestMetres = 0.05 * Math.PI / 180 * 6_367_000;
        double el = Math.atan2(-150, crestMetres);
        double e = 0, n = Math.cos(el), u = Math.sin(el);
        TerrainRayProbe overFlat = new TerrainRayProbe(flat, Viewpoint.onDem(flat, 46.5, 8.5, 300, 0), new Refraction(0), 30_000);
        double plane = overFlat.firstHitMetres(e, u, -n, 4700, 20_000);
        // The ray drops 300 m to the plane in 11.1 km (a little more with the earth's curvature), far behind the crest.
        assertTrue(plane > 11_000 && plane < 12_500, "the plain plane is met at " + plane + " m");
        assertSame(TerrainRayProbe.pyramidFor(flat), TerrainRayProbe.pyramidFor(flatAgain), "same tiles: the pyramid is kept");
        TerrainRayProbe overCrest = new TerrainRayProbe(crested, Viewpoint.onDem(crested, 46.5, 8.5, 300, 0), new Refraction(0),
                30_000);
        assertEquals(crestMetres, overCrest.firstHitMetres(e, u, -n, 4700, 20_000), 200, "the changed tile's crest is met");
        assertNotSame(TerrainRayProbe.pyramidFor(flat), TerrainRayProbe.pyramidFor(crested), "other tiles: another pyramid");
    }

    /**
     * The placed-vertex cache ({@link TerrainRayProbe.WalkTables}) is kept from walk to walk on a thread, so a walk by
     * another probe must never be served the first one's vertices. Two plane DEMs, at 500 m and at 600 m, on the same
     * grid, the eye at 2000 m over both: probe A walks a stretch holding the cells where B's ray meets its plane (A's
     * vertices there are 100 m too low for B), then B walks them, then A again. Each must meet its own plane where the
     * closed form says; stale vertices would put B's hit at A's (outside B's stretch: NaN) and A's at B's.
     */
    @Test
    void placedVerticesKeptFromWalkToWalkAreNeverServedToAnotherProbe() {
        TileSelection where = TileSelection.around(46.5, 8.5, 20_000);
        Mosaic low = Mosaic.of(Synthetic.dem((lat, lon) -> 500, 46, 8, 1, 1), where, MissingTilePolicy.AUTO);
        Mosaic high = Mosaic.of(Synthetic.dem((lat, lon) -> 600, 46, 8, 1, 1), where, MissingTilePolicy.AUTO);
        TerrainRayProbe a = new TerrainRayProbe(low, Viewpoint.onDem(low, 46.5, 8.5, 1500, 0), new Refraction(0), 20_000);
        TerrainRayProbe b = new TerrainRayProbe(high, Viewpoint.onDem(high, 46.5, 8.5, 1400, 0), new Refraction(0), 20_000);
        LocalFrame frame = new LocalFrame(46.5, 8.5, 2000);
        double[] origin = new double[3];
        frame.enuToEcef(0, 0, 0, origin);
        for (double azDeg = 0; azDeg < 360; azDeg += 60) {
            double el = Math.toRadians(-30), az = Math.toRadians(azDeg);
            double e = Math.cos(el) * Math.sin(az), n = Math.cos(el) * Math.cos(az), u = Math.sin(el);
            double[] dir = new double[3];
            EllipsoidRay.enuDirectionToEcef(frame, origin, e, n, u, new double[3], dir);
            double truthA = EllipsoidRay.distanceMetres(origin, dir, Ellipsoid.A_METRES + 500, Ellipsoid.B_METRES + 500);
            double truthB = EllipsoidRay.distanceMetres(origin, dir, Ellipsoid.A_METRES + 600, Ellipsoid.B_METRES + 600);
            String at = "azimuth " + azDeg + "°";
            assertTrue(truthB < 0.95 * truthA, at + ": the planes are met apart");
            for (int round = 0; round < 2; round++) {
                // A's stretch runs from short of B's hit to past its own: its walk places the cells under B's hit.
                assertEquals(truthA, a.nearestHitBetweenMetres(e, u, -n, 0.97 * truthB, 1.02 * truthA), 2e-6 * truthA, at + ", A");
                assertEquals(truthB, b.nearestHitBetweenMetres(e, u, -n, 0.98 * truthB, 1.02 * truthB), 2e-6 * truthB, at + ", B");
            }
        }
    }

    /**
     * On rugged relief (ridges a few cells wide, summits of one sample), the crest-safe search must
     * find what a dense march finds: the first sign change of the clearance sampled every 1/16 of a
     * cell, then bisected. The march can miss a crest crossed over less than its step, where the
     * search (which computes the ray on every edge it crosses near the surface) finds a nearer true
     * crossing; it must never find a farther one. A march by whole cells must differ often (what the
     * test is able to see: a search stepping cell by cell would fail it).
     */
    @Test
    void crestSafeSearchFindsWhatADenseMarchFinds() {
        java.util.function.DoubleBinaryOperator relief = (lat, lon) -> {
            double y = (lat - 46) * 600, x = (lon - 8) * 600; // in cells
            double ridges = 400 * Math.abs(Math.sin(0.11 * x + 0.05 * y)) + 300 * Math.abs(Math.sin(0.07 * y - 0.03 * x));
            double spikes = ((int) (x * 7 + y * 13) % 23 == 0) ? 250 : 0;
            return 600 + ridges + spikes;
        };
        double range = 15_000;
        Mosaic mosaic = Mosaic.of(Synthetic.dem(relief, 46, 8, 1, 1), TileSelection.around(46.5, 8.5, range), MissingTilePolicy.AUTO);
        Viewpoint eye = Viewpoint.onDem(mosaic, 46.5, 8.5, 150, 0);
        TerrainRayProbe probe = new TerrainRayProbe(mosaic, eye, Refraction.STANDARD, range);
        double cellMetres = Math.PI / 180 * Ellipsoid.A_METRES / 600 * Math.cos(Math.toRadians(46.5));
        Random random = new Random(11);
        int rays = 400, hits = 0, fineDiffers = 0, cellMarchDiffers = 0;
        for (int i = 0; i < rays; i++) {
            double az = random.nextDouble() * 2 * Math.PI, el = Math.toRadians(-4 + 5 * random.nextDouble());
            double e = Math.cos(el) * Math.sin(az), n = Math.cos(el) * Math.cos(az), u = Math.sin(el);
            double truth = denseMarch(probe, e, n, u, cellMetres / 16, range / Math.cos(el));
            double fine = probe.firstHitMetres(e, u, -n, 50, range / Math.cos(el));
            double cellMarch = denseMarch(probe, e, n, u, cellMetres, range / Math.cos(el));
            if (Double.isFinite(truth)) {
                hits++;
            }
            if (differs(fine, truth) && fine < truth) {
                // Nearer than the march: a crest between its samples, which must be a real crossing.
                assertTrue(probe.clearance(e, n, u, fine) < 0.05, "a nearer hit that is no crossing at " + fine + " m (march: " + truth + " m)");
            } else if (differs(fine, truth)) {
                fineDiffers++;
            }
            cellMarchDiffers += differs(cellMarch, truth) ? 1 : 0;
        }
        assertTrue(hits > rays / 2, "most rays meet the relief: " + hits);
        assertEquals(0, fineDiffers, "crest-safe search misses what the dense march finds on " + fineDiffers + " of " + rays + " rays");
        assertTrue(cellMarchDiffers >= rays / 20, "a march by whole cells should miss crests here: " + cellMarchDiffers);
    }

    /** A probe from 2 m above Mount Washington's summit on the shared SRTM3 tiles, standard refraction. */
    private static TerrainRayProbe washingtonProbe(double rangeMetres) throws java.io.IOException {
        Mosaic mosaic = Mosaic.of(new dempano.dem.DemDirectory(dempano.SharedData.demDir()),
                TileSelection.around(44.2706, -71.3033, rangeMetres), MissingTilePolicy.AUTO);
        return new TerrainRayProbe(mosaic, Viewpoint.onDem(mosaic, 44.2706, -71.3033, 2, 0), Refraction.STANDARD, rangeMetres);
    }

    /**
     * The same on real relief: Mount Washington's SRTM3 tile (N44W072) from 2 m above the summit,
     * rays from 6° to 0.5° under the horizon, out to 40 km, against a march by 1/8 cell.
     */
    @Test
    void crestSafeSearchOnRealReliefFindsWhatADenseMarchFinds() throws Exception {
        double range = 40_000;
        TerrainRayProbe probe = washingtonProbe(range);
        double cellMetres = Math.PI / 180 * Ellipsoid.A_METRES / 1200 * Math.cos(Math.toRadians(44.27)); // SRTM3
        Random random = new Random(5);
        int rays = 300, hits = 0, missed = 0;
        for (int i = 0; i < rays; i++) {
            double az = random.nextDouble() * 2 * Math.PI, el = Math.toRadians(-6 + 5.5 * random.nextDouble());
            double e = Math.cos(el) * Math.sin(az), n = Math.cos(el) * Math.cos(az), u = Math.sin(el);
            double to = range / Math.cos(el);
            double truth = denseMarch(probe, e, n, u, cellMetres / 8, to);
            double probed = probe.firstHitMetres(e, u, -n, 50, to);
            hits += Double.isFinite(truth) ? 1 : 0;
            if (differs(probed, truth) && probed < truth) {
                assertTrue(probe.clearance(e, n, u, probed) < 0.05, "a nearer hit that is no crossing at " + probed + " m (march: " + truth + " m)");
            } else if (differs(probed, truth)) {
                missed++;
            }
        }
        assertTrue(hits > rays / 2, "most rays meet the relief: " + hits);
        assertEquals(0, missed, "the search missed what the dense march found on " + missed + " of " + rays + " rays");
    }

    /**
     * A ray that grazes a crest on a cell edge finds it wherever its search starts. Mount Washington's panorama
     * (20 px/°, refraction 0.13, 100 km) has a pixel, azimuth 54.125°, elevation −2.775°, whose ray meets a ridge
     * 29.8 km off just under its crest: searched from 28.7 km it was met, from 28.68 km the search crossed that
     * edge where the path extrapolated from an anchor 2 km back put it (a metre or two off) and went on to 41.9 km.
     * The truth is the walk over every cell along the last 2 km ({@link TerrainRayProbe#nearestHitBetweenMetres}),
     * which needs no anchor.
     */
    @Test
    void aRayGrazingACrestOnAnEdgeMeetsItWhereverTheSearchStarts() throws Exception {
        TerrainRayProbe probe = washingtonProbe(100_000);
        double az = Math.toRadians(54.125), el = Math.toRadians(-2.775);
        double e = Math.cos(el) * Math.sin(az), n = Math.cos(el) * Math.cos(az), u = Math.sin(el);
        double truth = probe.nearestHitBetweenMetres(e, u, -n, 28_600, 30_500);
        assertEquals(29_838, truth, 1, "the walk meets the ridge");
        for (double from : new double[] {5_000, 20_000, 25_000, 28_000, 28_600, 28_675.852880706883, 28_700, 29_700}) {
            assertEquals(truth, probe.firstHitMetres(e, u, -n, from, 45_000), 1e-6 * truth, "searched from " + from + " m");
        }
    }

    /**
     * A ray clipping a crest of the search's surface (heights interpolated in latitude and longitude) that the drawn
     * triangles, planar in 3-D, hold centimetres lower passes over it and meets the drawn surface behind. The hills at
     * 70° N of the stiff-scene test (ExactDistanceTest): the pixel at azimuth 289.375°, elevation −1.025°, from 2 m
     * above the ground, was given 1296 m (the interpolated crest) where the CPU reference and the walk over every
     * cell's triangles meet it 1406 m off; in real panoramas 1 to 9 pixels each, up to 300 times too near.
     */
    @Test
    void aRayClippingACrestOnlyTheInterpolatedHeightsHaveMeetsTheDrawnSurfaceBehindIt() {
        double k = 111_195;
        java.util.function.DoubleBinaryOperator hills = (la, lo) -> 200 + 900 * Math.exp(-(Math.pow((la - 70.55) * k, 2)
                + Math.pow((lo - 10.6) * k * Math.cos(Math.toRadians(70.5)), 2)) / (2 * 3000 * 3000));
        Mosaic mosaic = Mosaic.of(Synthetic.tiles(hills, 601, Synthetic.block(70, 10, 1, 1)),
                TileSelection.around(70.5, 10.5, 30_000), MissingTilePolicy.AUTO);
        Viewpoint eye = Viewpoint.onDem(mosaic, 70.5, 10.5, 0, 2);
        TerrainRayProbe probe = new TerrainRayProbe(mosaic, eye, Refraction.NONE, 30_000);
        double az = Math.toRadians(289.375), el = Math.toRadians(-1.025);
        double e = Math.cos(el) * Math.sin(az), n = Math.cos(el) * Math.cos(az), u = Math.sin(el);
        assertTrue(probe.clearance(e, n, u, 1296.3112) < 0.01, "the interpolated heights reach the ray near 1296 m");
        assertTrue(Double.isNaN(probe.nearestHitBetweenMetres(e, u, -n, 1100, 1400)), "the drawn triangles do not");
        double truth = probe.nearestHitBetweenMetres(e, u, -n, 1300, 1500);
        assertEquals(1406.26, truth, 0.01, "the walk over the triangles");
        for (double from : new double[] {1, 100, 700, 1257}) {
            assertEquals(truth, probe.firstHitMetres(e, u, -n, from, 40_000), 1e-6 * truth, "searched from " + from + " m");
        }
    }

    /**
     * Whether two crossings differ: more than a cell (1/600°, 128 m east–west here) apart along the
     * ray. The march steps on the heights interpolated in latitude and longitude, the probe ends on
     * the planar triangles the renderers draw; the two surfaces are millimetres to centimetres apart,
     * which at grazing incidence moves a crossing by metres, never by a cell. A crest stepped over
     * moves it at least to the far side of that crest.
     */
    private static boolean differs(double probed, double truth) {
        if (Double.isInfinite(truth) || Double.isNaN(truth)) {
            return Double.isFinite(probed);
        }
        return !(Math.abs(probed - truth) <= 128);
    }

    /** The first sign change of the clearance sampled every {@code step} metres, bisected to 1e-10; +∞ when none. */
    private static double denseMarch(TerrainRayProbe probe, double e, double n, double u, double step, double to) {
        double a = 50;
        for (double b = a + step; b <= to; a = b, b += step) {
            double cb = probe.clearance(e, n, u, b);
            if (Double.isNaN(cb)) {
                return Double.POSITIVE_INFINITY;
            }
            if (cb <= 0) {
                for (int k = 0; k < 80 && b - a > 1e-10 * b; k++) {
                    double m = 0.5 * (a + b);
                    if (probe.clearance(e, n, u, m) > 0) {
                        a = m;
                    } else {
                        b = m;
                    }
                }
                return 0.5 * (a + b);
            }
        }
        return Double.POSITIVE_INFINITY;
    }
}
