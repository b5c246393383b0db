package dempano.geo;

import static org.junit.jupiter.api.Assertions.assertEquals;

import net.sf.geographiclib.Geodesic;
import net.sf.geographiclib.GeodesicData;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class EllipsoidTest {
    @Test
    void knownEcefPoints() {
        double[] p = new double[3];
        Ellipsoid.toEcef(0, 0, 0, p);
        assertEquals(6378137.0, p[0], 1e-9);
        assertEquals(0, p[1], 1e-9);
        Ellipsoid.toEcef(90, 0, 0, p);
        assertEquals(6356752.314245, p[2], 1e-6);
        Ellipsoid.toEcef(0, 90, 100, p);
        assertEquals(6378237.0, p[1], 1e-9);
    }

    // Round trip geodetic -> ECEF -> geodetic; tolerance 1e-10 deg (11 µm) and 0.1 mm.
    @ParameterizedTest
    @CsvSource({"0, 0, 0", "46.4314, 8.0942, 2927", "-15.5, 166.5, -50", "59.9, 10.5, 10000", "89.9999, -45, 5",
            "-89.5, 179.99, 1000000", "10, -180, -100000", "44.2706, -71.3033, 1917"})
    void roundTrip(double lat, double lon, double h) {
        double[] p = new double[3];
        Ellipsoid.toEcef(lat, lon, h, p);
        double[] g = Ellipsoid.toGeodetic(p[0], p[1], p[2]);
        assertEquals(lat, g[0], 1e-10);
        assertEquals(0, ((g[1] - lon) % 360 + 540) % 360 - 180, 1e-10);
        assertEquals(h, g[2], 1e-4);
    }

    // The ENU direction of a far point (the normal-section azimuth) equals GeographicLib's geodesic
    // azimuth to within the difference between the two curves: tens of micro-degrees at 300 km.
    @ParameterizedTest
    @CsvSource({"46.43, 8.09, 0, 1000", "46.43, 8.09, 37, 100000", "46.43, 8.09, 200, 300000",
            "-15.5, 166.5, 300, 150000", "59.9, 10.5, 90, 300000", "0, 179.9, 95, 200000"})
    void enuAzimuthMatchesGeodesicAzimuth(double lat, double lon, double az, double dist) {
        GeodesicData g = Geodesic.WGS84.Direct(lat, lon, az, dist);
        LocalFrame f = new LocalFrame(lat, lon, 0);
        double[] enu = new double[3];
        f.toEnu(g.lat2, g.lon2, 0, enu);
        double enuAz = Math.toDegrees(Math.atan2(enu[0], enu[1]));
        assertEquals(0, ((enuAz - az) % 360 + 540) % 360 - 180, 5e-5);
        // Chord length vs arc: the chord is shorter by d³/(24R²) on a sphere.
        double chord = Math.sqrt(enu[0] * enu[0] + enu[1] * enu[1] + enu[2] * enu[2]);
        double sphereArc = Refraction.groundDistanceFromChordMetres(chord);
        assertEquals(dist, sphereArc, dist * 5e-3);
        // The point sinks below the tangent plane by about d²/2R.
        double r = Ellipsoid.MEAN_RADIUS_METRES;
        assertEquals(-dist * dist / (2 * r), enu[2], Math.max(0.02, 0.01 * dist * dist / (2 * r)));
    }

    @Test
    void enuRoundTrip() {
        LocalFrame f = new LocalFrame(46.4314, 8.0942, 2929);
        double[] enu = new double[3];
        f.toEnu(46.9, 8.7, 1500, enu);
        double[] g = f.toGeodetic(enu[0], enu[1], enu[2]);
        assertEquals(46.9, g[0], 1e-10);
        assertEquals(8.7, g[1], 1e-10);
        assertEquals(1500, g[2], 1e-4);
        f.toEnu(46.4314, 8.0942, 2929, enu);
        assertEquals(0, Math.abs(enu[0]) + Math.abs(enu[1]) + Math.abs(enu[2]), 1e-6);
    }

    @Test
    void refractionLift() {
        // k·d²/2R with R = 6371008.77 m: 100 km at k = 0.13 lifts 102.0 m.
        assertEquals(0.13 * 1e10 / (2 * 6371008.7714), Refraction.STANDARD.liftMetres(100_000), 1e-6);
        assertEquals(0, Refraction.NONE.liftMetres(300_000), 0);
        org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class, () -> new Refraction(Double.NaN));
    }

    @Test
    void radiiOfCurvatureAgainstGeodesicArcs() {
        // M(φ) is the meridian arc's metres per radian of latitude, N(φ)·cos φ a parallel's metres per radian of
        // longitude: both measured as short geodesics by GeographicLib (a 1e-4 rad arc: the truncation error of
        // the central difference is below 1e-9 relative).
        net.sf.geographiclib.Geodesic g = net.sf.geographiclib.Geodesic.WGS84;
        double deltaDeg = Math.toDegrees(1e-4);
        for (double lat : new double[] {0, 10, 30, 44.27, 46.4314, 60, 80, 89}) {
            double s = Math.sin(Math.toRadians(lat));
            double meridian = g.Inverse(lat - deltaDeg, 0, lat + deltaDeg, 0).s12 / 2e-4;
            assertEquals(meridian, Ellipsoid.meridianRadiusOfSinMetres(s), 1e-6 * 1e-3 * meridian, "M at " + lat);
            // The parallel's arc is no geodesic, but over 1e-4 rad of longitude a geodesic between its ends is
            // shorter only by a part in 1e9 at these latitudes.
            double parallelPerRadian = g.Inverse(lat, -deltaDeg / 2 * 1e-2, lat, deltaDeg / 2 * 1e-2).s12 / 1e-6;
            assertEquals(parallelPerRadian, Ellipsoid.primeVerticalRadiusOfSinMetres(s) * Math.cos(Math.toRadians(lat)),
                    1e-6 * parallelPerRadian, "N cos φ at " + lat);
            assertEquals(Ellipsoid.primeVerticalRadiusMetres(lat), Ellipsoid.primeVerticalRadiusOfSinMetres(s));
        }
    }
}
