package dempano.panorama;

import dempano.dem.Mosaic;
import dempano.geo.Ellipsoid;
import dempano.geo.Geodesy;
import dempano.geo.LocalFrame;
import dempano.geo.Refraction;
import dempano.dem.Triangulation;
import java.util.EnumMap;
import java.util.Map;
import java.util.Set;
import java.util.stream.IntStream;

/**
 * Per-pixel layers from each pixel's ray and distance: the point seen is eye + distance·ray in the
 * eye's east-north-up frame; its geodetic position follows exactly; its terrain elevation is its
 * height minus the refraction lift the renderer added.
 *
 * <p>{@link Layer#INCIDENCE} takes the surface at the point seen from the mosaic: the DEM cell's
 * triangle holding the point (split as {@link Triangulation}, the surface both renderers draw), its
 * slope in metres per metre in the local east-north-up frame at the point (up = ellipsoid normal
 * there, so earth curvature is accounted for), plus the slope of the refraction lift k·s²/(2R) along
 * the ground direction away from the eye (s = ground distance from the eye; the renderer draws a
 * straight ray against lifted terrain, which gives the same angle as the bent real ray against the
 * real terrain). Ray and surface normal are compared in ECEF.
 */
public final class LayerComputer {
    /**
     * Vertical error of the DEM used by {@link Layer#UNCERTAINTY}, metres: SRTM's stated relative
     * vertical accuracy (10 m, 90 % linear error). The absolute figure (16 m) does not apply: an
     * error common to the eye's ground and the terrain around it cancels, since the eye stands on
     * the same DEM.
     */
    public static final double SRTM_RELATIVE_VERTICAL_ERROR_METRES = 10;

    private LayerComputer() {
    }

    /**
     * @param distance metres per pixel, +∞ for sky (row-major, as {@code g})
     * @param mosaic   the DEM the distances were rendered from; needed only for
     *                 {@link Layer#INCIDENCE} and {@link Layer#UNCERTAINTY}
     */
    public static Map<Layer, float[]> compute(Set<Layer> wanted, PanoramaGeometry g, float[] distance, LocalFrame eye,
                                              Refraction refraction, Mosaic mosaic) {
        return compute(wanted, new Grid(g.widthPx(), g.heightPx(), (col, row, d, out) -> {
            double el = Math.toRadians(g.elevationOfRow(row)), az = Math.toRadians(g.azimuthOfColumn(col));
            out[0] = d * Math.cos(el) * Math.sin(az);
            out[1] = d * Math.cos(el) * Math.cos(az);
            out[2] = d * Math.sin(el);
        }), distance, new Surroundings(eye, refraction, mosaic));
    }

    /**
     * The layers of any target image (a camera's photo grid), each pixel's point seen at its distance along the
     * target's own ray ({@link dempano.camera.TargetImage#rayOf}); a pixel without a ray gets NaN in every layer.
     *
     * @param distance metres per pixel, +∞ for sky, NaN without a ray (row-major, as {@code target})
     * @param around   the eye's frame, the refraction the distances were rendered with, and the DEM (needed only for
     *                 {@link Layer#INCIDENCE} and {@link Layer#UNCERTAINTY})
     */
    public static Map<Layer, float[]> compute(Set<Layer> wanted, dempano.camera.TargetImage target, float[] distance,
                                              Surroundings around) {
        return compute(wanted, new Grid(target.widthPx(), target.heightPx(), (col, row, d, out) -> {
            target.rayOf(col, row, out);
            out[0] *= d;
            out[1] *= d;
            out[2] *= d;
        }), distance, around);
    }

    /**
     * The eye's frame, the refraction the distances were rendered with, and the DEM they were rendered from.
     *
     * @param mosaic null where neither incidence nor uncertainty is wanted
     */
    public record Surroundings(LocalFrame eye, Refraction refraction, Mosaic mosaic) {
    }

