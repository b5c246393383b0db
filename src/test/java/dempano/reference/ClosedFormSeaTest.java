package dempano.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.geo.Ellipsoid;
import dempano.geo.LocalFrame;
import dempano.panorama.DistanceComparison;
import dempano.panorama.PanoramaGeometry;
import org.junit.jupiter.api.Test;

class ClosedFormSeaTest {
    @Test
    void everyPixelMeetsTheSeaOrTheSkyAndTheHorizonIsAtTheDip() {
        double lat = 43.5, h = 100;
        LocalFrame eye = new LocalFrame(lat, 7.5, h);
        PanoramaGeometry g = PanoramaGeometry.of(4, -10, 2); // 1440 × 48 px
        ClosedFormSea sea = ClosedFormSea.of(eye, g);
        int w = g.widthPx();
        for (int row = 0; row < g.heightPx(); row++) {
            double el = Math.toRadians(g.elevationOfRow(row));
            for (int col = 0; col < w; col += 37) {
                double az = Math.toRadians(g.azimuthOfColumn(col));
                double e = Math.cos(el) * Math.sin(az), n = Math.cos(el) * Math.cos(az), u = Math.sin(el);
                float d = sea.distanceMetres()[row * w + col];
                if (Float.isFinite(d)) {
                    // On the sea (height 0 through the independent geodetic conversion); float rounding allowed.
                    assertEquals(0, eye.toGeodetic(d * e, d * n, d * u)[2], 1e-7 * d + 1e-4, "row " + row + " col " + col);
                    float inc = sea.incidenceDeg()[row * w + col];
                    assertTrue(inc > 0 && inc <= 90, "incidence " + inc);
                } else {
                    // Sky: the ray's lowest point (or its end 500 km out) stays above the sea.
                    double t = Math.min(500_000, Math.max(0, -(u) * Ellipsoid.MEAN_RADIUS_METRES));
                    assertTrue(eye.toGeodetic(t * e, t * n, t * u)[2] > 0, "row " + row + " col " + col);
                    assertTrue(Float.isNaN(sea.incidenceDeg()[row * w + col]));
                }
            }
        }
        // The horizon row brackets the dip acos(r / (r + h)), r the radius of curvature along the azimuth.
        double s = Math.sin(Math.toRadians(lat));
        double nRad = Ellipsoid.primeVerticalRadiusMetres(lat);
        double mRad = Ellipsoid.A_METRES * (1 - Ellipsoid.E2) / Math.pow(1 - Ellipsoid.E2 * s * s, 1.5);
        for (int col = 0; col < w; col += 90) {
            double az = Math.toRadians(g.azimuthOfColumn(col));
            double r = 1 / (Math.cos(az) * Math.cos(az) / mRad + Math.sin(az) * Math.sin(az) / nRad);
            double dipDeg = Math.toDegrees(Math.acos(r / (r + h)));
            int sky = DistanceComparison.skylineRow(sea.distanceMetres(), w, g.heightPx(), col);
            assertTrue(g.elevationOfRow(sky) <= -dipDeg && g.elevationOfRow(sky - 1) > -dipDeg, "dip at column " + col);
        }
    }
}
