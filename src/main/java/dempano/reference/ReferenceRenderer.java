package dempano.reference;

import dempano.dem.Mosaic;
import dempano.geo.Ellipsoid;
import dempano.geo.LocalFrame;
import dempano.geo.Refraction;
import dempano.geo.Viewpoint;
import dempano.panorama.PanoramaGeometry;
import dempano.dem.Triangulation;
import java.util.concurrent.atomic.AtomicLong;
import java.util.stream.IntStream;

/**
 * The exact CPU reference: for every panorama pixel centre, the distance to the first point of the
 * terrain its ray meets, in double precision, on the surface the GPU draws (the full-resolution
 * mosaic split into triangles by {@link Triangulation}, vertices placed on the WGS84 ellipsoid and
 * lifted by refraction k·d²/2R, terrain cut at the range of sight by horizontal distance).
 *
 * <p>Algorithm (a horizon sweep; nothing shared with the GL path): all rays of one panorama column
 * lie in the vertical plane through the eye at that azimuth. The plane cuts the triangulated surface
 * in a polyline, walked triangle by triangle outward from the eye's foot. Seen from the eye, the
 * polyline's angle above the horizontal rises and falls; a pixel's ray first meets it on the first
 * segment whose far end rises above the pixel's elevation while everything before stayed below, so
 * one pass with the running maximum angle assigns every pixel of the column its exact intersection.
 * Cost is O(cells crossed + pixels) per column; columns run in parallel.
 *
 * <p>Accuracy contract: distances are exact on the triangulated surface up to double rounding
 * (micrometres); sky is +∞.
 */
public final class ReferenceRenderer {
    private ReferenceRenderer() {
    }

    /**
     * What the sweep produced.
     *
     * @param distanceMetres   straight-line distance per pixel (row-major, row 0 on top), +∞ for sky
     * @param argb             shaded colour per pixel (null when colour was not asked for)
     * @param trianglesVisited triangles walked over all columns
     */
    public record Result(float[] distanceMetres, int[] argb, long trianglesVisited) {
    }

    /**
     * Renders one panorama.
     *
     * @param rangeMetres terrain farther than this horizontally from the eye is not drawn
     * @param colour      also compute a shaded colour image
     */
    public static Result render(Mosaic mosaic, Viewpoint eye, Refraction refraction, double rangeMetres,
                                PanoramaGeometry geometry, boolean colour) {
        Surface surface = new Surface(mosaic, eye, refraction);
        int w = geometry.widthPx(), h = geometry.heightPx();
        float[] distance = new float[w * h];
        int[] argb = colour ? new int[w * h] : null;
        double[] sinEl = new double[h], cosEl = new double[h];
        for (int r = 0; r < h; r++) {
            double el = Math.toRadians(geometry.elevationOfRow(r));
            sinEl[r] = Math.sin(el);
            cosEl[r] = Math.cos(el);
        }
        ReliefShading shading = colour ? new ReliefShading(rangeMetres) : null;
        AtomicLong visited = new AtomicLong();
        IntStream.range(0, w).parallel().forEach(col -> {
            ColumnSweep sweep = new ColumnSweep(surface, Math.toRadians(geometry.azimuthOfColumn(col)), rangeMetres,
                    sinEl, cosEl, shading);
            visited.addAndGet(sweep.run());
            for (int r = 0; r < h; r++) {
                distance[r * w + col] = (float) sweep.distance[r];
                if (argb != null) {
                    argb[r * w + col] = sweep.argb[r];
                }
            }
        });
        return new Result(distance, argb, visited.get());
    }

    /** Vertex positions of the triangulated surface in the eye's ENU frame, computed on demand. */
    static final class Surface {
        final Mosaic mosaic;
        final int rows, cols;
        private final double[] sinLat, cosLat, sinLon, cosLon;
        private final LocalFrame frame;
        private final double[] eyeFoot = new double[3];
        private final Refraction refraction;
        final double eyeRow, eyeCol;

        Surface(Mosaic mosaic, Viewpoint eye, Refraction refraction) {
            this.mosaic = mosaic;
            this.rows = mosaic.rows();
            this.cols = mosaic.cols();
            this.refraction = refraction;
            this.frame = eye.eyeFrame();
            Ellipsoid.toEcef(eye.latDeg(), eye.lonDeg(), 0, eyeFoot);
            sinLat = new double[rows];
            cosLat = new double[rows];
            for (int r = 0; r < rows; r++) {
                double phi = Math.toRadians(mosaic.latOfRow(r));
                sinLat[r] = Math.sin(phi);
                cosLat[r] = Math.cos(phi);
            }
            sinLon = new double[cols];
            cosLon = new double[cols];
            for (int c = 0; c < cols; c++) {
                double lam = Math.toRadians(mosaic.wrappedLonOfCol(c));
                sinLon[c] = Math.sin(lam);
                cosLon[c] = Math.cos(lam);
            }
            eyeRow = mosaic.rowOf(eye.latDeg());
            eyeCol = mosaic.colOf(eye.lonDeg());
        }