    /** Where a pixel's point seen lies: metres east, north, up from the eye at distance d along its ray. */
    private interface PointOf {
        void point(int col, int row, double d, double[] enuOut);
    }

    private record Grid(int widthPx, int heightPx, PointOf points) {
    }

    private static Map<Layer, float[]> compute(Set<Layer> wanted, Grid g, float[] distance, Surroundings around) {
        LocalFrame eye = around.eye();
        Refraction refraction = around.refraction();
        Mosaic mosaic = around.mosaic();
        Map<Layer, float[]> out = new EnumMap<>(Layer.class);
        if (wanted.isEmpty()) {
            return out;
        }
        int w = g.widthPx(), n = w * g.heightPx();
        for (Layer l : wanted) {
            out.put(l, new float[n]);
        }
        float[] elev = out.get(Layer.ELEVATION), lat = out.get(Layer.LATITUDE), lon = out.get(Layer.LONGITUDE),
                ground = out.get(Layer.GROUND_DISTANCE), inc = out.get(Layer.INCIDENCE),
                unc = out.get(Layer.UNCERTAINTY);
        boolean surface = inc != null || unc != null;
        if (surface && mosaic == null) {
            throw new IllegalArgumentException("incidence and uncertainty need the mosaic");
        }
        float[][] all = {elev, lat, lon, ground, inc, unc};
        double[] eyeFoot = new double[3], eyeEcef = new double[3];
        Ellipsoid.toEcef(eye.originLatDeg(), eye.originLonDeg(), 0, eyeFoot);
        eye.enuToEcef(0, 0, 0, eyeEcef);
        IntStream.range(0, g.heightPx()).parallel().forEach(row -> {
            double[] foot = new double[3], hit = new double[3], ray = new double[3], point = new double[3];
            for (int col = 0; col < w; col++) {
                int i = row * w + col;
                double d = distance[i];
                if (!Double.isFinite(d)) {
                    for (float[] a : all) {
                        if (a != null) {
                            a[i] = Float.NaN;
                        }
                    }
                    continue;
                }
                g.points().point(col, row, d, point);
                double e = point[0], nn = point[1], u = point[2];
                if (Double.isNaN(e)) { // no ray
                    for (float[] a : all) {
                        if (a != null) {
                            a[i] = Float.NaN;
                        }
                    }
                    continue;
                }
                double[] geo = eye.toGeodetic(e, nn, u);
                if (lat != null) {
                    lat[i] = (float) geo[0];
                }
                if (lon != null) {
                    lon[i] = (float) geo[1];
                }
                double groundFromEye = Double.NaN;
                if (elev != null || surface) {
                    Ellipsoid.toEcef(geo[0], geo[1], 0, foot);
                    groundFromEye = Refraction.groundDistanceBetweenFeetMetres(foot, eyeFoot);
                }
                if (elev != null) {
                    elev[i] = (float) (geo[2] - refraction.liftMetres(groundFromEye));
                }
                if (ground != null) {
                    ground[i] = (float) Geodesy.distanceMetres(eye.originLatDeg(), eye.originLonDeg(), geo[0], geo[1]);
                }
                if (surface) {
                    // Ray direction in ECEF (the eye frame is ECEF rotated and shifted).
                    eye.enuToEcef(e, nn, u, hit);
                    for (int k = 0; k < 3; k++) {
                        ray[k] = (hit[k] - eyeEcef[k]) / d;
                    }
                    double incidenceDeg = incidenceDeg(mosaic, geo[0], geo[1], ray,
                            refraction.coefficient() * groundFromEye / Ellipsoid.MEAN_RADIUS_METRES);
                    if (inc != null) {
                        inc[i] = (float) incidenceDeg;
                    }
                    if (unc != null) {
                        unc[i] = (float) uncertaintyMetres(incidenceDeg, d);
                    }
                }
            }
        });
        return out;
    }

