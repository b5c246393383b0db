package dempano.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.Synthetic;
import dempano.dem.InMemoryDem;
import dempano.geo.Ellipsoid;
import dempano.geo.Geodesy;
import dempano.geo.LocalFrame;
import dempano.geo.Refraction;
import dempano.panorama.DepthMode;
import dempano.panorama.DistanceComparison;
import dempano.panorama.ElevationRange;
import dempano.panorama.Panorama;
import java.util.function.DoubleBinaryOperator;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * End-to-end geometry on llvmpipe against independent truth: GeographicLib azimuths, the textbook
 * horizon dip, and a double-precision ray march through the analytic terrain.
 */
class RenderGeometryTest {
        static final double EYE_LAT = 46.5, EYE_LON = 8.5, HILL_LAT = 46.62, HILL_LON = 8.68;
    static final double BASE = 500, HILL = 1500, SIGMA_M = 3000;
    static final DoubleBinaryOperator TERRAIN = (lat, lon) -> {
        double dy = (lat - HILL_LAT) * 111_195, dx = (lon - HILL_LON) * 111_195 * Math.cos(Math.toRadians(HILL_LAT));
        return BASE + HILL * Math.exp(-(dx * dx + dy * dy) / (2 * SIGMA_M * SIGMA_M));
    };
    static PanoramaRenderer hillRenderer;
    static InMemoryDem hillDem;

    static InMemoryDem dem(DoubleBinaryOperator f, int latS, int lonW, int rows, int cols) {
        return Synthetic.dem(f, latS, lonW, rows, cols);
    }

    @BeforeAll
    static void open() {
        hillDem = dem(TERRAIN, 45, 7, 3, 3);
        hillRenderer = PanoramaRenderer.open(hillDem);
    }

    @AfterAll
    static void close() {
        hillRenderer.close();
    }

    static PanoramaRequest hillRequest(DepthMode mode) {
        return PanoramaRequest.at(EYE_LAT, EYE_LON).withRangeMetres(40_000).withRefraction(Refraction.NONE)
                .withElevationRange(new ElevationRange(-10, 10, false)).withDepthMode(mode)
                .withLodErrorPx(0); // the geometry at full resolution; LevelOfDetailRenderTest bounds what LOD adds
    }

    /** Skyline: elevation (deg) of the top edge of the first terrain row in a column, or NaN. */
    static int skylineRow(Panorama p, int col) {
        for (int r = 0; r < p.heightPx(); r++) {
            if (Float.isFinite(p.distanceMetres(col, r))) {
                return r;
            }
        }
        return -1;
    }

