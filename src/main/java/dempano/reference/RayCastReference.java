package dempano.reference;

import dempano.camera.TargetImage;
import dempano.dem.Mosaic;
import dempano.geo.LocalFrame;
import dempano.geo.Refraction;
import dempano.geo.Viewpoint;
import dempano.dem.Triangulation;
import java.util.concurrent.atomic.AtomicLong;
import java.util.stream.IntStream;

/**
 * The exact CPU reference for any target image (a camera with pitch, roll and lens distortion, or a
 * panorama): every pixel centre's own ray is cast on the triangulated surface the reference draws
 * ({@link TerrainRayProbe}: the full-resolution mosaic split by {@link Triangulation}, vertices on the WGS84
 * ellipsoid lifted by refraction k·d²/2R, cut at the range of sight by horizontal distance), in double
 * precision. Unlike {@link ReferenceRenderer}'s horizon sweep it needs no vertical planes of rays, so it serves
 * targets whose rays share none. Rows run in parallel.
 *
 * <p>Accuracy contract: the first crossing of the pixel's ray with the drawn planar triangles, to the probe's
 * tolerance (1e-9 relative); sky is +∞; a pixel without a ray (outside its lens model's domain) is NaN.
 */
public final class RayCastReference {
    /**
     * Higher than any terrain on Earth (Everest 8849 m), metres: a rising ray above it has met nothing. The
     * height of a straight ray above the ellipsoid is convex, so it is at least the eye's altitude plus
     * up-component × distance; the refraction lift (k &lt; 1) grows slower than the ray's curvature gain.
     */
    static final double HIGHEST_TERRAIN_METRES = 9000;
    /** Where the search along each ray begins, metres (the probe backs toward the eye where the ray is not above there). */
    private static final double SEARCH_FROM_METRES = 1.0;

    private RayCastReference() {
    }

    /**
     * What the ray cast produced.
     *
     * @param distanceMetres straight-line distance per pixel (row-major, row 0 on top), +∞ sky, NaN without a ray
     * @param argb           shaded colour per pixel, as {@link ReferenceRenderer} shades (null when not asked for)
     * @param undecided      rays the probe could not decide (the eye inside the terrain): NaN in the distances
     */
    public record Result(float[] distanceMetres, int[] argb, long undecided) {
    }

    /**
     * Casts every pixel's ray.
     *
     * @param scene       the DEM, the eye and the refraction the surface is lifted by
     * @param rangeMetres terrain farther than this horizontally from the eye is not drawn
     * @param target      the pixels and their rays (east-north-up at the eye)
     * @param colour      also compute a shaded colour image
     */
    public static Result render(Scene scene, double rangeMetres, TargetImage target, boolean colour) {
        TerrainRayProbe probe = new TerrainRayProbe(scene.mosaic(), scene.eye(), scene.refraction(), rangeMetres);
        ReferenceRenderer.Surface surface = new ReferenceRenderer.Surface(scene.mosaic(), scene.eye(), scene.refraction());
        LocalFrame frame = scene.eye().eyeFrame();
        double eyeAltitude = scene.eye().eyeAltitudeMetres();
        int w = target.widthPx(), h = target.heightPx();
        float[] distance = new float[w * h];
        int[] argb = colour ? new int[w * h] : null;
        ReliefShading shading = colour ? new ReliefShading(rangeMetres) : null;
        AtomicLong undecided = new AtomicLong();
        IntStream.range(0, h).parallel().forEach(row -> {
            double[] ray = new double[3];
            double[][] corners = new double[3][3];
            long rowUndecided = 0;
            for (int col = 0; col < w; col++) {
                int i = row * w + col;
                target.rayOf(col, row, ray);
                double e = ray[0], n = ray[1], u = ray[2];
                if (Double.isNaN(e) || Double.isNaN(n) || Double.isNaN(u)) {
                    distance[i] = Float.NaN;
                    if (argb != null) {
                        argb[i] = 0xFF000000;
                    }
                    continue;
                }
                double t = castMetres(probe, e, n, u, eyeAltitude, rangeMetres);
                if (Double.isNaN(t)) {
                    rowUndecided++;
                }
                distance[i] = (float) t;
                if (argb != null) {
                    argb[i] = Double.isFinite(t) ? shade(surface, frame, shading, e * t, n * t, u * t, t, corners)
                            : Double.isNaN(t) ? 0xFF000000 : ReliefShading.SKY_ARGB;
                }
            }
            undecided.addAndGet(rowUndecided);
        });
        return new Result(distance, argb, undecided.get());
    }

