package dempano.geo;

/**
 * The closed-form sea: where a straight ray from an eye meets an ellipsoid of revolution (by default
 * WGS84, i.e. the sea at height 0 without refraction), in double precision. The ray x = o + t·u
 * (ECEF metres, |u| = 1) meets x²/a² + y²/a² + z²/b² = 1 where, with p = (oₓ/a, o_y/a, o_z/b) and
 * q = (uₓ/a, u_y/a, u_z/b), q·q t² + 2 p·q t + (p·p − 1) = 0; the nearer positive root is taken in
 * its cancellation-free form. A ray that misses (negative discriminant, or pointing away) gives +∞.
 *
 * <p>The truth of the accuracy report's sea scenes: a DEM of zeros seen with refraction k = 0 is this
 * ellipsoid (up to the chord sag of its triangles, well under a millimetre for 90 m cells).
 */
public final class EllipsoidRay {
    private EllipsoidRay() {
    }

    /**
     * Distance along a ray to an ellipsoid of revolution about the z axis.
     *
     * @param origin     ray origin, ECEF metres (length 3), outside the ellipsoid
     * @param direction  unit direction, ECEF (length 3)
     * @param aMetres    equatorial semi-axis, metres
     * @param bMetres    polar semi-axis, metres
     * @return distance to the first intersection, metres; +∞ when the ray misses; 0 for an origin on or
     *         inside the surface
     */
    public static double distanceMetres(double[] origin, double[] direction, double aMetres, double bMetres) {
        double px = origin[0] / aMetres, py = origin[1] / aMetres, pz = origin[2] / bMetres;
        double qx = direction[0] / aMetres, qy = direction[1] / aMetres, qz = direction[2] / bMetres;
        double qq = qx * qx + qy * qy + qz * qz;
        double pq = px * qx + py * qy + pz * qz;
        double c = px * px + py * py + pz * pz - 1;
        if (c <= 0) {
            return 0;
        }
        if (pq >= 0) {
            return Double.POSITIVE_INFINITY; // pointing away from the surface
        }
        double disc = pq * pq - qq * c;
        if (disc < 0) {
            return Double.POSITIVE_INFINITY;
        }
        // Roots (−pq ± √disc)/qq; the nearer one written as c / (−pq + √disc) to avoid cancellation.
        return c / (-pq + Math.sqrt(disc));
    }

    /** {@link #distanceMetres(double[], double[], double, double)} on the WGS84 ellipsoid. */
    public static double distanceToWgs84Metres(double[] origin, double[] direction) {
        return distanceMetres(origin, direction, Ellipsoid.A_METRES, Ellipsoid.B_METRES);
    }

    /**
     * Angle between a ray and the tangent plane of an ellipsoid of revolution at a point on it,
     * degrees in [0, 90] (90 = along the normal).
     *
     * @param point     point on the surface, ECEF metres
     * @param direction unit ray direction, ECEF
     */
    public static double incidenceDeg(double[] point, double[] direction, double aMetres, double bMetres) {
        // The outward normal is the gradient (x/a², y/a², z/b²).
        double nx = point[0] / (aMetres * aMetres), ny = point[1] / (aMetres * aMetres), nz = point[2] / (bMetres * bMetres);
        double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
        double cos = Math.abs(nx * direction[0] + ny * direction[1] + nz * direction[2]) / len;
        return Math.toDegrees(Math.asin(Math.min(1, cos)));
    }

    /**
     * An ENU unit direction as an ECEF unit direction: the frame maps points, so a point a long way
     * (10⁷ m) along the direction is mapped and the origin subtracted, which keeps the direction's
     * rounding near 10⁻¹⁶.
     *
     * @param originEcef the frame's origin in ECEF metres
     * @param scratch    work array, length ≥ 3
     * @param out        receives the unit direction (length ≥ 3)
     */
    public static void enuDirectionToEcef(LocalFrame eye, double[] originEcef, double e, double n, double u,
                                          double[] scratch, double[] out) {
        double scale = 1e7;
        eye.enuToEcef(e * scale, n * scale, u * scale, scratch);
        double len = 0;
        for (int k = 0; k < 3; k++) {
            out[k] = scratch[k] - originEcef[k];
            len += out[k] * out[k];
        }
        len = Math.sqrt(len);
        for (int k = 0; k < 3; k++) {
            out[k] /= len;
        }
    }
}
