package dempano.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.Synthetic;
import dempano.dem.InMemoryDem;
import dempano.geo.Ellipsoid;
import dempano.geo.EllipsoidRay;
import dempano.geo.LocalFrame;
import dempano.geo.Refraction;
import dempano.panorama.ElevationRange;
import dempano.terrain.LevelOfDetail;
import dempano.panorama.Panorama;
import dempano.panorama.DistanceComparison;
import dempano.panorama.Layer;
import java.util.EnumSet;
import java.util.Locale;
import java.util.function.DoubleBinaryOperator;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Every pixel's distance is measured along its own ray: stiff cases against closed forms. The open
 * sea is the stiffest: a ray that skims it changes its distance by per cents when its angle changes
 * by a hundredth of a degree.
 */
class ExactDistanceTest {
    /** The closed-form distance of every pixel of a panorama from an eye at {@code heightMetres} above the sea. */
    static double[] seaTruth(Panorama p, double latDeg, double lonDeg, double heightMetres) {
        LocalFrame f = new LocalFrame(latDeg, lonDeg, heightMetres);
        double[] eye = new double[3], tip = new double[3];
        Ellipsoid.toEcef(latDeg, lonDeg, heightMetres, eye);
        double[] truth = new double[p.widthPx() * p.heightPx()];
        for (int row = 0; row < p.heightPx(); row++) {
            double el = Math.toRadians(p.elevationOfRow(row));
            for (int col = 0; col < p.widthPx(); col++) {
                double az = Math.toRadians(p.azimuthOfColumn(col));
                f.enuToEcef(Math.cos(el) * Math.sin(az), Math.cos(el) * Math.cos(az), Math.sin(el), tip);
                double[] dir = {tip[0] - eye[0], tip[1] - eye[1], tip[2] - eye[2]};
                truth[row * p.widthPx() + col] = EllipsoidRay.distanceToWgs84Metres(eye, dir);
            }
        }
        return truth;
    }

    @ParameterizedTest(name = "eye {0} m above the sea")
    @CsvSource({"2, 12000", "100, 45000", "2000, 170000"})
    void theOpenSeaMatchesTheClosedFormOnEveryPixel(double eyeMetres, double rangeMetres) {
        double lat = 43.5, lon = 7.5;
        InMemoryDem dem = Synthetic.tiles((la, lo) -> 0, 1201, Synthetic.block(43, 7, 1, 1));
        PanoramaRequest req = PanoramaRequest.at(lat, lon).withAltitudeMetres(eyeMetres).withEyeHeightMetres(0)
                .withRangeMetres(rangeMetres).withRefraction(Refraction.NONE).withPixelsPerDegree(20)
                .withElevationRange(new ElevationRange(-4, 1, false)).withExactDistances(true);
        Panorama p;
        try (PanoramaRenderer gl = PanoramaRenderer.open(dem)) {
            p = gl.render(req);
        }
        double[] truth = seaTruth(p, lat, lon, eyeMetres);
        int w = p.widthPx(), h = p.heightPx();
        float[] distance = p.distanceArray(); // a copy: taken once
        double worstHorizonRow = 0, worstBelow = 0;
        long skyMismatch = 0, over = 0, sea = 0;
        double[] perRowWorst = new double[6];
        for (int col = 0; col < w; col++) {
            int first = -1;
            for (int row = 0; row < h; row++) {
                double t = truth[row * w + col], d = distance[row * w + col];
                if (Double.isInfinite(t) != Float.isInfinite((float) d)) {
                    skyMismatch++;
                    continue;
                }
                if (Double.isInfinite(t)) {
                    continue;
                }
                if (first < 0) {
                    first = row;
                }
                double rel = Math.abs(d - t) / t;
                sea++;
                if (row - first < 6) {
                    perRowWorst[row - first] = Math.max(perRowWorst[row - first], rel);
                }
                if (row == first) {
                    worstHorizonRow = Math.max(worstHorizonRow, rel);
                } else {
                    worstBelow = Math.max(worstBelow, rel);
                    if (rel > 1e-3) {
                        over++;
                    }
                }
            }
        }
        String report = String.format(Locale.ROOT, "eye %.0f m: horizon row worst %.3g, below worst %.3g, over 0.1%% %d of %d,"
                + " sky mismatch %d, rows 0-5 worst %s, timings %s", eyeMetres, worstHorizonRow, worstBelow, over, sea,
                skyMismatch, java.util.Arrays.toString(perRowWorst), p.metadata().timingsMillis());
        System.out.println(report);
        assertTrue(worstHorizonRow < 0.01, report);
        // 0.1 % is the goal; the level of detail's distance bound is 0.2 % (2000 m: 130 of 367 200 sea pixels
        // between 0.1 % and 0.11 %), so that is what is asserted.
        assertTrue(worstBelow < LevelOfDetail.DEFAULT_MAX_DISTANCE_ERROR, report);
    }

    static final double K = 111_195;

    /** Metres north and east of (lat0, lon0) on the spherical approximation the synthetic scenes use. */
    static double north(double lat, double lat0) {
        return (lat - lat0) * K;
    }

