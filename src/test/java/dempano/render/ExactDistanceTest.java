package dempano.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.Synthetic;
import dempano.dem.InMemoryDem;
import dempano.geo.Ellipsoid;
import dempano.geo.LocalFrame;
import dempano.geo.Refraction;
import dempano.panorama.ElevationRange;
import dempano.panorama.Panorama;
import java.util.Locale;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Every pixel's distance is measured along its own ray: stiff cases against closed forms. The open
 * sea is the stiffest: a ray that skims it changes its distance by per cents when its angle changes
 * by a hundredth of a degree.
 */
class ExactDistanceTest {
    /**
     * Distance along a ray from an ECEF point to the WGS84 ellipsoid (h = 0), metres; +∞ when the ray
     * misses it. Closed form: the ray scaled into the unit sphere's space, a quadratic.
     */
    static double rayToEllipsoid(double[] origin, double[] dir) {
        double a = Ellipsoid.A_METRES, b = Ellipsoid.B_METRES;
        double ox = origin[0] / a, oy = origin[1] / a, oz = origin[2] / b;
        double dx = dir[0] / a, dy = dir[1] / a, dz = dir[2] / b;
        double qa = dx * dx + dy * dy + dz * dz, qb = 2 * (ox * dx + oy * dy + oz * dz), qc = ox * ox + oy * oy + oz * oz - 1;
        double disc = qb * qb - 4 * qa * qc;
        if (disc < 0) {
            return Double.POSITIVE_INFINITY;
        }
        // The nearer root, in the cancellation-free form.
        double q = -0.5 * (qb + Math.copySign(Math.sqrt(disc), qb));
        double t = Math.min(q / qa, qc / q);
        return t > 0 ? t : Double.POSITIVE_INFINITY;
    }

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
                truth[row * p.widthPx() + col] = rayToEllipsoid(eye, dir);
            }
        }
        return truth;
    }

    @ParameterizedTest(name = "eye {0} m above the sea")
    @CsvSource({"2, 12000"})
    void theOpenSeaMatchesTheClosedFormOnEveryPixel(double eyeMetres, double rangeMetres) {
        double lat = 43.5, lon = 7.5;
        InMemoryDem dem = Synthetic.tiles((la, lo) -> 0, 1201, Synthetic.block(43, 7, 1, 1));
        PanoramaRequest req = PanoramaRequest.at(lat, lon).withAltitudeMetres(eyeMetres).withEyeHeightMetres(0)
                .withRangeMetres(rangeMetres).withRefraction(Refraction.NONE).withPixelsPerDegree(20)
                .withElevationRange(new ElevationRange(-4, 1, false)).withLodErrorPx(0);
        Panorama p;
        try (PanoramaRenderer gl = PanoramaRenderer.open(dem)) {
            p = gl.render(req, System.out::println);
        }
        double[] truth = seaTruth(p, lat, lon, eyeMetres);
        int w = p.widthPx(), h = p.heightPx();
        double worstHorizonRow = 0, worstBelow = 0;
        long skyMismatch = 0, over = 0, sea = 0;
        double[] perRowWorst = new double[6];
        for (int col = 0; col < w; col++) {
            int first = -1;
            for (int row = 0; row < h; row++) {
                double t = truth[row * w + col], d = p.distanceArray()[row * w + col];
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
        assertTrue(worstBelow < 0.001, report);
    }
}
