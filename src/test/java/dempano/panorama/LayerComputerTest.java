package dempano.panorama;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.Synthetic;
import dempano.dem.MissingTilePolicy;
import dempano.dem.Mosaic;
import dempano.geo.Ellipsoid;
import dempano.geo.Geodesy;
import dempano.geo.LocalFrame;
import dempano.geo.Refraction;
import java.util.Arrays;
import java.util.EnumSet;
import java.util.Map;
import java.util.function.DoubleBinaryOperator;
import org.junit.jupiter.api.Test;

/**
 * Incidence and uncertainty layers against independent truth: exact ray–ellipsoid intersection for
 * sea level, and surface normals by finite differences of the analytic terrain in ECEF (curvature
 * and, where asked, the refraction lift included) at the hit points of a double-precision ray march.
 */
class LayerComputerTest {
    private static final double LAT = 46, LON = 8;
    private static final double PPD = 2;
    private static final EnumSet<Layer> BOTH = EnumSet.of(Layer.INCIDENCE, Layer.UNCERTAINTY);

    /** Pixels filled with a truth distance; every other pixel is sky (+∞). */
    private record Case(PanoramaGeometry g, float[] distance, double[] trueIncidenceDeg, int[] pixels) {
    }

    private static PanoramaGeometry geometry() {
        return PanoramaGeometry.of(PPD, -90, 5);
    }