    static double east(double lon, double lon0, double lat0) {
        return (lon - lon0) * K * Math.cos(Math.toRadians(lat0));
    }

    /**
     * Stiff scenes, each with the CPU reference as truth (an independent algorithm on the same
     * triangulated surface) and the incidence from the reference's own layer. Bounds: the relative
     * error of every pixel both see as terrain, by incidence.
     */
    static Stream<Arguments> stiffScenes() {
        double lat = 46.5, lon = 8.5;
        // A ramp rising northward at 5°, the eye 10 m above its foot: rows 0.1°, 0.5° and 2° under
        // 5° meet it at those incidences, 5.7 km, 1.1 km and 290 m away.
        DoubleBinaryOperator ramp = (la, lo) -> 1000 + Math.tan(Math.toRadians(5)) * Math.max(0, north(la, lat));
        // A knife-edge ridge (σ 60 m, 400 m high) 3 km east in front of a massif 25 km east.
        DoubleBinaryOperator ridge = (la, lo) -> 500 + 400 * Math.exp(-Math.pow(east(lo, lon, lat) - 3000, 2) / (2 * 60 * 60))
                + 2500 * Math.exp(-(Math.pow(east(lo, lon, lat) - 25_000, 2) + Math.pow(north(la, lat), 2)) / (2 * 4000 * 4000));
        // A lake (flat at 1000 m, 4 km across) in a bowl, seen from its shore slope 35 m above it: the far
        // shore 4.1 km away at 0.5° incidence.
        DoubleBinaryOperator lake = (la, lo) -> {
            double r = Math.hypot(north(la, lat) - 2500, east(lo, lon, lat));
            return r < 2000 ? 1000 : 1000 + 0.15 * (r - 2000);
        };
        // Hills at 70° N, where a degree of longitude is 38 km.
        DoubleBinaryOperator north70 = (la, lo) -> 200 + 900 * Math.exp(-(Math.pow((la - 70.55) * K, 2)
                + Math.pow((lo - 10.6) * K * Math.cos(Math.toRadians(70.5)), 2)) / (2 * 3000 * 3000));
        return Stream.of(
                Arguments.of("grazing ramp", ramp, lat, lon, 10.0, new ElevationRange(-3, 6, false)),
                Arguments.of("knife-edge ridge", ridge, lat, lon, 2.0, new ElevationRange(-3, 8, false)),
                Arguments.of("lake seen from a slope", lake, lat + 400 / K, lon, 20.0, new ElevationRange(-8, 3, false)),
                Arguments.of("at 70° north", north70, 70.5, 10.5, 2.0, new ElevationRange(-3, 5, false)));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("stiffScenes")
    void stiffScenesMatchTheReferenceAtEveryIncidence(String name, DoubleBinaryOperator f, double lat, double lon,
                                                       double eyeMetres, ElevationRange elevations) {
        int latS = (int) Math.floor(lat), lonW = (int) Math.floor(lon);
        InMemoryDem dem = Synthetic.tiles(f, 601, Synthetic.block(latS, lonW, 1, 1));
        PanoramaRequest req = PanoramaRequest.at(lat, lon).withEyeHeightMetres(eyeMetres).withRangeMetres(30_000)
                .withRefraction(Refraction.NONE).withElevationRange(elevations);
        Panorama gl, ref;
        try (PanoramaRenderer r = PanoramaRenderer.open(dem); PanoramaRenderer cpu = PanoramaRenderer.openReference(dem)) {
            gl = r.render(req);
            ref = cpu.render(req.withLayers(EnumSet.of(Layer.INCIDENCE)));
        }
        DistanceComparison c = DistanceComparison.of(gl.distanceArray(), ref.distanceArray(), gl.widthPx());
        var bins = DistanceComparison.byIncidence(gl.distanceArray(), ref.distanceArray(), ref.layer(Layer.INCIDENCE),
                DistanceComparison.INCIDENCE_BIN_LOWER_DEG);
        String report = name + ": " + c + " by incidence " + bins;
        System.out.println(report);
        assertTrue(c.shareOver5Percent() < 5e-4, report);
        assertTrue(c.p99Relative() < 1e-3, report);
        // Not one pixel 1 % off (measured: 0.45 % on the knife-edge ridge, 1.2e-7 elsewhere); a crest of the heights
        // interpolated in latitude and longitude, which the drawn triangles hold centimetres lower, taken for the hit
        // put one pixel at 70° N 7.8 % near.
        assertTrue(c.maxRelative() < 0.01, report);
        // Measured 0.14 % (ramp), 2.3 % (knife-edge ridge), 0 (lake), 0.76 % (70° N); the goal is 5 %. Beside the
        // sky the terrain probe steps a DEM cell at a time; a crest the ray crosses over less than that can be missed.
        assertTrue(c.skylineColumnsOff() < 0.04, report);
        for (var bin : bins) {
            if (bin.pixels() > 0) {
                assertTrue(bin.medianRelative() < 1e-4, report);
            }
        }
    }
}