        /** DEM height of a vertex (metres; a NaN sample counts as sea level, as on the GPU). */
        double elevation(int r, int c) {
            float h = mosaic.sample(r, c);
            return Float.isNaN(h) ? 0 : h;
        }

        /** ENU position (metres) of vertex (r, c), refraction applied. @param out length ≥ 3 */
        void position(int r, int c, double[] out) {
            double[] foot = out;
            Ellipsoid.toEcef(sinLat[r], cosLat[r], sinLon[c], cosLon[c], 0, foot);
            double fx = foot[0], fy = foot[1], fz = foot[2];
            double ground = Refraction.groundDistanceBetweenFeetMetres(foot, eyeFoot);
            double h = elevation(r, c) + refraction.liftMetres(ground);
            frame.ecefToEnu(fx + h * cosLat[r] * cosLon[c], fy + h * cosLat[r] * sinLon[c], fz + h * sinLat[r], out);
        }
    }

    /** One column: the plane walk and the horizon sweep. */
    static final class ColumnSweep {
        private final Surface s;
        private final double dirE, dirN;     // horizontal direction of the azimuth
        private final double normE, normN;   // the plane's normal
        private final double rangeMetres;
        private final double[] sinEl, cosEl, elevationRad;
        private final ReliefShading shading;
        final double[] distance;
        final int[] argb;

        // Current triangle: vertex grid indices and ENU positions.
        private final int[] vr = new int[3], vc = new int[3];
        private final double[][] vp = new double[3][3];
        private final double[] vf = new double[3];
        private int cellR, cellC, half;

        ColumnSweep(Surface s, double azimuthRad, double rangeMetres, double[] sinEl, double[] cosEl, ReliefShading shading) {
            this.s = s;
            this.dirE = Math.sin(azimuthRad);
            this.dirN = Math.cos(azimuthRad);
            this.normE = dirN;
            this.normN = -dirE;
            this.rangeMetres = rangeMetres;
            this.sinEl = sinEl;
            this.cosEl = cosEl;
            this.elevationRad = new double[sinEl.length];
            for (int i = 0; i < sinEl.length; i++) {
                elevationRad[i] = Math.atan2(sinEl[i], cosEl[i]);
            }
            this.shading = shading;
            this.distance = new double[sinEl.length];
            java.util.Arrays.fill(distance, Double.POSITIVE_INFINITY);
            this.argb = shading == null ? null : new int[sinEl.length];
            if (argb != null) {
                java.util.Arrays.fill(argb, ReliefShading.SKY_ARGB);
            }
        }

        /** Loads triangle {@code half} (0 or 1) of the cell with north-west corner (r, c). */
        private void load(int r, int c, int which) {
            cellR = r;
            cellC = c;
            half = which;
            // Corners: NW, NE, SW, SE.
            boolean nwse = Triangulation.splitsNorthWestToSouthEast(r, c);
            for (int k = 0; k < 3; k++) {
                int corner = Triangulation.corner(nwse, which, k);
                vr[k] = r + (corner >> 1);
                vc[k] = c + (corner & 1);
                s.position(vr[k], vc[k], vp[k]);
                vf[k] = normE * vp[k][0] + normN * vp[k][1];
            }
        }

        // Triangle 0 (Triangulation.NORTH) holds the cell's north edge, 1 (SOUTH) its south edge; of an NW–SE cell the
        // north one has the east edge too, the south one the west edge; of an NE–SW cell the other way round.

        private static boolean positive(double f) {
            return f >= 0;
        }

        private boolean crosses(int a, int b) {
            return positive(vf[a]) != positive(vf[b]);
        }

        /** Intersection of edge (a, b) with the plane: {s, u, elevation}. */
        private void cut(int a, int b, double[] out) {
            double lambda = vf[a] / (vf[a] - vf[b]);
            double e = vp[a][0] + lambda * (vp[b][0] - vp[a][0]);
            double n = vp[a][1] + lambda * (vp[b][1] - vp[a][1]);
            out[0] = dirE * e + dirN * n;
            out[1] = vp[a][2] + lambda * (vp[b][2] - vp[a][2]);
            double ha = s.elevation(vr[a], vc[a]), hb = s.elevation(vr[b], vc[b]);
            out[2] = ha + lambda * (hb - ha);
        }