    /**
     * Distance error (metres, 90 % linear error like the DEM figure it scales) caused by the DEM's
     * vertical error at a point seen at the given incidence: σ_h / sin(incidence), σ_h =
     * {@link #SRTM_RELATIVE_VERTICAL_ERROR_METRES}, capped at the distance itself. NaN for a NaN
     * incidence.
     *
     * @param incidenceDeg angle between ray and surface, degrees in [0, 90]
     * @param distanceMetres distance to the point seen, metres
     */
    public static double uncertaintyMetres(double incidenceDeg, double distanceMetres) {
        if (Double.isNaN(incidenceDeg)) {
            return Double.NaN;
        }
        double s = Math.sin(Math.toRadians(incidenceDeg));
        double sigma = SRTM_RELATIVE_VERTICAL_ERROR_METRES / s; // +∞ at exactly 0°
        return Math.min(sigma, distanceMetres);
    }

    /**
     * Angle in degrees, in [0, 90], between a ray and the tangent plane of the drawn terrain (plus
     * the refraction lift's slope) at a point; NaN where the mosaic has no samples around it.
     *
     * @param rayEcef             unit ray direction in ECEF
     * @param liftSlope           slope of the refraction lift away from the eye, k·s/R (metres per metre)
     */
    static double incidenceDeg(Mosaic m, double latDeg, double lonDeg, double[] rayEcef, double liftSlope) {
        double row = m.rowOf(latDeg), col = m.colOf(lonDeg);
        if (!(row >= 0 && row <= m.rows() - 1 && col >= 0 && col <= m.cols() - 1)) {
            return Double.NaN;
        }
        int r = Math.min(m.rows() - 2, (int) row), c = Math.min(m.cols() - 2, (int) col);
        double v = row - r, uu = col - c; // south and east fractions in the cell
        double nw = m.sample(r, c), ne = m.sample(r, c + 1), sw = m.sample(r + 1, c), se = m.sample(r + 1, c + 1);
        // Height gradient on the cell's triangle, metres per cell step east (du) and south (dv).
        double du, dv;
        boolean nwToSe = Triangulation.splitsNorthWestToSouthEast(r, c);
        boolean northTriangle = Triangulation.triangleHolding(nwToSe, v, uu) == Triangulation.NORTH;
        if (nwToSe) {
            if (northTriangle) {
                du = ne - nw;
                dv = se - ne;
            } else {
                du = se - sw;
                dv = sw - nw;
            }
        } else if (northTriangle) {
            du = ne - nw;
            dv = sw - nw;
        } else {
            du = se - sw;
            dv = se - ne;
        }
        if (!Double.isFinite(du) || !Double.isFinite(dv)) {
            return Double.NaN;
        }
        double phi = Math.toRadians(latDeg), lam = Math.toRadians(lonDeg);
        double sp = Math.sin(phi), cp = Math.cos(phi), sl = Math.sin(lam), cl = Math.cos(lam);
        double step = Math.toRadians(1.0 / m.intervalsPerDegree());
        double eastStepMetres = step * Ellipsoid.primeVerticalRadiusOfSinMetres(sp) * cp;
        double southStepMetres = step * Ellipsoid.meridianRadiusOfSinMetres(sp);
        double gE = du / eastStepMetres, gN = -dv / southStepMetres;
        // Local ENU axes at the point, in ECEF.
        double[] east = {-sl, cl, 0}, north = {-sp * cl, -sp * sl, cp}, up = {cp * cl, cp * sl, sp};
        double rE = dot(rayEcef, east), rN = dot(rayEcef, north), rU = dot(rayEcef, up);
        double horizontal = Math.hypot(rE, rN);
        if (liftSlope != 0 && horizontal > 0) {
            gE += liftSlope * rE / horizontal;
            gN += liftSlope * rN / horizontal;
        }
        // Normal (−gE, −gN, 1) in ENU; the ray is already in ENU components.
        double s = Math.abs(-gE * rE - gN * rN + rU) / Math.sqrt(gE * gE + gN * gN + 1);
        return Math.toDegrees(Math.asin(Math.min(1, s)));
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }
}
