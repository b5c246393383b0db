package dempano.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.Synthetic;
import dempano.geo.Ellipsoid;
import dempano.geo.Geodesy;
import dempano.geo.LocalFrame;
import dempano.geo.Refraction;
import dempano.panorama.DistanceComparison;
import dempano.panorama.ElevationRange;
import dempano.panorama.Panorama;
import java.util.function.DoubleBinaryOperator;
import org.junit.jupiter.api.Test;

/** The CPU etalon against analytic truth (no OpenGL involved). */
class ReferenceRendererTest {
    static final double EYE_LAT = 46.5, EYE_LON = 8.5, HILL_LAT = 46.62, HILL_LON = 8.68;
    static final DoubleBinaryOperator HILL = (lat, lon) -> {
        double dy = (lat - HILL_LAT) * 111_195, dx = (lon - HILL_LON) * 111_195 * Math.cos(Math.toRadians(HILL_LAT));
        return 500 + 1500 * Math.exp(-(dx * dx + dy * dy) / (2 * 3000.0 * 3000.0));
    };

    /** Radius of curvature of the ellipsoid in an azimuth (Euler), metres. */
    static double eulerRadius(double latDeg, double azDeg) {
        double s = Math.sin(Math.toRadians(latDeg)), az = Math.toRadians(azDeg);
        double nRad = Ellipsoid.primeVerticalRadiusMetres(latDeg);
        double mRad = Ellipsoid.A_METRES * (1 - Ellipsoid.E2) / Math.pow(1 - Ellipsoid.E2 * s * s, 1.5);
        return 1 / (Math.cos(az) * Math.cos(az) / mRad + Math.sin(az) * Math.sin(az) / nRad);
    }

    @Test
    void flatSeaHorizonAndDistancesAreTheSphereOfCurvatures() {
        double h = 300;
        PanoramaRequest req = PanoramaRequest.at(EYE_LAT, EYE_LON).withAltitudeMetres(h).withEyeHeightMetres(0)
                .withRangeMetres(90_000).withRefraction(Refraction.NONE).withElevationRange(new ElevationRange(-3, 1, false));
        Panorama p;
        try (PanoramaRenderer r = PanoramaRenderer.openReference(Synthetic.dem((la, lo) -> 0, 45, 7, 3, 4))) {
            p = r.render(req);
        }
        int checked = 0;
        for (int col = 0; col < p.widthPx(); col += 61) {
            double az = p.azimuthOfColumn(col);
            double radius = eulerRadius(EYE_LAT, az);
            double dip = Math.toDegrees(Math.acos(radius / (radius + h)));
            // Exact point sampling: the first terrain row is the first whose centre lies below the horizon.
            int sky = DistanceComparison.skylineRow(p.distanceArray(), p.widthPx(), p.heightPx(), col);
            assertTrue(p.elevationOfRow(sky) <= -dip && p.elevationOfRow(sky - 1) > -dip, "azimuth " + az);
            // Below the horizon: the ray meets the sphere of radius R at t = (R+h) sin δ − √(R² − (R+h)² cos² δ).
            for (int row = sky + 20; row < p.heightPx(); row += 13) {
                double delta = Math.toRadians(-p.elevationOfRow(row));
                double t = (radius + h) * Math.sin(delta)
                        - Math.sqrt(radius * radius - Math.pow((radius + h) * Math.cos(delta), 2));
                // Facets sag below the ellipsoid by cell²/8R (under a millimetre); the osculating sphere
                // departs from the ellipsoid by d³-terms: 2e-5 relative within 20 km.
                if (t < 20_000) {
                    assertEquals(t, p.distanceMetres(col, row), t * 2e-5, "az " + az + " row " + row);
                    checked++;
                }
            }
        }
        assertTrue(checked > 100, "checked " + checked);
    }

    @Test
    void hillDistancesMatchAnIndependentRayMarch() {
        PanoramaRequest req = PanoramaRequest.at(EYE_LAT, EYE_LON).withRangeMetres(40_000).withRefraction(Refraction.NONE)
                .withElevationRange(new ElevationRange(-10, 10, false));
        Panorama p;
        try (PanoramaRenderer r = PanoramaRenderer.openReference(Synthetic.dem(HILL, 45, 7, 3, 3))) {
            p = r.render(req);
        }
        LocalFrame eye = new LocalFrame(EYE_LAT, EYE_LON, p.metadata().eyeAltitudeMetres());
        int c0 = (int) Math.floor(p.geometry().columnOf(Geodesy.azimuthDeg(EYE_LAT, EYE_LON, HILL_LAT, HILL_LON)));
        int checked = 0;
        for (int col = c0 - 60; col <= c0 + 60; col += 15) {
            int top = DistanceComparison.skylineRow(p.distanceArray(), p.widthPx(), p.heightPx(), col);
            for (int row = top + 2; row < p.heightPx(); row += 23) {
                double truth = Synthetic.rayMarch(eye, HILL, p.azimuthOfColumn(col), p.elevationOfRow(row), 45_000);
                if (!Double.isFinite(truth) || truth > 39_000) {
                    continue;
                }
                // The triangulated 6" grid departs from the Gaussian by under a metre.
                assertEquals(truth, p.distanceMetres(col, row), truth * 1e-3, "col " + col + " row " + row);
                checked++;
            }
        }
        assertTrue(checked > 30, "checked " + checked);
    }

