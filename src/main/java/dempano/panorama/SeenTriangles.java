package dempano.panorama;

/**
 * The triangles the views saw, in double precision, and which one each view sample saw: what lets
 * the {@link Stitcher} measure every panorama pixel's distance along that pixel's own centre ray.
 * Pure data and arithmetic, no GL.
 *
 * <p>Coordinates are the eye's frame in jME axes (x east, y up, z south; metres, the eye at the
 * origin), the vertices placed exactly as the terrain shader places them (refraction's lift
 * included), but in double precision.
 *
 * @param corners            per triangle 9 doubles: the first vertex, then the two edges from it
 *                           to the second and third vertex
 * @param skirt              per triangle: true for a skirt's (a vertical wall hung below a patch
 *                           edge to close cracks between levels of detail): drawn, but not terrain
 * @param simplified         per triangle: true where it belongs to a simplified patch (level of
 *                           detail above 0, or a merged block), whose surface sags off the
 *                           full-resolution one; false for a full-resolution patch's, which lies
 *                           on the surface the CPU reference draws (to micrometres)
 * @param triangleOfSample   per view, per sample (GL order, row 0 at the bottom): the index of the
 *                           triangle seen there, −1 where nothing was drawn (sky)
 * @param rangeMetres        the range cut: a point farther than this horizontally from the eye
 *                           (√(x² + z²)) is not drawn, as in the shader
 * @param normals            per triangle 4 doubles: the cross product of its two edges and that
 *                           vector's length (for {@link #incidenceSine}, asked per pixel)
 */
public record SeenTriangles(double[] corners, boolean[] skirt, boolean[] simplified, int[][] triangleOfSample,
                            double rangeMetres, double[] normals) {
    /** With the normals computed from the corners. */
    public SeenTriangles(double[] corners, boolean[] skirt, boolean[] simplified, int[][] triangleOfSample,
                         double rangeMetres) {
        this(corners, skirt, simplified, triangleOfSample, rangeMetres, normalsOf(corners));
    }

    private static double[] normalsOf(double[] c) {
        double[] out = new double[c.length / 9 * 4];
        java.util.stream.IntStream.range(0, c.length / 9).parallel().forEach(t -> {
            int o = t * 9, q = t * 4;
            double e1x = c[o + 3], e1y = c[o + 4], e1z = c[o + 5], e2x = c[o + 6], e2y = c[o + 7], e2z = c[o + 8];
            double nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
            out[q] = nx;
            out[q + 1] = ny;
            out[q + 2] = nz;
            out[q + 3] = Math.sqrt(nx * nx + ny * ny + nz * nz);
        });
        return out;
    }

    /**
     * Relative tolerance on the barycentric coordinates: a ray through a shared edge hits one of
     * its two triangles whatever the rounding (the nearer hit is kept, and both are at one distance).
     */
    static final double EDGE_TOLERANCE = 1e-9;

    public int triangles() {
        return corners.length / 9;
    }

    /** Squared distance from the eye to a triangle's first corner, square metres. */
    public double cornerDistanceSquared(int triangle) {
        int o = triangle * 9;
        return corners[o] * corners[o] + corners[o + 1] * corners[o + 1] + corners[o + 2] * corners[o + 2];
    }

    /** Distance from the eye to a triangle's first corner, metres. */
    public double cornerDistanceMetres(int triangle) {
        int o = triangle * 9;
        return Math.sqrt(corners[o] * corners[o] + corners[o + 1] * corners[o + 1] + corners[o + 2] * corners[o + 2]);
    }

    /**
     * Distance along a unit ray from the eye to a triangle (Möller–Trumbore in double precision),
     * or +∞ when the ray misses it, meets it behind the eye, or meets it beyond the range cut.
     * Exact to double rounding: at an incidence angle θ the relative error is about 1e-16 / sin θ.
     *
     * @param dx ray direction, unit length (eye frame, jME axes)
     */
    public double distanceAlong(int triangle, double dx, double dy, double dz) {
        double t = rayTriangleMetres(corners, triangle * 9, dx, dy, dz);
        if (t == Double.POSITIVE_INFINITY) {
            return t;
        }
        double hx = t * dx, hz = t * dz;
        return hx * hx + hz * hz > rangeMetres * rangeMetres ? Double.POSITIVE_INFINITY : t;
    }

    /**
     * Möller–Trumbore in double precision: the distance along a unit ray from the origin to the
     * triangle stored at {@code c[o..o+8]} (first vertex, then the edges to the second and third),
     * or +∞ when the ray misses it (beyond {@link #EDGE_TOLERANCE}), lies in its plane or meets it
     * behind the origin.
     */
    public static double rayTriangleMetres(double[] c, int o, double dx, double dy, double dz) {
        double e1x = c[o + 3], e1y = c[o + 4], e1z = c[o + 5], e2x = c[o + 6], e2y = c[o + 7], e2z = c[o + 8];
        double px = dy * e2z - dz * e2y, py = dz * e2x - dx * e2z, pz = dx * e2y - dy * e2x;
        double det = e1x * px + e1y * py + e1z * pz;
        if (det == 0 || Double.isNaN(det)) {
            return Double.POSITIVE_INFINITY; // the ray lies in the triangle's plane: it is seen edge-on
        }
        double inv = 1 / det;
        double tx = -c[o], ty = -c[o + 1], tz = -c[o + 2]; // origin − first vertex
        double u = (tx * px + ty * py + tz * pz) * inv;
        if (u < -EDGE_TOLERANCE || u > 1 + EDGE_TOLERANCE) {
            return Double.POSITIVE_INFINITY;
        }
        double qx = ty * e1z - tz * e1y, qy = tz * e1x - tx * e1z, qz = tx * e1y - ty * e1x;
        double v = (dx * qx + dy * qy + dz * qz) * inv;
        if (v < -EDGE_TOLERANCE || u + v > 1 + EDGE_TOLERANCE) {
            return Double.POSITIVE_INFINITY;
        }
        double t = (e2x * qx + e2y * qy + e2z * qz) * inv;
        return t > 0 ? t : Double.POSITIVE_INFINITY;
    }

    /**
     * Sine of the angle between a unit ray and a triangle's plane: 1 looking straight at it, near 0
     * at grazing incidence, where a small error of the surface's height is a large error of distance.
     */
    public double incidenceSine(int triangle, double dx, double dy, double dz) {
        int q = triangle * 4;
        double length = normals[q + 3];
        return length > 0 ? Math.abs(normals[q] * dx + normals[q + 1] * dy + normals[q + 2] * dz) / length : 0;
    }
}
