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
 * over. Stateless after construction: thread-safe.
 */
public final class TerrainRayProbe implements RayProbe {
    /** Outward steps multiply the distance by this. */
    static final double STEP_RATIO = 1.1;
    /** Bisection stops when the bracket is this narrow, relative to the distance. */
    static final double TOLERANCE = 1e-9;

    private final Mosaic mosaic;
    private final LocalFrame frame;
    private final Refraction refraction;
    private final double rangeMetres;
    private final double[] eyeFoot = new double[3];

    public TerrainRayProbe(Mosaic mosaic, Viewpoint eye, Refraction refraction, double rangeMetres) {
        this.mosaic = mosaic;
        this.frame = eye.eyeFrame();
        this.refraction = refraction;
        this.rangeMetres = rangeMetres;
        Ellipsoid.toEcef(eye.latDeg(), eye.lonDeg(), 0, eyeFoot);
    }

    @Override
    public double firstHitMetres(double dx, double dy, double dz, double fromMetres, double toMetres) {
        double e = dx, n = -dz, u = dy; // jME axes (east, up, south) to ENU
        double horizontal = Math.hypot(e, n);
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
            b = Math.min(b * STEP_RATIO, tMax);
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
        double[] geo = Ellipsoid.toGeodetic(ecef[0], ecef[1], ecef[2]);
        double row = mosaic.rowOf(geo[0]), col = mosaic.colOf(geo[1]);
        int r = (int) Math.floor(row), c = (int) Math.floor(col);
        if (r < 0 || c < 0 || r + 1 >= mosaic.rows() || c + 1 >= mosaic.cols()) {
            return Double.NaN;
        }
        double v = row - r, w = col - c; // south and east fractions
        double nw = height(r, c), ne = height(r, c + 1), sw = height(r + 1, c), se = height(r + 1, c + 1);
        double surface = LevelOfDetail.interpolate(nw, ne, sw, se, w, v, Triangulation.splitsNorthWestToSouthEast(r, c));
        double[] foot = new double[3];
        Ellipsoid.toEcef(geo[0], geo[1], 0, foot);
        return geo[2] - surface - refraction.liftMetres(Refraction.groundDistanceBetweenFeetMetres(foot, eyeFoot));
    }

    private double height(int r, int c) {
        float h = mosaic.sample(r, c);
        return Float.isNaN(h) ? 0 : h;
    }
}
