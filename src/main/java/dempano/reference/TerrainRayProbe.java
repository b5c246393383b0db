package dempano.reference;

import dempano.dem.Mosaic;
import dempano.geo.Ellipsoid;
import dempano.geo.LocalFrame;
import dempano.geo.Refraction;
import dempano.geo.Viewpoint;
import dempano.panorama.RayProbe;
import dempano.terrain.LevelOfDetail;
import dempano.terrain.Triangulation;

/**
 * A ray's first crossing with the full-resolution triangulated surface (the surface the CPU
 * reference draws: mosaic cells split by {@link Triangulation}, NaN samples at sea level, refraction
 * lift k·d²/2R, cut at the range of sight), found by search: outward in steps of
 * {@link #STEP_RATIO} until the ray is below the surface, then regula falsi (Illinois) to
 * {@link #TOLERANCE} (relative). A crest rising above the ray for less than one step can be stepped
 * over; fine probes cap the step at one DEM cell, so that the ray must cross a crest over less than a cell to miss it. Stateless after construction: thread-safe.
 */
public final class TerrainRayProbe implements RayProbe {
    /** Outward steps multiply the distance by this. */
    static final double STEP_RATIO = 1.1;
    /** Bisection stops when the bracket is this narrow, relative to the distance. */
    static final double TOLERANCE = 1e-9;
    /** e'² = (a² − b²) / b². */
    private static final double SECOND_ECCENTRICITY_SQ = Ellipsoid.E2 / ((1 - Ellipsoid.F) * (1 - Ellipsoid.F));

    private final Mosaic mosaic;
    private final LocalFrame frame;
    private final Refraction refraction;
    private final double rangeMetres;
    private final double[] eyeFoot = new double[3];
    /** Fine steps' horizontal length: one of the mosaic's cells, the narrower (east–west) way. */
    private final double fineStepMetres;

    public TerrainRayProbe(Mosaic mosaic, Viewpoint eye, Refraction refraction, double rangeMetres) {
        this.mosaic = mosaic;
        this.frame = eye.eyeFrame();
        this.refraction = refraction;
        this.rangeMetres = rangeMetres;
        Ellipsoid.toEcef(eye.latDeg(), eye.lonDeg(), 0, eyeFoot);
        double cellMetres = Math.PI / 180 * Ellipsoid.A_METRES / mosaic.intervalsPerDegree();
        this.fineStepMetres = cellMetres * Math.max(0.05, Math.cos(Math.toRadians(eye.latDeg())));
    }

    @Override
    public double firstHitMetres(double dx, double dy, double dz, double fromMetres, double toMetres, boolean fine) {
        double e = dx, n = -dz, u = dy; // jME axes (east, up, south) to ENU
        double horizontal = Math.hypot(e, n), horizontalShare = Math.max(horizontal, 0.01);
        double tMax = Math.min(toMetres, horizontal > 0 ? rangeMetres / horizontal : Double.POSITIVE_INFINITY);
        double a = Math.max(1e-3, Math.min(fromMetres, tMax));
        double ca = clearance(e, n, u, a);
        while (a > 1e-3 && !(ca > 0)) {
            a /= 4; // not above there: back toward the eye, which is above the terrain
            ca = clearance(e, n, u, a);
        }
        if (!(ca > 0)) {
            return Double.NaN;
        }
        double b = a, cb;
        while (true) {
            b = Math.min(fine ? Math.min(b * STEP_RATIO, b + fineStepMetres / horizontalShare) : b * STEP_RATIO, tMax);
            cb = clearance(e, n, u, b);
            if (Double.isNaN(cb)) {
                return Double.POSITIVE_INFINITY; // off the mosaic: nothing drawn there
            }
            if (cb <= 0) {
                break;
            }
            if (b >= tMax) {
                return b >= rangeMetres / Math.max(horizontal, 1e-300) ? Double.POSITIVE_INFINITY : Double.NaN;
            }
            a = b;
            ca = cb;
        }
        // Illinois regula falsi: the clearance is close to linear along the ray within a triangle.
        int side = 0;
        for (int i = 0; i < 100 && b - a > TOLERANCE * b; i++) {
            double m = Math.max(a, Math.min(b, (a * cb - b * ca) / (cb - ca)));
            double cm = clearance(e, n, u, m);
            if (Double.isNaN(cm) || cm == 0) {
                return m;
            }
            if (cm > 0) {
                a = m;
                ca = cm;
                if (side == 1) {
                    cb /= 2;
                }
                side = 1;
            } else {
                b = m;
                cb = cm;
                if (side == -1) {
                    ca /= 2;
                }
                side = -1;
            }
        }
        return 0.5 * (a + b);
    }