    private static double[] rayEcef(LocalFrame eye, double azDeg, double elDeg) {
        double az = Math.toRadians(azDeg), el = Math.toRadians(elDeg);
        double[] a = new double[3], b = new double[3];
        eye.enuToEcef(0, 0, 0, a);
        eye.enuToEcef(Math.cos(el) * Math.sin(az), Math.cos(el) * Math.cos(az), Math.sin(el), b);
        return new double[] {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    private static double angleToPlaneDeg(double[] ray, double[] normal) {
        double s = Math.abs(dot(ray, normal)) / Math.sqrt(dot(ray, ray) * dot(normal, normal));
        return Math.toDegrees(Math.asin(s));
    }

    /** Normal of the surface height = f(lat, lon) in ECEF, by central differences (±1e-4°). */
    private static double[] fdNormal(DoubleBinaryOperator f, double lat, double lon) {
        double e = 1e-4;
        double[] pn = new double[3], ps = new double[3], pe = new double[3], pw = new double[3];
        Ellipsoid.toEcef(lat + e, lon, f.applyAsDouble(lat + e, lon), pn);
        Ellipsoid.toEcef(lat - e, lon, f.applyAsDouble(lat - e, lon), ps);
        Ellipsoid.toEcef(lat, lon + e, f.applyAsDouble(lat, lon + e), pe);
        Ellipsoid.toEcef(lat, lon - e, f.applyAsDouble(lat, lon - e), pw);
        double[] a = {pn[0] - ps[0], pn[1] - ps[1], pn[2] - ps[2]}, b = {pe[0] - pw[0], pe[1] - pw[1], pe[2] - pw[2]};
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    /** Exact distance along a ray from the eye to the WGS84 ellipsoid (sea level); +∞ if it misses. */
    private static double rayEllipsoid(LocalFrame eye, double[] ray) {
        double[] p = new double[3];
        eye.enuToEcef(0, 0, 0, p);
        double a2 = Ellipsoid.A_METRES * Ellipsoid.A_METRES, b2 = Ellipsoid.B_METRES * Ellipsoid.B_METRES;
        double qa = (ray[0] * ray[0] + ray[1] * ray[1]) / a2 + ray[2] * ray[2] / b2;
        double qb = 2 * ((p[0] * ray[0] + p[1] * ray[1]) / a2 + p[2] * ray[2] / b2);
        double qc = (p[0] * p[0] + p[1] * p[1]) / a2 + p[2] * p[2] / b2 - 1;
        double disc = qb * qb - 4 * qa * qc;
        if (disc < 0) {
            return Double.POSITIVE_INFINITY;
        }
        double t = (-qb - Math.sqrt(disc)) / (2 * qa);
        return t > 0 ? t : Double.POSITIVE_INFINITY;
    }

    private static Map<Layer, float[]> layers(Case c, LocalFrame eye, Refraction k, Mosaic m) {
        return LayerComputer.compute(BOTH, c.g, c.distance, eye, k, m);
    }

    private static void checkAgainstTruth(Case c, Map<Layer, float[]> out, double toleranceDeg) {
        float[] inc = out.get(Layer.INCIDENCE), unc = out.get(Layer.UNCERTAINTY);
        for (int j = 0; j < c.pixels.length; j++) {
            int i = c.pixels[j];
            double truth = c.trueIncidenceDeg[j];
            assertEquals(truth, inc[i], toleranceDeg, "incidence of pixel " + i + " at " + c.distance[i] + " m");
            double expected = Math.min(10 / Math.sin(Math.toRadians(truth)), c.distance[i]);
            assertEquals(expected, unc[i], expected * 2e-3, "uncertainty of pixel " + i);
        }
        boolean[] filled = new boolean[c.distance.length];
        for (int i : c.pixels) {
            filled[i] = true;
        }
        for (int i = 0; i < filled.length; i++) {
            if (!filled[i]) {
                assertTrue(Float.isNaN(inc[i]) && Float.isNaN(unc[i]), "sky pixel " + i + " not NaN");
            }
        }
    }

    @Test
    void seaLevelWithEarthCurvatureMatchesExactRayEllipsoid() {
        // Eye 1000 m over a sea-level DEM, no refraction. Truth: exact ray–ellipsoid hit and the
        // ellipsoid normal (x/a², y/a², z/b²) there. On a sphere the angle is δ − d/R, not the
        // flat-earth δ: 0.18° less at 20 km, 0.4° at 44 km.
        DoubleBinaryOperator sea = (la, lo) -> 0;
        Mosaic m = Mosaic.around(Synthetic.dem(sea, 45, 7, 2, 2), LAT, LON, 60_000, MissingTilePolicy.ERROR);
        LocalFrame eye = new LocalFrame(LAT, LON, 1000);
        PanoramaGeometry g = geometry();
        float[] distance = new float[g.widthPx() * g.heightPx()];
        Arrays.fill(distance, Float.POSITIVE_INFINITY);
        int[] cols = {0, 75, 180, 401, 650};
        int[] rows = {g.heightPx() - 1, (int) Math.round(g.rowOf(-45)), (int) Math.round(g.rowOf(-10)),
                (int) Math.round(g.rowOf(-3)), (int) Math.round(g.rowOf(-2)), (int) Math.round(g.rowOf(-1.5)),
                (int) Math.round(g.rowOf(0))};
        int n = 0;
        int[] pixels = new int[cols.length * rows.length];
        double[] truth = new double[pixels.length];
        int curved = 0;
        for (int row : rows) {
            for (int col : cols) {
                double az = g.azimuthOfColumn(col), el = g.elevationOfRow(row);
                double[] ray = rayEcef(eye, az, el);
                double d = rayEllipsoid(eye, ray);
                if (!Double.isFinite(d)) {
                    continue; // above the horizon: sky
                }
                double[] p = new double[3];
                eye.enuToEcef(0, 0, 0, p);
                double a2 = Ellipsoid.A_METRES * Ellipsoid.A_METRES, b2 = Ellipsoid.B_METRES * Ellipsoid.B_METRES;
                double[] normal = {(p[0] + d * ray[0]) / a2, (p[1] + d * ray[1]) / a2, (p[2] + d * ray[2]) / b2};
                distance[row * g.widthPx() + col] = (float) d;
                pixels[n] = row * g.widthPx() + col;
                truth[n] = angleToPlaneDeg(ray, normal);
                if (d > 19_000) {
                    assertTrue(Math.abs(-el - truth[n]) > 0.1, "curvature should matter at " + d + " m");
                    curved++;
                }
                n++;
            }
        }
        assertEquals(30, n, "pixels on the sea");
        assertEquals(10, curved, "pixels beyond 19 km");
        Case c = new Case(g, distance, Arrays.copyOf(truth, n), Arrays.copyOf(pixels, n));
        checkAgainstTruth(c, layers(c, eye, Refraction.NONE, m), 0.002);
        // Straight down: 90°; uncertainty 10 m.
        int down = (g.heightPx() - 1) * g.widthPx();
        float[] inc = layers(c, eye, Refraction.NONE, m).get(Layer.INCIDENCE);
        assertEquals(90 - Math.abs(-90 - g.elevationOfRow(g.heightPx() - 1)), inc[down], 0.01);
    }

    @Test
    void refractionLiftTiltsTheSurfaceSeen() {
        // k = 0.13: the renderer draws a straight ray against sea lifted by k·s²/(2R). Truth: ray march
        // against that lifted surface (s geodesic), normal by finite differences; the lift's slope
        // k·s/R is 0.02–0.05° here, well above the tolerance.
        Refraction k = Refraction.STANDARD;
        DoubleBinaryOperator lifted = (la, lo) -> k.liftMetres(Geodesy.distanceMetres(LAT, LON, la, lo));
        Mosaic m = Mosaic.around(Synthetic.dem((la, lo) -> 0, 45, 7, 2, 2), LAT, LON, 60_000, MissingTilePolicy.ERROR);
        LocalFrame eye = new LocalFrame(LAT, LON, 1000);
        PanoramaGeometry g = geometry();
        float[] distance = new float[g.widthPx() * g.heightPx()];
        Arrays.fill(distance, Float.POSITIVE_INFINITY);
        double[] els = {-1.5, -2, -3};
        int[] cols = {30, 333};
        int[] pixels = new int[els.length * cols.length];
        double[] truth = new double[pixels.length];
        int n = 0;
        for (double elDeg : els) {
            int row = (int) Math.round(g.rowOf(elDeg));
            for (int col : cols) {
                double az = g.azimuthOfColumn(col), el = g.elevationOfRow(row);
                double d = Synthetic.rayMarch(eye, lifted, az, el, 60_000);
                assertTrue(d > 15_000 && d < 60_000, "hit at " + d);
                double[] ray = rayEcef(eye, az, el);
                double[] geo = eye.toGeodetic(d * Math.cos(Math.toRadians(el)) * Math.sin(Math.toRadians(az)),
                        d * Math.cos(Math.toRadians(el)) * Math.cos(Math.toRadians(az)), d * Math.sin(Math.toRadians(el)));
                truth[n] = angleToPlaneDeg(ray, fdNormal(lifted, geo[0], geo[1]));
                double unlifted = angleToPlaneDeg(ray, fdNormal((la, lo) -> 0, geo[0], geo[1]));
                assertTrue(Math.abs(truth[n] - unlifted) > 0.02, "lift slope matters: " + truth[n] + " vs " + unlifted);
                distance[row * g.widthPx() + col] = (float) d;
                pixels[n++] = row * g.widthPx() + col;
            }
        }
        checkAgainstTruth(new Case(g, distance, truth, pixels), layers(new Case(g, distance, truth, pixels), eye, k, m),
                0.002);
    }

    @Test
    void tiltedPlaneFromManyDirections() {
        // A plane in (lat, lon), drawn exactly by the DEM's triangles: rising 0.3 m/m eastward and
        // 0.2 m/m southward at the eye. Eye 200 m above it. Truth: ray march, finite-difference normal;
        // sanity: the flat-earth closed form asin(|r·n|) with n = (−0.3, 0.2, 1) within 0.05° near the eye.
        double sE = 0.3, sN = -0.2;
        double metresPerDegLon = Math.toRadians(1) * Ellipsoid.primeVerticalRadiusMetres(LAT) * Math.cos(Math.toRadians(LAT));
        double p = Math.sin(Math.toRadians(LAT)), w2 = 1 - Ellipsoid.E2 * p * p;
        double metresPerDegLat = Math.toRadians(1) * Ellipsoid.A_METRES * (1 - Ellipsoid.E2) / (w2 * Math.sqrt(w2));
        DoubleBinaryOperator plane = (la, lo) -> 500 + sE * (lo - LON) * metresPerDegLon + sN * (la - LAT) * metresPerDegLat;
        Mosaic m = Mosaic.around(Synthetic.dem(plane, 45, 7, 2, 2), LAT, LON, 20_000, MissingTilePolicy.ERROR);
        LocalFrame eye = new LocalFrame(LAT, LON, 700);
        PanoramaGeometry g = geometry();
        float[] distance = new float[g.widthPx() * g.heightPx()];
        Arrays.fill(distance, Float.POSITIVE_INFINITY);
        double[] azs = {0, 45, 90, 135, 180, 225, 270, 315};
        double[] els = {-2, -5, -10, -20, -40, -70};
        int[] pixels = new int[azs.length * els.length];
        double[] truth = new double[pixels.length];
        int n = 0, closeForm = 0;
        double[] flatNormal = {-sE, -sN, 1};
        for (double azDeg : azs) {
            for (double elDeg : els) {
                int row = (int) Math.round(g.rowOf(elDeg)), col = (int) Math.round(g.columnOf(azDeg));
                double az = g.azimuthOfColumn(col), el = g.elevationOfRow(row);
                double d = Synthetic.rayMarch(eye, plane, az, el, 15_000);
                if (!Double.isFinite(d)) {
                    continue; // downhill and shallow: misses the plane within the mosaic
                }
                double[] ray = rayEcef(eye, az, el);
                double[] geo = eye.toGeodetic(d * Math.cos(Math.toRadians(el)) * Math.sin(Math.toRadians(az)),
                        d * Math.cos(Math.toRadians(el)) * Math.cos(Math.toRadians(az)), d * Math.sin(Math.toRadians(el)));
                truth[n] = angleToPlaneDeg(ray, fdNormal(plane, geo[0], geo[1]));
                if (d < 3000) {
                    double[] enuRay = {Math.cos(Math.toRadians(el)) * Math.sin(Math.toRadians(az)),
                            Math.cos(Math.toRadians(el)) * Math.cos(Math.toRadians(az)), Math.sin(Math.toRadians(el))};
                    assertEquals(angleToPlaneDeg(enuRay, flatNormal), truth[n], 0.05, "closed form at " + d + " m");
                    closeForm++;
                }
                distance[row * g.widthPx() + col] = (float) d;
                pixels[n++] = row * g.widthPx() + col;
            }
        }
        assertTrue(n >= 35, "hits: " + n);
        assertTrue(closeForm >= 30, "near hits: " + closeForm);
        Case c = new Case(g, distance, Arrays.copyOf(truth, n), Arrays.copyOf(pixels, n));
        checkAgainstTruth(c, layers(c, eye, Refraction.NONE, m), 0.01);
    }


    @Test
    void normalIsTheDrawnTriangles() {
        // Rough terrain: each cell's two triangles differ. Truth: the normal of the triangle holding the
        // point from its three vertices in ECEF (split per Triangulation), rays from several directions.
        DoubleBinaryOperator rough = (la, lo) -> 800 + 300 * Math.sin(la * 917) * Math.cos(lo * 613) + 40 * Math.sin(lo * 5000);
        Mosaic m = Mosaic.around(Synthetic.dem(rough, 45, 7, 2, 2), LAT, LON, 20_000, MissingTilePolicy.ERROR);
        int r = (int) Math.floor(m.rowOf(LAT + 0.013)), checked = 0, differ = 0;
        for (int c0 = (int) Math.floor(m.colOf(LON + 0.021)), c = c0; c < c0 + 2; c++) {
            for (double[] uv : new double[][] {{0.7, 0.2}, {0.2, 0.7}, {0.15, 0.3}, {0.8, 0.9}}) {
                double lat = m.latOfRow(r + uv[1]), lon = m.lonOfCol(c + uv[0]);
                boolean nwSe = dempano.dem.Triangulation.splitsNorthWestToSouthEast(r, c);
                int[][] tri = nwSe ? (uv[0] >= uv[1] ? new int[][] {{0, 0}, {0, 1}, {1, 1}} : new int[][] {{0, 0}, {1, 1}, {1, 0}})
                        : (uv[0] + uv[1] <= 1 ? new int[][] {{0, 0}, {0, 1}, {1, 0}} : new int[][] {{0, 1}, {1, 1}, {1, 0}});
                double[][] v = new double[3][3];
                for (int k = 0; k < 3; k++) {
                    int rr = r + tri[k][0], cc = c + tri[k][1];
                    Ellipsoid.toEcef(m.latOfRow(rr), m.lonOfCol(cc), m.sample(rr, cc), v[k]);
                }
                double[] a = {v[1][0] - v[0][0], v[1][1] - v[0][1], v[1][2] - v[0][2]};
                double[] b = {v[2][0] - v[0][0], v[2][1] - v[0][1], v[2][2] - v[0][2]};
                double[] normal = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
                LocalFrame at = new LocalFrame(lat, lon, 0);
                for (double[] azEl : new double[][] {{10, -5}, {100, -30}, {200, -1}, {290, -60}}) {
                    double[] ray = rayEcef(at, azEl[0], azEl[1]);
                    double truth = angleToPlaneDeg(ray, normal);
                    double got = LayerComputer.incidenceDeg(m, lat, lon, ray, 0);
                    assertEquals(truth, got, 0.01, "cell " + r + "," + c + " at " + Arrays.toString(uv) + " ray " + Arrays.toString(azEl));
                    if (Math.abs(truth - angleToPlaneDeg(ray, fdNormal(rough, lat, lon))) > 1) {
                        differ++; // the triangle is not the smooth analytic surface: this test sees the split
                    }
                    checked++;
                }
            }
        }
        assertEquals(32, checked);
        assertTrue(differ >= 8, "cases where the triangle differs from the smooth surface: " + differ);
    }

    @Test
    void uncertaintyFormulaAndCap() {
        assertEquals(10, LayerComputer.uncertaintyMetres(90, 5000), 1e-9);
        assertEquals(20, LayerComputer.uncertaintyMetres(30, 5000), 1e-9);
        assertEquals(10 / Math.sin(Math.toRadians(0.5)), LayerComputer.uncertaintyMetres(0.5, 5000), 1e-6);
        assertEquals(300, LayerComputer.uncertaintyMetres(1, 300), 0); // capped at the distance
        assertEquals(40_000, LayerComputer.uncertaintyMetres(0, 40_000), 0);
        assertTrue(Double.isNaN(LayerComputer.uncertaintyMetres(Double.NaN, 40_000)));
    }

    @Test
    void namesAndMosaicRequired() {
        assertEquals(Layer.INCIDENCE, Layer.fromName("incidence"));
        assertEquals(Layer.UNCERTAINTY, Layer.fromName("UNCERTAINTY"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> Layer.fromName("slope")).getMessage()
                .contains("incidence, uncertainty"));
        PanoramaGeometry g = geometry();
        float[] sky = new float[g.widthPx() * g.heightPx()];
        assertThrows(IllegalArgumentException.class, () -> LayerComputer.compute(BOTH, g, sky,
                new LocalFrame(LAT, LON, 0), Refraction.NONE, null));
    }
}