        /** Runs the sweep; returns the number of triangles visited. */
        long run() {
            int[] start = startTriangle();
            if (start == null) {
                return 0;
            }
            load(start[0], start[1], start[2]);
            // Of the two crossing edges pick the one farther along the azimuth as the exit.
            int[] edges = crossingEdges();
            double[] a = new double[3], b = new double[3];
            cut(edges[0], edges[1], a);
            cut(edges[2], edges[3], b);
            int exitA, exitB;
            if (b[0] >= a[0]) {
                exitA = edges[2];
                exitB = edges[3];
            } else {
                exitA = edges[0];
                exitB = edges[1];
                double[] t = a;
                a = b;
                b = t;
            }
            // Profile starts below the eye: the triangle's plane on the eye's vertical.
            double[] p = {0, uBelowEye(), s.elevation(vr[0], vc[0])};
            double maxAngle = -Math.PI / 2;
            int next = sinEl.length - 1; // lowest pixel not yet hit (rows grow downward)
            long count = 1;
            double[] entry = p;
            double[] exit = b;
            int limit = 4 * (s.rows + s.cols) + 16;
            while (true) {
                boolean last = false;
                if (exit[0] > rangeMetres) {
                    // Cut at the range: a point at horizontal distance exactly rangeMetres.
                    double lambda = (rangeMetres - entry[0]) / (exit[0] - entry[0]);
                    if (!(lambda >= 0 && lambda <= 1)) {
                        lambda = 0;
                    }
                    exit = new double[] {rangeMetres, entry[1] + lambda * (exit[1] - entry[1]),
                        entry[2] + lambda * (exit[2] - entry[2])};
                    last = true;
                }
                double angle = Math.atan2(exit[1], exit[0]);
                // Only points ahead of the eye belong to this column (exit[0] ≤ 0 is below or behind it).
                if (exit[0] > 0 && angle > maxAngle) {
                    double ds = exit[0] - entry[0], du = exit[1] - entry[1];
                    // Invariant: every pixel below `next` is hit, and elevation[next] > maxAngle.
                    while (next >= 0 && elevationRad[next] <= angle) {
                        double denom = cosEl[next] * du - sinEl[next] * ds;
                        double t = denom == 0 ? Math.hypot(entry[0], entry[1])
                                : (entry[0] * du - entry[1] * ds) / denom;
                        double ra = Math.hypot(entry[0], entry[1]), rb = Math.hypot(exit[0], exit[1]);
                        // Rounding guard: a segment's points are no farther than its farther end (distance
                        // along a segment is convex); its nearest point may be inside it.
                        t = Math.max(0, Math.min(Math.max(ra, rb), t));
                        distance[next] = t;
                        if (argb != null) {
                            double len = Math.hypot(ds, du);
                            double frac = len == 0 ? 0
                                    : Math.hypot(t * cosEl[next] - entry[0], t * sinEl[next] - entry[1]) / len;
                            double elevation = entry[2] + Math.min(1, frac) * (exit[2] - entry[2]);
                            argb[next] = shading.argb(elevation, triangleNormal(), t);
                        }
                        next--;
                    }
                    maxAngle = angle;
                    if (next < 0) {
                        return count; // every pixel of the column hit
                    }
                }
                if (last || count > limit) {
                    return count;
                }
                // Step across the exit edge into the neighbouring triangle.
                if (!stepAcross(exitA, exitB)) {
                    return count; // left the mosaic
                }
                count++;
                // The shared edge is the entry; find the other crossing edge.
                int[] e = crossingEdges();
                if (e == null) {
                    return count; // numerically degenerate: should not happen with a consistent sign rule
                }
                int ia = sameEdge(e[0], e[1], entryR0, entryC0, entryR1, entryC1) ? e[2] : e[0];
                int ib = sameEdge(e[0], e[1], entryR0, entryC0, entryR1, entryC1) ? e[3] : e[1];
                entry = exit;
                exit = new double[3];
                cut(ia, ib, exit);
                exitA = ia;
                exitB = ib;
            }
        }

        private int entryR0, entryC0, entryR1, entryC1;

        private boolean sameEdge(int a, int b, int r0, int c0, int r1, int c1) {
            return vr[a] == r0 && vc[a] == c0 && vr[b] == r1 && vc[b] == c1
                    || vr[a] == r1 && vc[a] == c1 && vr[b] == r0 && vc[b] == c0;
        }

        /** The two crossing edges as {a0, b0, a1, b1}, or null. */
        private int[] crossingEdges() {
            int[] out = new int[4];
            int k = 0;
            int[][] pairs = {{0, 1}, {1, 2}, {2, 0}};
            for (int[] pr : pairs) {
                if (crosses(pr[0], pr[1])) {
                    if (k == 4) {
                        return null;
                    }
                    out[k++] = pr[0];
                    out[k++] = pr[1];
                }
            }
            return k == 4 ? out : null;
        }