    @Test
    void theRangeCutIsExactWithAndWithoutRefraction() {
        // A plain at 1000 m seen from 100 m above: within 30 km the plain's far edge is its highest
        // point in view (the geometric horizon would be 36 km away), so each column's skyline is the
        // range cut, at s = 30 km horizontally in the eye's frame.
        double s = 30_000;
        PanoramaRequest req = PanoramaRequest.at(EYE_LAT, EYE_LON).withAltitudeMetres(1100).withEyeHeightMetres(0)
                .withRangeMetres(s).withElevationRange(new ElevationRange(-2, 1, false));
        try (PanoramaRenderer r = PanoramaRenderer.openReference(Synthetic.dem((la, lo) -> 1000, 45, 7, 3, 4))) {
            for (Refraction k : new Refraction[] {Refraction.NONE, Refraction.STANDARD}) {
                Panorama p = r.render(req.withRefraction(k));
                for (int col = 0; col < p.widthPx(); col += 149) {
                    double radius = eulerRadius(EYE_LAT, p.azimuthOfColumn(col)) + 1000;
                    double lift = k.liftMetres(s); // ground distance = s to 1e-5
                    double up = Math.sqrt(radius * radius - s * s) - (radius + 100) + lift;
                    double edgeDeg = Math.toDegrees(Math.atan2(up, s));
                    int sky = DistanceComparison.skylineRow(p.distanceArray(), p.widthPx(), p.heightPx(), col);
                    assertTrue(p.elevationOfRow(sky) <= edgeDeg + 1e-6 && p.elevationOfRow(sky - 1) > edgeDeg - 1e-6,
                            k + " azimuth " + p.azimuthOfColumn(col) + ": edge at " + edgeDeg + "°, skyline row " + sky);
                    for (int row = 0; row < p.heightPx(); row++) {
                        float d = p.distanceMetres(col, row);
                        assertTrue(Float.isInfinite(d) || d < s + 200, "nothing beyond the range: row " + row + " " + p.distanceMetres(col, row) + " sky " + sky + " col " + col);
                    }
                }
            }
        }
    }

    /**
     * The eye's foot exactly on a grid vertex, with terrain behind it higher than the eye: the plane of
     * a column then only grazes the foot's triangle, and the walk must still set off forwards (it once
     * went backwards and gave whole columns a distance of 0).
     */
    @Test
    void eyeOnAGridVertexAmongHigherTerrainSetsOffForwards() {
        // Rugged relief around the vertex at 46.5N 8.5E; the eye 30 m above it.
        DoubleBinaryOperator rugged = (lat, lon) -> {
            double y = (lat - EYE_LAT) * 111_195, x = (lon - EYE_LON) * 76_500;
            return 1200 + 700 * Math.sin(x / 3100) * Math.cos(y / 4300) + 180 * Math.sin((x + 2 * y) / 900)
                    + 60 * Math.cos((3 * x - y) / 310);
        };
        PanoramaRequest req = PanoramaRequest.at(EYE_LAT, EYE_LON).withRangeMetres(35_000).withEyeHeightMetres(30)
                .withElevationRange(new ElevationRange(-40, 15, false));
        Panorama p;
        try (PanoramaRenderer r = PanoramaRenderer.openReference(Synthetic.dem(rugged, 46, 8, 1, 1))) {
            p = r.render(req);
        }
        for (int col = 0; col < p.widthPx(); col++) {
            for (int row = 0; row < p.heightPx(); row++) {
                float d = p.distanceMetres(col, row);
                assertTrue(d >= 15, "azimuth " + p.azimuthOfColumn(col) + " row " + row + ": " + d + " m");
            }
            // No pixel nearer than the ground under the eye allows (30 m at slopes up to 60°); at −40° the
            // ground is within a few hundred metres in every direction.
            double down = p.distanceMetres(col, p.heightPx() - 1);
            assertTrue(down < 1000, "azimuth " + p.azimuthOfColumn(col) + ": " + down);
        }
    }
}
