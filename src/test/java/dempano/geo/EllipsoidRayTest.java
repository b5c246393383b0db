package dempano.geo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class EllipsoidRayTest {
    static final double R = 6_371_000;

    /** A unit direction at a depression angle below the local horizontal of a point on the x axis, in the x-y plane. */
    static double[] depressed(double depressionRad) {
        return new double[] {-Math.sin(depressionRad), Math.cos(depressionRad), 0};
    }

    // Sphere, textbook: from distance D = R + h off the centre, a ray depressed by α meets the sphere at
    // d = D sin α − √(R² − D² cos² α), at an incidence i with R cos i = D cos α; it misses when D cos α > R.
    @ParameterizedTest
    @CsvSource({"2, 0.1", "2, 1", "100, 0.5", "100, 45", "2000, 2", "2000, 89.9", "10, 90"})
    void onASphereTheTextbookFormulaHolds(double heightMetres, double depressionDeg) {
        double a = Math.toRadians(depressionDeg), big = R + heightMetres;
        double[] origin = {big, 0, 0};
        double[] dir = depressed(a);
        double expected = big * Math.sin(a) - Math.sqrt(R * R - big * big * Math.cos(a) * Math.cos(a));
        double d = EllipsoidRay.distanceMetres(origin, dir, R, R);
        assertEquals(expected, d, 1e-9 * expected + 1e-6);
        double[] hit = {origin[0] + d * dir[0], origin[1] + d * dir[1], 0};
        double expectedIncidence = Math.toDegrees(Math.acos(Math.min(1, big * Math.cos(a) / R)));
        assertEquals(expectedIncidence, EllipsoidRay.incidenceDeg(hit, dir, R, R), 1e-6);
    }

    @ParameterizedTest
    @CsvSource({"2", "100", "2000"})
    void theHorizonDipSeparatesSeaFromSky(double heightMetres) {
        // Sphere, any plane: the dip is acos(R / (R + h)); at the equator looking east the WGS84 section is
        // the equatorial circle, so the same holds with R = a.
        for (double radius : new double[] {R, Ellipsoid.A_METRES}) {
            double dip = Math.acos(radius / (radius + heightMetres));
            double[] origin = {radius + heightMetres, 0, 0};
            double below = EllipsoidRay.distanceMetres(origin, depressed(dip + 1e-7), radius, radius == R ? R : Ellipsoid.B_METRES);
            double above = EllipsoidRay.distanceMetres(origin, depressed(dip - 1e-7), radius, radius == R ? R : Ellipsoid.B_METRES);
            double tangent = Math.sqrt((radius + heightMetres) * (radius + heightMetres) - radius * radius);
            assertTrue(Double.isFinite(below), "just below the dip the sea is met");
            // Just below the tangent the root moves fast: within a few per cent of the tangent length.
            assertEquals(tangent, below, 0.05 * tangent);
            assertEquals(Double.POSITIVE_INFINITY, above, "just above the dip is sky");
        }
    }

    @ParameterizedTest
    @CsvSource({"0, 0, 2", "46.5, 8.5, 100", "-33.9, 151.2, 2000", "89.5, -120, 37", "43.5, 7.5, 0.5"})
    void straightDownReadsExactlyTheEyeHeight(double latDeg, double lonDeg, double heightMetres) {
        LocalFrame eye = new LocalFrame(latDeg, lonDeg, heightMetres);
        double[] origin = new double[3], scratch = new double[3], dir = new double[3];
        eye.enuToEcef(0, 0, 0, origin);
        EllipsoidRay.enuDirectionToEcef(eye, origin, 0, 0, -1, scratch, dir);
        assertEquals(heightMetres, EllipsoidRay.distanceToWgs84Metres(origin, dir), 1e-7);
        double[] hit = {origin[0] + heightMetres * dir[0], origin[1] + heightMetres * dir[1], origin[2] + heightMetres * dir[2]};
        assertEquals(90, EllipsoidRay.incidenceDeg(hit, dir, Ellipsoid.A_METRES, Ellipsoid.B_METRES), 1e-5);
        // Straight up, and horizontal (the eye is above the sea): sky.
        EllipsoidRay.enuDirectionToEcef(eye, origin, 0, 0, 1, scratch, dir);
        assertEquals(Double.POSITIVE_INFINITY, EllipsoidRay.distanceToWgs84Metres(origin, dir));
        EllipsoidRay.enuDirectionToEcef(eye, origin, 1, 0, 0, scratch, dir);
        assertEquals(Double.POSITIVE_INFINITY, EllipsoidRay.distanceToWgs84Metres(origin, dir));
    }

    @ParameterizedTest
    @CsvSource({"46.5, 8.5, 100, 30, -1", "0, 0, 2, 90, -0.2", "-60, 20, 2000, 200, -5"})
    void theMetPointLiesOnTheEllipsoid(double latDeg, double lonDeg, double heightMetres, double azDeg, double elDeg) {
        // Checked through the independent ECEF → geodetic conversion: height 0 at the point met.
        LocalFrame eye = new LocalFrame(latDeg, lonDeg, heightMetres);
        double az = Math.toRadians(azDeg), el = Math.toRadians(elDeg);
        double e = Math.cos(el) * Math.sin(az), n = Math.cos(el) * Math.cos(az), u = Math.sin(el);
        double[] origin = new double[3], scratch = new double[3], dir = new double[3];
        eye.enuToEcef(0, 0, 0, origin);
        EllipsoidRay.enuDirectionToEcef(eye, origin, e, n, u, scratch, dir);
        double d = EllipsoidRay.distanceToWgs84Metres(origin, dir);
        assertTrue(Double.isFinite(d) && d > heightMetres, "met at " + d);
        assertEquals(0, eye.toGeodetic(d * e, d * n, d * u)[2], 1e-6);
        assertTrue(eye.toGeodetic(0.999 * d * e, 0.999 * d * n, 0.999 * d * u)[2] > 0, "above the sea before the point");
    }
}