        /** Moves to the triangle across edge (a, b) of the current one; false when off the mosaic. */
        private boolean stepAcross(int a, int b) {
            entryR0 = vr[a];
            entryC0 = vc[a];
            entryR1 = vr[b];
            entryC1 = vc[b];
            int r = cellR, c = cellC;
            boolean horizontal = entryR0 == entryR1, vertical = entryC0 == entryC1;
            int nr, nc, nh;
            if (!horizontal && !vertical) {
                // The diagonal: the other half of the same cell.
                nr = r;
                nc = c;
                nh = 1 - half;
            } else if (horizontal) {
                if (entryR0 == r) {
                    nr = r - 1; // north edge: the cell above, its half with a south edge
                } else {
                    nr = r + 1;
                }
                nc = c;
                boolean wantSouth = nr < r;
                // Halves with a south edge: SOUTH (1) of either split; with a north edge: NORTH (0).
                nh = wantSouth ? 1 : 0;
            } else {
                if (entryC0 == c) {
                    nc = c - 1; // west edge: the cell to the west, its half with an east edge
                } else {
                    nc = c + 1;
                }
                nr = r;
                boolean wantEast = nc < c;
                boolean nwse = Triangulation.splitsNorthWestToSouthEast(nr, nc);
                // East edge: NW–SE's NORTH (0), NE–SW's SOUTH (1). West edge: NW–SE's SOUTH (1), NE–SW's NORTH (0).
                nh = wantEast ? (nwse ? 0 : 1) : (nwse ? 1 : 0);
            }
            if (nr < 0 || nc < 0 || nr >= s.rows - 1 || nc >= s.cols - 1) {
                return false;
            }
            load(nr, nc, nh);
            return true;
        }

        /** The current triangle's plane evaluated on the eye's vertical (E = N = 0): its up coordinate. */
        private double uBelowEye() {
            double[] n = triangleNormal();
            // n · (P - V0) = 0 with P = (0, 0, u).
            if (Math.abs(n[2]) < 1e-12) {
                return vp[0][2];
            }
            return vp[0][2] + (n[0] * vp[0][0] + n[1] * vp[0][1]) / n[2];
        }

        private double[] triangleNormal() {
            double ax = vp[1][0] - vp[0][0], ay = vp[1][1] - vp[0][1], az = vp[1][2] - vp[0][2];
            double bx = vp[2][0] - vp[0][0], by = vp[2][1] - vp[0][1], bz = vp[2][2] - vp[0][2];
            double nx = ay * bz - az * by, ny = az * bx - ax * bz, nz = ax * by - ay * bx;
            double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
            if (len == 0) {
                return new double[] {0, 0, 1};
            }
            if (nz < 0) {
                len = -len; // upward
            }
            return new double[] {nx / len, ny / len, nz / len};
        }

        /**
         * The triangle under the eye that the plane crosses: the one containing the eye's foot, or,
         * if rounding makes the plane miss it, a crossed triangle in the neighbouring cells whose
         * cut straddles the eye. Null if the eye is off the mosaic.
         */
        private int[] startTriangle() {
            int r = (int) Math.floor(s.eyeRow), c = (int) Math.floor(s.eyeCol);
            r = Math.max(0, Math.min(s.rows - 2, r));
            c = Math.max(0, Math.min(s.cols - 2, c));
            double y = s.eyeRow - r, x = s.eyeCol - c;
            int which = Triangulation.triangleHolding(Triangulation.splitsNorthWestToSouthEast(r, c), y, x);
            // The triangle containing the foot, unless the plane only grazes it (the foot on a vertex or
            // an edge): then the walk could set off backwards. Otherwise the neighbour whose cut
            // straddles the eye and reaches farthest ahead.
            load(r, c, which);
            double[] a = new double[3], b = new double[3];
            int[] e0 = crossingEdges();
            if (e0 != null) {
                cut(e0[0], e0[1], a);
                cut(e0[2], e0[3], b);
                if (Math.max(a[0], b[0]) > 1e-6) {
                    return new int[] {r, c, which};
                }
            }
            int[] best = null;
            double bestAhead = 1e-6;
            for (int dr = -1; dr <= 1; dr++) {
                for (int dc = -1; dc <= 1; dc++) {
                    for (int hh = 0; hh < 2; hh++) {
                        int rr = r + dr, cc = c + dc;
                        if (rr < 0 || cc < 0 || rr >= s.rows - 1 || cc >= s.cols - 1) {
                            continue;
                        }
                        load(rr, cc, hh);
                        int[] e = crossingEdges();
                        if (e == null) {
                            continue;
                        }
                        cut(e[0], e[1], a);
                        cut(e[2], e[3], b);
                        double ahead = Math.max(a[0], b[0]);
                        if (Math.min(a[0], b[0]) <= 1e-6 && ahead > bestAhead) {
                            best = new int[] {rr, cc, hh};
                            bestAhead = ahead;
                        }
                    }
                }
            }
            if (best != null) {
                load(best[0], best[1], best[2]);
            }
            return best;
        }
    }
}