    /**
     * The DEM, the eye and the refraction of a render.
     *
     * @param eye the eye as placed (its frame is the one the target's rays are in)
     */
    public record Scene(Mosaic mosaic, Viewpoint eye, Refraction refraction) {
    }

    /**
     * One ray's first crossing with the surface, metres: +∞ when it stays above out to the range of sight (or,
     * rising, above the highest terrain there is); NaN when the probe cannot decide.
     *
     * @param e,n,u unit direction, east-north-up
     */
    static double castMetres(TerrainRayProbe probe, double e, double n, double u, double eyeAltitudeMetres,
                             double rangeMetres) {
        double horizontal = Math.hypot(e, n);
        double toRange = horizontal > 0 ? rangeMetres / horizontal : Double.POSITIVE_INFINITY;
        double toTop = u > 0 ? Math.max(0, HIGHEST_TERRAIN_METRES - eyeAltitudeMetres) / u + 1 : Double.POSITIVE_INFINITY;
        if (toTop < toRange) {
            double t = probe.firstHitMetres(e, u, -n, Math.min(SEARCH_FROM_METRES, toTop), toTop);
            // Above the highest terrain at toTop and rising: nothing farther can be met.
            return Double.isNaN(t) && toTop > 0 ? Double.POSITIVE_INFINITY : t;
        }
        return probe.firstHitMetres(e, u, -n, SEARCH_FROM_METRES, Double.POSITIVE_INFINITY);
    }

    /**
     * Shaded colour of a hit point (ENU metres): the DEM height and the normal of the drawn triangle under it.
     * {@code corners}: 3×3 scratch.
     */
    private static int shade(ReferenceRenderer.Surface surface, LocalFrame frame, ReliefShading shading, double e,
                             double n, double u, double t, double[][] corners) {
        double[] geo = frame.toGeodetic(e, n, u);
        Mosaic m = surface.mosaic;
        double row = m.rowOf(geo[0]), col = m.colOf(geo[1]);
        int r = Math.max(0, Math.min(m.rows() - 2, (int) Math.floor(row)));
        int c = Math.max(0, Math.min(m.cols() - 2, (int) Math.floor(col)));
        double y = row - r, x = col - c;
        boolean nwToSe = Triangulation.splitsNorthWestToSouthEast(r, c);
        int triangle = Triangulation.triangleHolding(nwToSe, y, x);
        double elevation = 0;
        for (int k = 0; k < 3; k++) {
            int corner = Triangulation.corner(nwToSe, triangle, k), cr = r + (corner >> 1), cc = c + (corner & 1);
            surface.position(cr, cc, corners[k]);
            elevation += cornerWeight(nwToSe, triangle, corner, y, x) * surface.elevation(cr, cc);
        }
        double ax = corners[1][0] - corners[0][0], ay = corners[1][1] - corners[0][1], az = corners[1][2] - corners[0][2];
        double bx = corners[2][0] - corners[0][0], by = corners[2][1] - corners[0][1], bz = corners[2][2] - corners[0][2];
        double nx = ay * bz - az * by, ny = az * bx - ax * bz, nz = ax * by - ay * bx;
        double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
        double[] normal = len == 0 ? new double[] {0, 0, 1}
                : new double[] {nx / len * Math.signum(nz == 0 ? 1 : nz), ny / len * Math.signum(nz == 0 ? 1 : nz),
                Math.abs(nz) / len};
        return shading.argb(elevation, normal, t);
    }

    /**
     * The barycentric weight of a cell corner ({@link Triangulation#NW}…{@link Triangulation#SE}) at a point (south and
     * east fractions of the cell) of the triangle holding it.
     */
    static double cornerWeight(boolean nwToSe, int triangle, int corner, double south, double east) {
        if (nwToSe) {
            if (triangle == Triangulation.NORTH) { // NW, NE, SE
                return corner == Triangulation.NW ? 1 - east : corner == Triangulation.NE ? east - south : south;
            }
            return corner == Triangulation.NW ? 1 - south : corner == Triangulation.SW ? south - east : east; // NW, SW, SE
        }
        if (triangle == Triangulation.NORTH) { // NW, NE, SW
            return corner == Triangulation.NW ? 1 - east - south : corner == Triangulation.NE ? east : south;
        }
        return corner == Triangulation.NE ? 1 - south : corner == Triangulation.SE ? east + south - 1 : 1 - east; // NE, SE, SW
    }
}
