package dempano.terrain;

import dempano.geo.Ellipsoid;
import dempano.geo.Refraction;
import dempano.geo.Viewpoint;

/**
 * Where the eye is, in the form the terrain shader takes it: the terrain's vertices are ECEF
 * positions (double-single) that do not depend on the eye, and the shader subtracts the eye's
 * position, lifts each vertex by refraction (k·d²/2R over the ground distance d between the feet, as
 * {@link Refraction} defines it) and turns it into the eye's frame (jME axes: x east, y up,
 * z south). Immutable, and free of GL: {@link TerrainBuilder#applyEye} hands {@link #uniforms()} to a material.
 */
public final class EyePlacement {
    /** Added to every bound, metres: the earth's curvature between a patch's corners (a few metres) and more. */
    static final double BOUND_MARGIN_METRES = 20;
    private final double[] eyeEcef = new double[3];
    private final double[] footRelative = new double[3];
    private final double[][] rows; // east, up, south (ECEF components)
    private final double liftPerSquareMetre;

    public EyePlacement(Viewpoint eye, Refraction refraction) {
        Ellipsoid.toEcef(eye.latDeg(), eye.lonDeg(), eye.eyeAltitudeMetres(), eyeEcef);
        double[] foot = new double[3];
        Ellipsoid.toEcef(eye.latDeg(), eye.lonDeg(), 0, foot);
        for (int a = 0; a < 3; a++) {
            footRelative[a] = foot[a] - eyeEcef[a];
        }
        double phi = Math.toRadians(eye.latDeg()), lam = Math.toRadians(eye.lonDeg());
        double sp = Math.sin(phi), cp = Math.cos(phi), sl = Math.sin(lam), cl = Math.cos(lam);
        rows = new double[][] {{-sl, cl, 0}, {cp * cl, cp * sl, sp}, {sp * cl, sp * sl, -cp}};
        liftPerSquareMetre = refraction.liftMetres(1);
    }

    /**
     * Where the shader puts a vertex, computed in double precision: the same subtraction of the eye,
     * refraction lift over the ground distance between the feet, and rotation as Terrain.vert.
     *
     * @param ecef          the vertex, ECEF metres
     * @param up            the ellipsoid normal at the vertex (ECEF, unit)
     * @param heightMetres  the vertex's height above the ellipsoid as placed
     * @param out           receives x, y, z in the eye's frame (jME axes: east, up, south), metres,
     *                      from {@code out[at]}
     */
    public void place(double[] ecef, double[] up, double heightMetres, double[] out, int at) {
        double rx = ecef[0] - eyeEcef[0], ry = ecef[1] - eyeEcef[1], rz = ecef[2] - eyeEcef[2];
        double cx = rx - heightMetres * up[0] - footRelative[0];
        double cy = ry - heightMetres * up[1] - footRelative[1];
        double cz = rz - heightMetres * up[2] - footRelative[2];
        double ground = dempano.geo.Refraction.groundDistanceFromChordMetres(Math.sqrt(cx * cx + cy * cy + cz * cz));
        double lift = liftPerSquareMetre * ground * ground;
        rx += lift * up[0];
        ry += lift * up[1];
        rz += lift * up[2];
        for (int a = 0; a < 3; a++) {
            out[at + a] = rows[a][0] * rx + rows[a][1] * ry + rows[a][2] * rz;
        }
    }

    /**
     * The eye as the terrain shader takes it (Terrain.vert's uniforms).
     *
     * @param eyeHigh            the eye's ECEF position rounded to floats, metres
     * @param eyeLow             the rest of it (eye − high, as floats): high + low is the eye to about 1e-15
     *                           relative, the vertices' double-single form
     * @param eyeFoot            the ellipsoid point below the eye, relative to the eye (ECEF), metres
     * @param ecefToEye          the rotation from ECEF to the eye's frame, row-major (rows east, up, south)
     * @param liftPerSquareMetre refraction's lift over a ground distance d is this × d², metres per square metre
     */
    public record Uniforms(float[] eyeHigh, float[] eyeLow, float[] eyeFoot, float[] ecefToEye, float liftPerSquareMetre) {
    }

    /** The eye's uniforms for the terrain shader. */
    public Uniforms uniforms() {
        float[] high = new float[3], low = new float[3], foot = new float[3], rotation = new float[9];
        for (int a = 0; a < 3; a++) {
            high[a] = (float) eyeEcef[a];
            low[a] = (float) (eyeEcef[a] - high[a]);
            foot[a] = (float) footRelative[a];
            for (int b = 0; b < 3; b++) {
                rotation[3 * a + b] = (float) rows[a][b];
            }
        }
        return new Uniforms(high, low, foot, rotation, (float) liftPerSquareMetre);
    }

    /**
     * A box in the eye's frame (jME axes, metres) holding every point of an ECEF point set's convex
     * hull as the shader places it: refraction's lift (at most that of the farthest point, along the
     * vertical there) and {@link #BOUND_MARGIN_METRES} are added on every side.
     *
     * @param hull ECEF points, 3 doubles each
     * @return the box's least x, y, z, then its greatest x, y, z, metres
     */
    public double[] bound(double[] hull) {
        double[] min = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] max = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        double farthest = 0;
        for (int i = 0; i < hull.length; i += 3) {
            double dx = hull[i] - eyeEcef[0], dy = hull[i + 1] - eyeEcef[1], dz = hull[i + 2] - eyeEcef[2];
            farthest = Math.max(farthest, Math.sqrt(dx * dx + dy * dy + dz * dz));
            for (int a = 0; a < 3; a++) {
                double v = rows[a][0] * dx + rows[a][1] * dy + rows[a][2] * dz;
                min[a] = Math.min(min[a], v);
                max[a] = Math.max(max[a], v);
            }
        }
        double pad = BOUND_MARGIN_METRES + liftPerSquareMetre * Math.pow(1.01 * farthest + 1000, 2);
        return new double[] {min[0] - pad, min[1] - pad, min[2] - pad, max[0] + pad, max[1] + pad, max[2] + pad};
    }
}
