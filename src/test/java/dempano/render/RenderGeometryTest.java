package dempano.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.dem.HgtTile;
import dempano.dem.InMemoryDem;
import dempano.dem.TileId;
import dempano.geo.Ellipsoid;
import dempano.geo.Geodesy;
import dempano.geo.LocalFrame;
import dempano.geo.Refraction;
import dempano.panorama.DepthMode;
import dempano.panorama.ElevationRange;
import dempano.panorama.Panorama;
import java.util.ArrayList;
import java.util.List;
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
    static final int N = 601; // 6" synthetic tiles
    static final double EYE_LAT = 46.5, EYE_LON = 8.5, HILL_LAT = 46.62, HILL_LON = 8.68;
    static final double BASE = 500, HILL = 1500, SIGMA_M = 3000;
    static final DoubleBinaryOperator TERRAIN = (lat, lon) -> {
        double dy = (lat - HILL_LAT) * 111_195, dx = (lon - HILL_LON) * 111_195 * Math.cos(Math.toRadians(HILL_LAT));
        return BASE + HILL * Math.exp(-(dx * dx + dy * dy) / (2 * SIGMA_M * SIGMA_M));
    };
    static PanoramaRenderer hillRenderer, seaRenderer;

    static InMemoryDem dem(DoubleBinaryOperator f, int latS, int lonW, int rows, int cols) {
        List<HgtTile> tiles = new ArrayList<>();
        for (int i = 0; i < rows; i++) {
            for (int j = 0; j < cols; j++) {
                float[] h = new float[N * N];
                for (int r = 0; r < N; r++) {
                    for (int c = 0; c < N; c++) {
                        h[r * N + c] = (float) f.applyAsDouble(latS + i + 1 - r / (N - 1.0), lonW + j + c / (N - 1.0));
                    }
                }
                tiles.add(HgtTile.of(TileId.of(latS + i, lonW + j), N, h, "synthetic"));
            }
        }
        return new InMemoryDem("synthetic", tiles);
    }

    @BeforeAll
    static void open() {
        hillRenderer = PanoramaRenderer.open(dem(TERRAIN, 45, 7, 3, 3));
    }

    @AfterAll
    static void close() {
        hillRenderer.close();
    }

    static PanoramaRequest hillRequest(DepthMode mode) {
        return PanoramaRequest.at(EYE_LAT, EYE_LON).withRangeMetres(40_000).withRefraction(Refraction.NONE)
                .withElevationRange(new ElevationRange(-10, 10, false)).withDepthMode(mode);
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
            if (Double.isFinite(RayMarch.distance(eye, TERRAIN, colAz, mid, 40_000))) {
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
                double truth = RayMarch.distance(eye, TERRAIN, p.azimuthOfColumn(col), p.elevationOfRow(r), 45_000);
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

    /** Independent truth: march a ray in double precision through the analytic terrain, then bisect. */
    static final class RayMarch {
        static double distance(LocalFrame eye, DoubleBinaryOperator terrain, double azDeg, double elDeg, double max) {
            double az = Math.toRadians(azDeg), el = Math.toRadians(elDeg);
            double de = Math.cos(el) * Math.sin(az), dn = Math.cos(el) * Math.cos(az), du = Math.sin(el);
            double step = 5, prev = 0;
            for (double t = step; t <= max; t += step) {
                if (below(eye, terrain, de * t, dn * t, du * t)) {
                    double lo = prev, hi = t;
                    for (int i = 0; i < 60; i++) {
                        double mid = (lo + hi) / 2;
                        if (below(eye, terrain, de * mid, dn * mid, du * mid)) {
                            hi = mid;
                        } else {
                            lo = mid;
                        }
                    }
                    return (lo + hi) / 2;
                }
                prev = t;
            }
            return Double.POSITIVE_INFINITY;
        }

        private static boolean below(LocalFrame eye, DoubleBinaryOperator terrain, double e, double n, double u) {
            double[] g = eye.toGeodetic(e, n, u);
            return g[2] <= terrain.applyAsDouble(g[0], g[1]);
        }
    }
}