    @Test
    void hillSummitAtTheGeodesicAzimuthAndTrueElevation() {
        Panorama p = hillRenderer.render(hillRequest(DepthMode.SHADER_RANGE));
        double az = Geodesy.azimuthDeg(EYE_LAT, EYE_LON, HILL_LAT, HILL_LON);
        LocalFrame eye = new LocalFrame(EYE_LAT, EYE_LON, p.metadata().eyeAltitudeMetres());
        double[] enu = new double[3];
        eye.toEnu(HILL_LAT, HILL_LON, BASE + HILL, enu);
        double summitEl = Math.toDegrees(Math.atan2(enu[2], Math.hypot(enu[0], enu[1])));
        // Azimuth: the skyline of a symmetric hill is symmetric about the summit: its centroid.
        int c0 = (int) Math.floor(p.geometry().columnOf(az));
        double baseline = p.elevationOfRow(skylineRow(p, c0 - 200));
        double sumW = 0, sumWC = 0;
        for (int c = c0 - 150; c <= c0 + 150; c++) {
            double excess = p.geometry().topElevationDeg() - skylineRow(p, c) / p.geometry().pixelsPerDegree() - baseline;
            if (excess > 0) {
                sumW += excess;
                sumWC += excess * (c + 0.5);
            }
        }
        double centroidCol = sumWC / sumW;
        assertEquals(p.geometry().columnOf(az), centroidCol, 0.25, "summit azimuth within a quarter pixel");
        // Elevation: the apparent top of a hill is not its summit (a nearer point of the flank rises
        // higher in the view); the truth is the highest elevation whose ray still meets the analytic
        // terrain, found by bisection with the ray march. A one-sample-per-pixel raster brackets it to
        // half a pixel, plus half a view pixel of nearest-sample resampling.
        int col = c0;
        double lo = summitEl - 1, hi = summitEl + 1;
        double colAz = p.azimuthOfColumn(col);
        for (int i = 0; i < 30; i++) {
            double mid = (lo + hi) / 2;
            if (Double.isFinite(Synthetic.rayMarch(eye, TERRAIN, colAz, mid, 40_000))) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        double skylineRowTruth = p.geometry().rowOf(lo);
        assertEquals(skylineRowTruth, skylineRow(p, col), 1.0, "skyline at " + lo + "° in the summit's column");
    }

    @ParameterizedTest
    @EnumSource(value = DepthMode.class, names = {"SHADER_RANGE", "REVERSED_32F"})
    void distancesMatchARayMarchThroughTheAnalyticTerrain(DepthMode mode) {
        Panorama p = hillRenderer.render(hillRequest(mode));
        LocalFrame eye = new LocalFrame(EYE_LAT, EYE_LON, p.metadata().eyeAltitudeMetres());
        double az = Geodesy.azimuthDeg(EYE_LAT, EYE_LON, HILL_LAT, HILL_LON);
        int c0 = (int) Math.floor(p.geometry().columnOf(az));
        int checked = 0;
        for (int dc = -60; dc <= 60; dc += 20) {
            int col = c0 + dc;
            int top = skylineRow(p, col);
            for (int r = top + 3; r < p.heightPx(); r += 37) {
                double got = p.distanceMetres(col, r);
                double truth = Synthetic.rayMarch(eye, TERRAIN, p.azimuthOfColumn(col), p.elevationOfRow(r), 45_000);
                if (!Double.isFinite(truth) || truth > 39_000) {
                    continue;
                }
                assertEquals(truth, got, truth * 1e-3, "col " + col + " row " + r);
                checked++;
            }
        }
        assertTrue(checked > 20, "checked " + checked + " pixels");
    }

    @Test
    void flatSeaHorizonDipsByTheTextbookAngle() {
        double h = 300;
        try (PanoramaRenderer sea = PanoramaRenderer.open(dem((la, lo) -> 0, 45, 7, 3, 4))) {
            Panorama p = sea.render(PanoramaRequest.at(EYE_LAT, EYE_LON).withAltitudeMetres(h).withEyeHeightMetres(0)
                    .withRangeMetres(90_000).withRefraction(Refraction.NONE).withElevationRange(new ElevationRange(-3, 1, false)));
            for (int col = 0; col < p.widthPx(); col += 97) {
                double az = Math.toRadians(p.azimuthOfColumn(col));
                // Radius of curvature of the ellipsoid in this azimuth (Euler), and the dip arccos(R/(R+h)).
                double phi = Math.toRadians(EYE_LAT), s = Math.sin(phi);
                double nRad = Ellipsoid.primeVerticalRadiusMetres(EYE_LAT);
                double mRad = Ellipsoid.A_METRES * (1 - Ellipsoid.E2) / Math.pow(1 - Ellipsoid.E2 * s * s, 1.5);
                double r = 1 / (Math.cos(az) * Math.cos(az) / mRad + Math.sin(az) * Math.sin(az) / nRad);
                double dip = Math.toDegrees(Math.acos(r / (r + h)));
                // Terrain is drawn where a pixel centre lies below the horizon: half a pixel of bracket,
                // plus at most half a view pixel of nearest-sample resampling at supersampling 1.
                assertEquals(p.geometry().rowOf(-dip), skylineRow(p, col), 1.0, "azimuth " + p.azimuthOfColumn(col));
            }
        }
    }

    @Test
    void skyIsInfiniteAndMetadataHoldsTheViewpoint() {
        Panorama p = hillRenderer.render(hillRequest(DepthMode.SHADER_RANGE));
        assertTrue(Float.isInfinite(p.distanceMetres(0, 0)));
        assertEquals(BASE + 2, p.metadata().eyeAltitudeMetres(), 1.0);
        assertEquals(Double.POSITIVE_INFINITY, p.distanceAt(10, 9.9));
    }

    /** The GL path against the CPU reference on the same surface, every pixel of a 360° panorama. */
    @ParameterizedTest
    @EnumSource(value = DepthMode.class, names = {"SHADER_RANGE", "REVERSED_32F"})
    void everyPixelMatchesTheCpuReference(DepthMode mode) {
        PanoramaRequest req = hillRequest(mode).withRefraction(Refraction.STANDARD);
        Panorama gl = hillRenderer.render(req);
        Panorama ref;
        try (PanoramaRenderer cpu = PanoramaRenderer.openReference(hillDem)) {
            ref = cpu.render(req);
        }
        DistanceComparison c = DistanceComparison.of(gl.distanceArray(), ref.distanceArray(), gl.widthPx());
        // Bounds: float vertices (relative 1e-7) give ~1e-7 in the median. This scene is a plain seen
        // from 2 m: the rows just under each column's skyline look at the plain so obliquely that a
        // shift of a fraction of a pixel moves the point seen by kilometres, and the GL samples lie up to
        // half a view pixel from the panorama's pixel centres: that is the tail (about one pixel a column).
        assertTrue(c.medianRelative() < 1e-5, "median " + c);
        assertTrue(c.p95Relative() < 1e-3, "p95 " + c);
        assertTrue(c.p99Relative() < 0.05, "p99 " + c);
        assertTrue(c.shareOver5Percent() < 0.01, "over 5 % " + c);
        assertTrue(c.skylineMeanAbsPx() < 0.5, "skyline " + c);
        assertTrue(c.skylineMaxAbsPx() <= 1, "skyline " + c);
    }
}
