package dempano.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.CameraImage;
import dempano.CameraRequest;
import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.Synthetic;
import dempano.camera.CameraIntrinsics;
import dempano.camera.CameraOrientation;
import dempano.camera.CameraPose;
import dempano.camera.LensDistortion;
import dempano.camera.PanoramaTarget;
import dempano.camera.TargetImage;
import dempano.dem.InMemoryDem;
import dempano.dem.MissingTilePolicy;
import dempano.dem.Mosaic;
import dempano.geo.Ellipsoid;
import dempano.geo.EllipsoidRay;
import dempano.geo.LocalFrame;
import dempano.geo.Refraction;
import dempano.geo.Viewpoint;
import dempano.panorama.ElevationRange;
import dempano.panorama.Panorama;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The CPU reference for any ray ({@link RayCastReference}, through {@code PanoramaRenderer.openReference(dem)
 * .render(CameraRequest)}) against independent truth: a sea view against the WGS84 ellipsoid in closed form
 * (refraction 0), and the horizon-sweep panorama reference ({@link ReferenceRenderer}, an unrelated algorithm on
 * the same surface) on exactly the same rays.
 */
class RayCastReferenceTest {
    private static final double LAT = 43.5, LON = 7.5;

    /**
     * Sea: the drawn sea is planar triangles between points of the ellipsoid, so it lies below the ellipsoid by at
     * most a cell's sag, (cell diagonal)²/(8R) ≈ 0.3 mm for SRTM3; a ray meeting it at incidence α travels
     * sag / sin α farther. Bound per pixel: that, plus 1e-7 relative.
     */
    @ParameterizedTest(name = "{0}")
    @CsvSource({
            "level pinhole, 300, 200, 50, 0, 0, 0, 0, 100",
            "barrel k1 -0.25 rolled 20° pitched -8°, 300, 200, 70, -0.25, 0.05, 20, -8, 100",
            "pitched -30° rolled 30° tangential, 240, 240, 60, -0.05, 0.01, 30, -30, 300",
            "telephoto 2° across the horizon, 300, 200, 2, 0, 0, 5, -1.2, 1500"})
    void aSeaViewMatchesTheEllipsoidOnEveryPixel(String name, int w, int h, double hfovDeg, double k1, double p1,
                                                 double rollDeg, double pitchDeg, double eyeMetres) {
        CameraIntrinsics base = CameraIntrinsics.fromHorizontalFov(w, h, hfovDeg);
        CameraIntrinsics k = base.withDistortion(new LensDistortion(k1, 0, p1, p1 / 2, 0));
        CameraPose pose = new CameraPose(LAT, LON, 0, eyeMetres, 0, new CameraOrientation(57, pitchDeg, rollDeg));
        InMemoryDem dem = Synthetic.tiles((la, lo) -> 0, 1201, Synthetic.block(43, 7, 1, 1));
        double range = Math.min(170_000, 4 * Math.sqrt(2 * 6_371_000.0 * eyeMetres) + 5000);
        CameraRequest req = CameraRequest.of(k, pose).withSettings(PanoramaRequest.at(LAT, LON).withRangeMetres(range)
                .withRefraction(Refraction.NONE));
        CameraImage img;
        long start = System.nanoTime();
        try (PanoramaRenderer cpu = PanoramaRenderer.openReference(dem)) {
            img = cpu.render(req);
        }
        double seconds = (System.nanoTime() - start) / 1e9;
        LocalFrame f = new LocalFrame(LAT, LON, eyeMetres);
        double[] eye = new double[3], scratch = new double[3], dir = new double[3], ray = new double[3];
        Ellipsoid.toEcef(LAT, LON, eyeMetres, eye);
        double cell = Math.toRadians(1.0 / 1200) * Ellipsoid.A_METRES;
        double sag = 2 * cell * cell / (8 * Ellipsoid.B_METRES);
        float[] distance = img.distanceArray();
        long sea = 0, sky = 0, noRay = 0, bad = 0;
        double worstRatio = 0;
        for (int row = 0; row < h; row++) {
            for (int col = 0; col < w; col++) {
                img.view().rayOf(col, row, ray);
                double d = distance[row * w + col];
                if (Double.isNaN(ray[0])) {
                    noRay++;
                    bad += Double.isNaN(d) ? 0 : 1;
                    continue;
                }
                EllipsoidRay.enuDirectionToEcef(f, eye, ray[0], ray[1], ray[2], scratch, dir);
                double t = EllipsoidRay.distanceToWgs84Metres(eye, dir);
                if (Double.isInfinite(t)) {
                    // Sky by the ellipsoid: the facets lie below it, so the cast ray must miss them too.
                    sky++;
                    bad += Double.isInfinite(d) ? 0 : 1;
                    continue;
                }
                double[] p = {eye[0] + t * dir[0], eye[1] + t * dir[1], eye[2] + t * dir[2]};
                double sinIncidence = Math.sin(Math.toRadians(EllipsoidRay.incidenceDeg(p, dir, Ellipsoid.A_METRES,
                        Ellipsoid.B_METRES)));
                double bound = sag / Math.max(sinIncidence, 1e-12) + 1e-7 * t;
                if (Double.isInfinite(d) && t > range * 0.999) {
                    continue; // the sea beyond the range of sight is not drawn
                }
                sea++;
                double ratio = Math.abs(d - t) / bound;
                worstRatio = Math.max(worstRatio, Double.isNaN(ratio) ? Double.POSITIVE_INFINITY : ratio);
                // Below a facet-sized incidence the ray may pass under a facet's edge and out to the horizon: only
                // where the sag bound is under a tenth of the distance is the bound checked.
                if (bound < 0.1 * t && !(ratio <= 1)) {
                    bad++;
                }
            }
        }
        String report = String.format(Locale.ROOT, "%s: %d sea, %d sky, %d without a ray, %d outside the bound;"
                + " worst |error|/bound %.3g; %.1f s (CPU ray cast)", name, sea, sky, noRay, bad, worstRatio, seconds);
        System.out.println(report);
        assertTrue(sea > w * h / 20, report);
        assertEquals(0, bad, report);
    }