    /** Height of the ray's point at distance t above the (lifted) surface, metres; NaN off the mosaic. */
    double clearance(double e, double n, double u, double t) {
        double[] ecef = new double[3];
        frame.enuToEcef(t * e, t * n, t * u, ecef);
        double x = ecef[0], y = ecef[1], z = ecef[2];
        double p = Math.sqrt(x * x + y * y);
        if (p < 1e3) {
            return clearanceNearPole(x, y, z);
        }
        // Bowring's closed form (one step from the parametric latitude): under 1e-7 m in height
        // and 1e-12 rad in latitude for terrestrial heights (TerrainRayProbeTest), and trig-free
        // but for two atan2, which matters here: the probe runs a dozen of these per probed pixel.
        double za = z * Ellipsoid.A_METRES, pb = p * Ellipsoid.B_METRES, q = Math.sqrt(za * za + pb * pb);
        double st = za / q, ct = pb / q;
        double num = z + SECOND_ECCENTRICITY_SQ * Ellipsoid.B_METRES * st * st * st;
        double den = p - Ellipsoid.E2 * Ellipsoid.A_METRES * ct * ct * ct;
        double r = Math.sqrt(num * num + den * den), sinLat = num / r, cosLat = den / r;
        double nRadius = Ellipsoid.A_METRES / Math.sqrt(1 - Ellipsoid.E2 * sinLat * sinLat);
        double height = p * cosLat + z * sinLat - Ellipsoid.A_METRES * Ellipsoid.A_METRES / nRadius;
        double latDeg = Math.toDegrees(Math.atan2(num, den)), lonDeg = Math.toDegrees(Math.atan2(y, x));
        double fx = nRadius * cosLat * x / p - eyeFoot[0], fy = nRadius * cosLat * y / p - eyeFoot[1],
                fz = nRadius * (1 - Ellipsoid.E2) * sinLat - eyeFoot[2];
        double ground = Refraction.groundDistanceFromChordMetres(Math.sqrt(fx * fx + fy * fy + fz * fz));
        return clearanceAt(latDeg, lonDeg, height, ground);
    }

    /** The same within 1 km of the axis, by the iterative conversion (Bowring's p divides there). */
    double clearanceNearPole(double x, double y, double z) {
        double[] geo = Ellipsoid.toGeodetic(x, y, z);
        double[] foot = new double[3];
        Ellipsoid.toEcef(geo[0], geo[1], 0, foot);
        return clearanceAt(geo[0], geo[1], geo[2], Refraction.groundDistanceBetweenFeetMetres(foot, eyeFoot));
    }

    private double clearanceAt(double latDeg, double lonDeg, double heightMetres, double groundDistanceMetres) {
        double row = mosaic.rowOf(latDeg), col = mosaic.colOf(lonDeg);
        int r = (int) Math.floor(row), c = (int) Math.floor(col);
        if (r < 0 || c < 0 || r + 1 >= mosaic.rows() || c + 1 >= mosaic.cols()) {
            return Double.NaN;
        }
        double v = row - r, w = col - c; // south and east fractions
        double nw = height(r, c), ne = height(r, c + 1), sw = height(r + 1, c), se = height(r + 1, c + 1);
        double surface = LevelOfDetail.interpolate(nw, ne, sw, se, w, v, Triangulation.splitsNorthWestToSouthEast(r, c));
        return heightMetres - surface - refraction.liftMetres(groundDistanceMetres);
    }

    private double height(int r, int c) {
        float h = mosaic.sample(r, c);
        return Float.isNaN(h) ? 0 : h;
    }
}