    private static final double K = 111_195;

    /** A 1500 m cone on a grid node, a ridge in front of it and rolling hills: crests, silhouettes, hidden valleys. */
    private static double hills(double la, double lo) {
        double n = (la - 46.55) * K, e = (lo - 8.56) * K * Math.cos(Math.toRadians(46.5));
        double peak = Math.max(0, 1500 - 0.6 * Math.hypot(n, e));
        double n2 = (la - 46.52) * K, e2 = (lo - 8.53) * K * Math.cos(Math.toRadians(46.5));
        double ridge = 400 * Math.exp(-Math.pow(n2 + e2, 2) / (2 * 400.0 * 400.0));
        double rolling = 120 * Math.sin(la * 300) * Math.cos(lo * 210);
        return 800 + peak + ridge + rolling;
    }

    /**
     * The ray cast and the horizon sweep are two algorithms for one surface: on a panorama's own pixel rays
     * they must agree to double rounding wherever neither ray grazes a silhouette edge.
     */
    @Test
    void onAPanoramasRaysTheRayCastAgreesWithTheHorizonSweep() {
        InMemoryDem dem = Synthetic.tiles(RayCastReferenceTest::hills, 601, Synthetic.block(46, 8, 1, 1));
        double lat = 46.5, lon = 8.5, range = 30_000;
        Refraction refraction = Refraction.STANDARD;
        PanoramaRequest req = PanoramaRequest.at(lat, lon).withRangeMetres(range).withRefraction(refraction)
                .withPixelsPerDegree(4).withElevationRange(new ElevationRange(-20, 15, false));
        Panorama pano;
        try (PanoramaRenderer cpu = PanoramaRenderer.openReference(dem)) {
            pano = cpu.render(req);
        }
        Mosaic mosaic = Mosaic.around(dem, lat, lon, range, MissingTilePolicy.AUTO);
        Viewpoint eye = Viewpoint.onDem(mosaic, lat, lon, req.offsetMetres(), req.eyeHeightMetres());
        assertEquals(pano.metadata().eyeAltitudeMetres(), eye.eyeAltitudeMetres(), 1e-9);
        TargetImage target = new PanoramaTarget(pano.geometry());
        RayCastReference.Result cast = RayCastReference.render(new RayCastReference.Scene(mosaic, eye, refraction), range,
                target, false);
        float[] sweep = pano.distanceArray(), rays = cast.distanceMetres();
        int w = target.widthPx(), h = target.heightPx();
        long terrain = 0, sky = 0, disagree = 0, mismatch = 0;
        double worst = 0;
        for (int i = 0; i < w * h; i++) {
            double a = sweep[i], b = rays[i];
            if (Double.isInfinite(a) && Double.isInfinite(b)) {
                sky++;
            } else if (Double.isInfinite(a) != Double.isInfinite(b) || Double.isNaN(b)) {
                mismatch++;
            } else {
                terrain++;
                double rel = Math.abs(a - b) / a;
                worst = Math.max(worst, rel);
                // Both in float32 at the end: a few ulps (6e-8 each).
                if (rel > 1e-6) {
                    disagree++;
                }
            }
        }
        String report = String.format(Locale.ROOT, "%d×%d: %d terrain (worst relative difference %.2e, %d over 1e-6),"
                + " %d sky, %d sky/terrain mismatches; undecided %d", w, h, terrain, worst, disagree, sky, mismatch,
                cast.undecided());
        System.out.println(report);
        assertTrue(terrain > w * h / 3, report);
        assertTrue(sky > w * h / 10, report);
        assertEquals(0, cast.undecided(), report);
        // A ray exactly through a silhouette vertex may be decided either way by rounding: at most a few.
        assertTrue(mismatch + disagree <= w * h / 20_000 + 2, report);
    }

    @Test
    void theShadedElevationIsTheDrawnSurfacesHeight() {
        // The corner weights shade() interpolates the elevation with reproduce the drawn surface's height
        // (Triangulation.height) and are a partition of one, non-negative inside the triangle holding the point.
        java.util.Random random = new java.util.Random(3);
        for (boolean nwToSe : new boolean[] {true, false}) {
            for (int i = 0; i < 2000; i++) {
                double[] h = {random.nextDouble() * 3000, random.nextDouble() * 3000, random.nextDouble() * 3000,
                        random.nextDouble() * 3000};
                double south = random.nextDouble(), east = random.nextDouble();
                int triangle = dempano.dem.Triangulation.triangleHolding(nwToSe, south, east);
                double sum = 0, elevation = 0;
                for (int k = 0; k < 3; k++) {
                    int corner = dempano.dem.Triangulation.corner(nwToSe, triangle, k);
                    double w = RayCastReference.cornerWeight(nwToSe, triangle, corner, south, east);
                    org.junit.jupiter.api.Assertions.assertTrue(w >= -1e-12, "weight " + w);
                    sum += w;
                    elevation += w * h[corner];
                }
                org.junit.jupiter.api.Assertions.assertEquals(1, sum, 1e-12);
                org.junit.jupiter.api.Assertions.assertEquals(
                        dempano.dem.Triangulation.height(nwToSe, h[0], h[1], h[2], h[3], south, east), elevation, 1e-9);
            }
        }
    }
}
