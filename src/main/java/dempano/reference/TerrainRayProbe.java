package dempano.reference;

import dempano.dem.Mosaic;
import dempano.geo.Ellipsoid;
import dempano.geo.LocalFrame;
import dempano.geo.Refraction;
import dempano.geo.Viewpoint;
import dempano.panorama.RayProbe;
import dempano.dem.Triangulation;
import dempano.util.Floors;
import dempano.util.SmallAngles;

/**
 * A ray's first crossing with the full-resolution triangulated surface (the surface the CPU
 * reference draws: mosaic cells split by {@link Triangulation}, NaN samples at sea level, refraction
 * lift k·d²/2R, cut at the range of sight), found by a crest-safe search, then regula falsi
 * (Illinois) to {@link #TOLERANCE} (relative).
 * <p>
 * The search crosses a stretch of the ray in one step only where a maximum pyramid of the DEM
 * (blocks of {@link #BLOCK_CELLS} cells, then single cells) proves the ray above every sample it
 * can pass over. Where it cannot, it computes the ray where it crosses the triangulation's edges:
 * the clearance is nearly linear between them, so its minima (crests) are computed, not stepped
 * over. The pyramid's blocks are filled on first use. A pyramid is kept for the next probe (one, the
 * last made) and reused by a probe whose mosaic holds the same samples ({@link Mosaic#sampleIdentity}:
 * the same tile grid, the same immutable tile objects in every slot, the same sea-level slots), as
 * consecutive renders over cached tiles have; any other mosaic, or a tile since collected, gets a
 * new pyramid. Thread-safe.
 */
public final class TerrainRayProbe implements RayProbe {
    /** Near the eye, where a cell is a large part of the distance, steps are at most this times the distance. */
    static final double NEAR_STEP_RATIO = 0.1;
    /** Bisection stops when the bracket is this narrow, relative to the distance. */
    static final double TOLERANCE = 1e-9;
    /** Cells per block side of the maximum pyramid's levels, finest first (each a multiple of the one before). */
    private static final int[] BLOCK_CELLS = {4, 16, 64};
    /** log2 of {@link #BLOCK_CELLS} (each a power of two). */
    private static final int[] BLOCK_SHIFT = java.util.Arrays.stream(BLOCK_CELLS).map(Integer::numberOfTrailingZeros).toArray();
    private static final int LEVELS = BLOCK_CELLS.length;
    /**
     * Horizontal metres from an anchor (an exactly computed ray point) over which the ray's path in
     * grid rows and columns is extrapolated linearly. Over 2 km the path bends by under 0.3 m at
     * 45°, 1.8 m at 80° (the change of azimuth along a geodesic); the margin allows a cell.
     */
    private static final double ANCHOR_SPAN_METRES = 2000;
    /** Margin of the extrapolated path, cells: this, plus (distance from the anchor / ANCHOR_SPAN_METRES)². */
    private static final double PATH_MARGIN_CELLS = 0.05;
    /** Height margin of the pyramid tests, metres (the closed-form geodetic height is good to 1e-7 m). */
    private static final double HEIGHT_MARGIN_METRES = 1e-3;
    /** A ray point: where it is, and how it moves there (per metre along the ray). */
    private static final int LAT = 0, LON = 1, HEIGHT = 2, LIFT = 3, GROUND = 4, RISE = 5, ROW = 6, COL = 7,
            ROW_RATE = 8, COL_RATE = 9, SIN_LAT = 10, COS_LAT = 11, SIN_LON = 12, COS_LON = 13, N_RADIUS = 14, POINT = 15;
    /** e'² = (a² − b²) / b². */
    private static final double SECOND_ECCENTRICITY_SQ = Ellipsoid.E2 / ((1 - Ellipsoid.F) * (1 - Ellipsoid.F));

    private final Mosaic mosaic;
    private final LocalFrame frame;
    private final Refraction refraction;
    private final double rangeMetres;
    private final double[] eyeFoot = new double[3];
    /** The eye's latitude and longitude, degrees, with their cosines and sines. */
    private final double eyeLatDeg, eyeLonDeg, eyeCosLat, eyeSinLat, eyeCosLon, eyeSinLon;
    /** Cell steps' horizontal length: one of the mosaic's cells, the narrower (east–west) way. */
    private final double cellStepMetres;
    /** A cell's longer side (north–south), metres. */
    private final double cellLongestMetres;
    /** Per level: block rows and columns, and each block's highest sample (NaN until first asked). */
    private final int[] blockRows, blockCols;
    private final float[][] blockMaxima;

    /**
     * A maximum pyramid and the samples it was made from: per level, each block's highest sample
     * (NaN until first asked; concurrent fills store the same values).
     */
    private record Pyramid(Mosaic.SampleIdentity samples, float[][] blockMaxima) {
        static Pyramid of(Mosaic mosaic) {
            float[][] maxima = new float[LEVELS][];
            for (int level = 0; level < LEVELS; level++) {
                maxima[level] = new float[blocks(mosaic.rows(), level) * blocks(mosaic.cols(), level)];
                java.util.Arrays.fill(maxima[level], Float.NaN);
            }
            return new Pyramid(mosaic.sampleIdentity(), maxima);
        }
    }

    /** Blocks of a pyramid level along a side of {@code samples} samples. */
    private static int blocks(int samples, int level) {
        return (samples - 1) / BLOCK_CELLS[level] + 1;
    }

    /** The last pyramid made, for the next probe over the same samples. */
    private static final java.util.concurrent.atomic.AtomicReference<Pyramid> LAST_PYRAMID =
            new java.util.concurrent.atomic.AtomicReference<>();

    /** The kept pyramid when it was made from {@code mosaic}'s samples, else a new one (then kept). */
    static float[][] pyramidFor(Mosaic mosaic) {
        Pyramid last = LAST_PYRAMID.get();
        if (last != null && last.samples().matches(mosaic)) {
            return last.blockMaxima();
        }
        Pyramid made = Pyramid.of(mosaic);
        LAST_PYRAMID.set(made);
        return made.blockMaxima();
    }
    /** The reference's vertex placement, for the final intersection with the drawn triangles. */
    private final ReferenceRenderer.Surface surface;

    public TerrainRayProbe(Mosaic mosaic, Viewpoint eye, Refraction refraction, double rangeMetres) {
        this.mosaic = mosaic;
        this.frame = eye.eyeFrame();
        this.refraction = refraction;
        this.rangeMetres = rangeMetres;
        this.surface = new ReferenceRenderer.Surface(mosaic, eye, refraction);
        Ellipsoid.toEcef(eye.latDeg(), eye.lonDeg(), 0, eyeFoot);
        this.eyeLatDeg = eye.latDeg();
        this.eyeLonDeg = eye.lonDeg();
        this.eyeCosLat = Math.cos(Math.toRadians(eyeLatDeg));
        this.eyeSinLat = Math.sin(Math.toRadians(eyeLatDeg));
        this.eyeCosLon = Math.cos(Math.toRadians(eyeLonDeg));
        this.eyeSinLon = Math.sin(Math.toRadians(eyeLonDeg));
        double cellMetres = Math.PI / 180 * Ellipsoid.A_METRES / mosaic.intervalsPerDegree();
        this.cellStepMetres = cellMetres * Math.max(0.05, Math.cos(Math.toRadians(eye.latDeg())));
        this.cellLongestMetres = cellMetres;
        this.blockMaxima = pyramidFor(mosaic);
        this.blockRows = new int[LEVELS];
        this.blockCols = new int[LEVELS];
        for (int level = 0; level < LEVELS; level++) {
            blockRows[level] = blocks(mosaic.rows(), level);
            blockCols[level] = blocks(mosaic.cols(), level);
        }
    }

    /** Horizontal metres over which {@link #nearestHitBetweenMetres} takes the ray's path in rows and columns as straight. */
    static final double STRAIGHT_PATH_METRES = 2000;

    @Override
    public double nearestHitBetweenMetres(double dx, double dy, double dz, double fromMetres, double toMetres) {
        double e = dx, n = -dz, u = dy; // jME axes (east, up, south) to ENU
        double horizontal = Math.hypot(e, n);
        double to = Math.min(toMetres, horizontal > 0 ? rangeMetres / horizontal : Double.POSITIVE_INFINITY);
        if (!(fromMetres > 0 && to > fromMetres) || (to - fromMetres) * horizontal > STRAIGHT_PATH_METRES) {
            return Double.NaN;
        }
        return trianglesBetween(e, n, u, fromMetres, to, new double[POINT], Double.NaN, Double.NaN);
    }

    @Override
    public double firstHitMetres(double dx, double dy, double dz, double fromMetres, double toMetres) {
        double e = dx, n = -dz, u = dy; // jME axes (east, up, south) to ENU
        double horizontal = Math.hypot(e, n), horizontalShare = Math.max(horizontal, 0.01);
        double tMax = Math.min(toMetres, horizontal > 0 ? rangeMetres / horizontal : Double.POSITIVE_INFINITY);
        double a = Math.max(1e-3, Math.min(fromMetres, tMax));
        double[] pa = new double[POINT], pb = new double[POINT];
        double start = clearance(e, n, u, a, pa);
        while (a > 1e-3 && !(start > 0)) {
            a /= 4; // not above there: back toward the eye, which is above the terrain
            start = clearance(e, n, u, a, pa);
        }
        if (!(start > 0)) {
            return Double.NaN;
        }
        double[] bracket;
        double ca, b, cb;
        for (int clipped = 0; ; clipped++) {
            bracket = crestSafeBracket(e, n, u, a, tMax, horizontalShare, pa, pb);
            if (bracket.length == 1) {
                // Nothing met up to the end: out to the range of sight (or off the mosaic) that is +∞, short of it undecided.
                return bracket[0] >= rangeMetres / Math.max(horizontal, 1e-300) ? Double.POSITIVE_INFINITY : Double.NaN;
            }
            a = bracket[0];
            ca = bracket[1];
            b = bracket[2];
            cb = bracket[3];
            // The bracket is a piece of the ray within a cell (or less): the drawn triangles around it decide, as
            // below (onTriangles), without first narrowing it.
            double mid = 0.5 * (a + b), window = 1.5 * cellStepMetres / horizontalShare;
            double onDrawn = trianglesBetween(e, n, u, Math.max(1e-3, mid - window), mid + window, pb, Double.NaN, UNWALKABLE);
            if (onDrawn == UNWALKABLE) {
                break;
            }
            if (!Double.isNaN(onDrawn)) {
                return onDrawn;
            }
            // None met: the ray clipped a crest of the search's surface (heights interpolated in latitude and
            // longitude) that the drawn one, planar in 3-D, holds centimetres lower, and passed over it (at 70° N a pixel
            // took such a crest 1296 m off for its hit; the drawn triangles meet its ray 1406 m off). Where the ray is
            // above the search's surface again within a few cells, the triangles up to there decide, else the search goes
            // on from there. (Not above again: the crossing below is narrowed and taken, as before.)
            double past = clipped < MAX_CLIPPED_CRESTS ? aboveAgain(e, n, u, b, tMax, horizontalShare, pb) : Double.NaN;
            if (Double.isNaN(past)) {
                break;
            }
            double between = trianglesBetween(e, n, u, Math.max(1e-3, mid - window), past + window, pb, Double.NaN, UNWALKABLE);
            if (between == UNWALKABLE) {
                break;
            }
            if (!Double.isNaN(between)) {
                return between;
            }
            a = past;
        }
        // Illinois regula falsi: the clearance is close to linear along the ray within a triangle.
        int side = 0;
        for (int i = 0; i < 100 && b - a > TOLERANCE * b; i++) {
            double m = Math.max(a, Math.min(b, (a * cb - b * ca) / (cb - ca)));
            double cm = clearance(e, n, u, m, pb);
            if (Double.isNaN(cm) || cm == 0) {
                return onTriangles(e, n, u, m, horizontalShare, pb, m);
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
        return onTriangles(e, n, u, 0.5 * (a + b), horizontalShare, pb, 0.5 * (a + b));
    }

    /** What {@link #trianglesBetween} gives where it cannot walk (the stretch leaves the mosaic or is too long). */
    private static final double UNWALKABLE = Double.NEGATIVE_INFINITY;

    /** Crests of the search's surface that the ray clips but the drawn surface does not, passed over in one search. */
    private static final int MAX_CLIPPED_CRESTS = 8;

    /**
     * The first point past {@code t} (where the ray is under the search's surface) at which it is above it again, within
     * three cells' length of ray, stepped a tenth of a cell at a time; NaN if none (or off the mosaic, or past tMax).
     */
    private double aboveAgain(double e, double n, double u, double t, double tMax, double horizontalShare, double[] scratch) {
        double step = 0.1 * cellStepMetres / horizontalShare;
        for (int i = 1; i <= 30; i++) {
            double ti = t + i * step;
            if (ti >= tMax) {
                return Double.NaN;
            }
            double c = clearance(e, n, u, ti, scratch);
            if (Double.isNaN(c)) {
                return Double.NaN;
            }
            if (c > 0) {
                return ti;
            }
        }
        return Double.NaN;
    }

    /**
     * The crossing found on the surface as the reference and the GPU draw it: planar triangles
     * between vertices placed in 3-D (the search's clearance interpolates heights in latitude and
     * longitude instead, which differs by millimetres to centimetres on steep cells: at grazing
     * incidence metres of distance). The ray is intersected with the triangles of the cells around
     * the approximate crossing, a cell and a half either way; the nearest hit there wins, else {@code otherwise}
     * (the approximation itself, or NaN to say that none was met).
     */
    private double onTriangles(double e, double n, double u, double approximate, double horizontalShare, double[] scratch,
                               double otherwise) {
        double window = 1.5 * cellStepMetres / horizontalShare;
        return trianglesBetween(e, n, u, Math.max(1e-3, approximate - window), approximate + window, scratch, otherwise, otherwise);
    }

    /**
     * The nearest hit of the ray (ENU direction) on the drawn triangles of the cells it passes over between
     * {@code from} and {@code to} metres (a straight path in rows and columns, with a margin of 0.05 cells), else
     * {@code otherwise}; {@code unwalkable} when the stretch leaves the mosaic or is longer than
     * {@link #MAX_PATH_SAMPLES} quarter cells.
     */
    private double trianglesBetween(double e, double n, double u, double from, double to, double[] scratch, double otherwise,
                                    double unwalkable) {
        clearance(e, n, u, from, scratch);
        double rowA = scratch[ROW], colA = scratch[COL];
        clearance(e, n, u, to, scratch);
        double rowB = scratch[ROW], colB = scratch[COL];
        int r0 = Floors.floorInt(Math.min(rowA, rowB) - 0.05), r1 = Floors.floorInt(Math.max(rowA, rowB) + 0.05);
        int c0 = Floors.floorInt(Math.min(colA, colB) - 0.05), c1 = Floors.floorInt(Math.max(colA, colB) + 0.05);
        // The cells along the path (a straight line in rows and columns), with their neighbours across an edge the
        // path runs along, nearest first.
        int samples = (int) Math.ceil(4 * (Math.abs(rowB - rowA) + Math.abs(colB - colA))) + 2;
        if (r0 < 0 || c0 < 0 || r1 + 1 >= mosaic.rows() || c1 + 1 >= mosaic.cols() || samples > MAX_PATH_SAMPLES) {
            return unwalkable;
        }
        // Visited cells (this walk's: keys carry its stamp) and placed vertices (this probe's, kept from walk to walk:
        // neighbouring pixels' rays cross the same cells), direct-mapped by grid index: a vertex serves four cells, and
        // the path meets a cell again at its next samples. A collision costs a recomputation of the same value.
        WalkTables w = WalkTables.of(this);
        long stamp = w.nextWalk();
        long[] cellKey = w.cellKey;
        double best = Double.POSITIVE_INFINITY;
        // Past a hit, cells two cells' length of ray farther on hold only farther hits: the walk stops there.
        double beyond = 2 * cellLongestMetres / Math.max(Math.hypot(e, n), 0.01);
        int lastRowLo = Integer.MIN_VALUE, lastRowHi = 0, lastColLo = 0, lastColHi = 0;
        for (int i = 0; i <= samples; i++) {
            double f = (double) i / samples, row = rowA + f * (rowB - rowA), col = colA + f * (colB - colA);
            if (from + f * (to - from) > best + beyond) {
                break;
            }
            int rowLo = Floors.floorInt(row - 0.05), rowHi = Floors.floorInt(row + 0.05);
            int colLo = Floors.floorInt(col - 0.05), colHi = Floors.floorInt(col + 0.05);
            if (rowLo == lastRowLo && rowHi == lastRowHi && colLo == lastColLo && colHi == lastColHi) {
                continue; // the sample before lay on the same cells (a cell holds about four samples): all visited
            }
            lastRowLo = rowLo;
            lastRowHi = rowHi;
            lastColLo = colLo;
            lastColHi = colHi;
            for (int k = 0; k < 4; k++) {
                int r = (k & 1) == 0 ? rowLo : rowHi, c = (k & 2) == 0 ? colLo : colHi;
                long cell = stamp + (long) r * mosaic.cols() + c;
                int slot = (int) (cell & (CACHE_SLOTS - 1));
                if (r < r0 || r > r1 || c < c0 || c > c1 || cellKey[slot] == cell) {
                    continue;
                }
                cellKey[slot] = cell;
                double t = cellHit(e, n, u, r, c, w);
                if (t >= from && t <= to && t < best) {
                    best = t;
                }
            }
        }
        return best < Double.POSITIVE_INFINITY ? best : otherwise;
    }

    /**
     * Distance along the unit ray to the nearer of cell (r, c)'s two triangles, +∞ if it misses both. One call site
     * for its corners and one for its triangles: inlined four and two times over into the walk, they made the JIT
     * recompile a large method (0.5–1.1 s of server compiler time in a JVM's first four renders).
     */
    private double cellHit(double e, double n, double u, int r, int c, WalkTables w) {
        double[][] corner = w.corners; // Triangulation.NW, NE, SW, SE
        for (int k = 0; k < 4; k++) {
            vertex(r + (k >> 1), c + (k & 1), w.vertexKey, w.vertexAt, corner[k]);
        }
        boolean nwToSe = Triangulation.splitsNorthWestToSouthEast(r, c);
        double best = Double.POSITIVE_INFINITY;
        for (int k = 0; k < 2; k++) {
            double hit = rayTriangle(e, n, u, corner[Triangulation.corner(nwToSe, k, 0)],
                    corner[Triangulation.corner(nwToSe, k, 1)], corner[Triangulation.corner(nwToSe, k, 2)], w.tri);
            if (hit < best) { // (not Math.min, which the client compiler calls: a hit is positive or +∞, never NaN)
                best = hit;
            }
        }
        return best;
    }

    /** Slots of {@link #trianglesBetween}'s cell table (a power of two). */
    private static final int CACHE_SLOTS = 64;
    /** Slots of the placed-vertex cache (a power of two): 128 KB a thread. */
    static final int VERTEX_SLOTS = 4096;

    /**
     * A thread's tables for {@link #trianglesBetween}, so that a walk allocates nothing: the cells visited by the
     * current walk, and the vertices placed by the probe that last used them.
     * <p>
     * Cache contract. A vertex's position is a pure function of its grid index for one probe (its mosaic's
     * immutable samples, its eye and refraction), so placed vertices are kept from walk to walk, keyed by grid
     * index: what invalidates them is another probe. The tables belong to one probe at a time ({@link #of}); a walk
     * by any other probe on the thread (another render, another eye, another DEM) empties them first. Cell keys
     * carry the walk's stamp (+2^40 a walk; a mosaic has far fewer samples than 2^40), so no cell is taken as
     * visited by an earlier walk; when the stamp wraps round (every 2^24 walks) the cell table is emptied.
     */
    static final class WalkTables {
        private static final ThreadLocal<WalkTables> OF_THREAD = ThreadLocal.withInitial(WalkTables::new);

        final long[] vertexKey = new long[VERTEX_SLOTS], cellKey = new long[CACHE_SLOTS];
        final double[] vertexAt = new double[3 * VERTEX_SLOTS];
        final double[][] corners = new double[4][3];
        final double[] tri = new double[9];
        /** Weak: a pool thread's tables must not keep a finished render's probe (and its mosaic) alive. */
        private java.lang.ref.WeakReference<TerrainRayProbe> owner = new java.lang.ref.WeakReference<>(null);
        private long stamp;

        private WalkTables() {
            java.util.Arrays.fill(cellKey, -1);
        }

        /** The thread's tables, emptied of another probe's vertices. */
        static WalkTables of(TerrainRayProbe probe) {
            WalkTables w = OF_THREAD.get();
            if (w.owner.get() != probe) {
                java.util.Arrays.fill(w.vertexKey, -1);
                w.owner = new java.lang.ref.WeakReference<>(probe);
            }
            return w;
        }

        long nextWalk() {
            stamp += 1L << 40;
            if (stamp == 0) {
                java.util.Arrays.fill(cellKey, -1);
                stamp = 1L << 40;
            }
            return stamp;
        }
    }
    /** Longest path {@link #trianglesBetween} walks, in samples of a quarter cell. */
    private static final int MAX_PATH_SAMPLES = 4096;

    /** Vertex (r, c)'s position as the reference places it, from the cache where it is there. */
    private void vertex(int r, int c, long[] keys, double[] positions, double[] out) {
        long key = (long) r * mosaic.cols() + c;
        int slot = (int) ((key ^ (key >>> 12)) & (VERTEX_SLOTS - 1)), o = 3 * slot; // folded: a row apart is not a slot apart
        if (keys[slot] != key) {
            surface.position(r, c, out);
            keys[slot] = key;
            positions[o] = out[0];
            positions[o + 1] = out[1];
            positions[o + 2] = out[2];
        } else {
            out[0] = positions[o];
            out[1] = positions[o + 1];
            out[2] = positions[o + 2];
        }
    }

    /** Distance along the unit ray from the eye (ENU origin) to triangle (p, q, s); +∞ if missed. {@code tri}: 9 doubles of scratch. */
    private static double rayTriangle(double dx, double dy, double dz, double[] p, double[] q, double[] s, double[] tri) {
        for (int a = 0; a < 3; a++) {
            tri[a] = p[a];
            tri[3 + a] = q[a] - p[a];
            tri[6 + a] = s[a] - p[a];
        }
        return dempano.panorama.SeenTriangles.rayTriangleMetres(tri, 0, dx, dy, dz);
    }

    /**
     * The crest-safe search from a point above the surface: {a, clearance(a), b, clearance(b)} with
     * the first crossing between a and b; or {t} when there is none before t: t = tMax (nothing
     * met; +∞ or undecided by the caller's rule), or +∞ (the ray left the mosaic).
     * <p>
     * From an anchor (a point computed exactly, with its height's rate of change and its rows' and
     * columns' rates) a stretch of the ray is crossed without computing it when a pyramid level
     * proves it above every sample it can pass over: its height is at least the anchor's tangent
     * line (the height above a convex ellipsoid is convex along a straight line), its lift at most
     * that of its far end, its cells within the linear extrapolation's rectangle widened by a margin.
     * Where even single cells may reach the ray, the ray is computed where it crosses the cell edges
     * and diagonals of the triangulation: between them the clearance is nearly linear, so a crest
     * (a minimum of the clearance, on an edge) is not stepped over.
     */
    private double[] crestSafeBracket(double e, double n, double u, double a, double tMax, double horizontalShare,
                                      double[] anchor, double[] scratch) {
        double[] dir = new double[3];
        frame.enuDirectionToEcef(e, n, u, dir);
        double anchorT = a, t = a, ct = clearance(e, n, u, a, anchor);
        rates(anchor, dir);
        int level = LEVELS - 1;
        double[] crossings = new double[16];
        boolean cellStepNeedsAnchor = false;
        while (true) {
            if (t >= tMax) {
                return new double[] {tMax};
            }
            if (cellStepNeedsAnchor || (t - anchorT) * horizontalShare >= ANCHOR_SPAN_METRES) {
                cellStepNeedsAnchor = false;
                double c = clearance(e, n, u, t, anchor);
                if (Double.isNaN(c)) {
                    return new double[] {Double.POSITIVE_INFINITY};
                }
                if (!(c > 0)) { // proven above up to here: only rounding can put it under
                    return new double[] {t - 1e-6 * t, ct, t, c};
                }
                rates(anchor, dir);
                anchorT = t;
                ct = c;
            }
            if (level >= 0) {
                double t1 = Math.min(t + BLOCK_CELLS[level] * cellStepMetres / horizontalShare, tMax);
                if (above(level, anchor, anchorT, t, t1, horizontalShare)) {
                    t = t1;
                    level = Math.min(level + 1, LEVELS - 1);
                } else {
                    level--;
                }
                continue;
            }
            // One cell or less (near the eye, a tenth of the distance), tested cell by cell.
            double t1 = Math.min(t + Math.min(NEAR_STEP_RATIO * t, cellStepMetres / horizontalShare), tMax);
            if (above(-1, anchor, anchorT, t, t1, horizontalShare)) {
                t = t1;
                level = 0;
                continue;
            }
            if (anchorT != t) {
                // The edges are crossed where the path extrapolated from the anchor says, up to 2 km back: a metre or two
                // off there (0.02 cells), beside a crest on an edge, a ray grazing it by less would step over it (one
                // pixel of Mount Washington's panorama, whose ray met a ridge 29.8 km off, passed for 41.9 km searched
                // from 28.7 km, met from 28.8 km). From an anchor where the step starts the path is good to a millimetre
                // (and the cell may then be proven above after all).
                cellStepNeedsAnchor = true;
                continue;
            }
            int count = edgeCrossings(anchor, anchorT, t, t1, crossings);
            double previous = t, cPrevious = ct;
            for (int i = 0; i <= count; i++) {
                double tc = i < count ? crossings[i] : t1;
                double c = clearance(e, n, u, tc, scratch);
                if (Double.isNaN(c)) {
                    return new double[] {Double.POSITIVE_INFINITY}; // off the mosaic: nothing drawn there
                }
                if (c <= 0) {
                    return new double[] {previous, cPrevious, tc, c};
                }
                previous = tc;
                cPrevious = c;
            }
            // Above at the cell's far end: a new anchor there, computed anyway.
            System.arraycopy(scratch, 0, anchor, 0, POINT);
            rates(anchor, dir);
            anchorT = t1;
            ct = cPrevious;
            t = t1;
            level = 0;
        }
    }

    /**
     * Whether the ray between t0 and t1 (metres, anchor ≤ t0 < t1) is provably above every sample of
     * the level's blocks it can pass over (level −1: single cells), lifted by refraction.
     */
    private boolean above(int level, double[] anchor, double anchorT, double t0, double t1, double horizontalShare) {
        double lowest = anchor[HEIGHT] + lesser(anchor[RISE] * (t0 - anchorT), anchor[RISE] * (t1 - anchorT)) - HEIGHT_MARGIN_METRES;
        double reach = (t1 - anchorT) * horizontalShare;
        double lift = greater(anchor[LIFT], refraction.liftMetres(anchor[GROUND] + reach));
        double margin = PATH_MARGIN_CELLS + (reach / ANCHOR_SPAN_METRES) * (reach / ANCHOR_SPAN_METRES);
        double row0 = anchor[ROW] + anchor[ROW_RATE] * (t0 - anchorT), row1 = anchor[ROW] + anchor[ROW_RATE] * (t1 - anchorT);
        double col0 = anchor[COL] + anchor[COL_RATE] * (t0 - anchorT), col1 = anchor[COL] + anchor[COL_RATE] * (t1 - anchorT);
        int r0 = Floors.floorInt(lesser(row0, row1) - margin), r1 = Floors.floorInt(greater(row0, row1) + margin) + 1;
        int c0 = Floors.floorInt(lesser(col0, col1) - margin), c1 = Floors.floorInt(greater(col0, col1) + margin) + 1;
        if (r0 < 0 || c0 < 0 || r1 >= mosaic.rows() || c1 >= mosaic.cols()) {
            return false; // may leave the mosaic: decided by computing the ray
        }
        double ceiling = lowest - lift;
        if (level < 0) {
            for (int r = r0; r <= r1; r++) {
                for (int c = c0; c <= c1; c++) {
                    if (height(r, c) >= ceiling) {
                        return false;
                    }
                }
            }
            return true;
        }
        int shift = BLOCK_SHIFT[level]; // r >> shift = r / cells (r ≥ 0), without a division
        for (int br = r0 >> shift, brEnd = r1 >> shift; br <= brEnd; br++) {
            for (int bc = c0 >> shift, bcEnd = c1 >> shift; bc <= bcEnd; bc++) {
                if (blockMaximum(level, br, bc) >= ceiling) {
                    return false;
                }
            }
        }
        return true;
    }

    /**
     * Math.min for {@link #above}, small enough for the client compiler to inline (it calls Math.min): NaN if either
     * is NaN, as Math.min; of +0 and −0 it may give either, which the sums it feeds do not tell apart.
     */
    private static double lesser(double a, double b) {
        return a < b || a != a ? a : b;
    }

    /** Math.max likewise ({@link #lesser}). */
    private static double greater(double a, double b) {
        return a > b || a != a ? a : b;
    }

    /**
     * Where the extrapolated path between t0 and t1 crosses a grid line or a cell's diagonal, in
     * increasing order; returns how many (at most {@code out.length}).
     */
    private static int edgeCrossings(double[] anchor, double anchorT, double t0, double t1, double[] out) {
        double rowRate = anchor[ROW_RATE], colRate = anchor[COL_RATE];
        double row0 = anchor[ROW] + rowRate * (t0 - anchorT), col0 = anchor[COL] + colRate * (t0 - anchorT);
        double row1 = anchor[ROW] + rowRate * (t1 - anchorT), col1 = anchor[COL] + colRate * (t1 - anchorT);
        int count = 0;
        for (int k = Floors.floorInt(Math.min(row0, row1)) + 1; k <= Math.max(row0, row1) && count < out.length / 2; k++) {
            out[count++] = t0 + (k - row0) / rowRate;
        }
        for (int k = Floors.floorInt(Math.min(col0, col1)) + 1; k <= Math.max(col0, col1) && count < out.length / 2; k++) {
            out[count++] = t0 + (k - col0) / colRate;
        }
        java.util.Arrays.sort(out, 0, count);
        // Each piece between grid crossings lies in one cell: where does it cross that cell's diagonal?
        int pieces = count + 1;
        for (int i = 0; i < pieces && count < out.length; i++) {
            double ta = i == 0 ? t0 : out[i - 1], tb = i < pieces - 1 ? out[i] : t1;
            double tm = 0.5 * (ta + tb);
            double rm = row0 + rowRate * (tm - t0), cm = col0 + colRate * (tm - t0);
            int r = Floors.floorInt(rm), c = Floors.floorInt(cm);
            double td;
            if (Triangulation.splitsNorthWestToSouthEast(r, c)) { // v = w: row − col = r − c
                td = t0 + ((r - c) - (row0 - col0)) / (rowRate - colRate);
            } else { // v + w = 1: row + col = r + c + 1
                td = t0 + ((r + c + 1) - (row0 + col0)) / (rowRate + colRate);
            }
            if (td > ta && td < tb) {
                out[count++] = td;
            }
        }
        java.util.Arrays.sort(out, 0, count);
        return count;
    }

    /**
     * Highest sample of block (br, bc) of a level, border samples included (NaN samples count as
     * the sea level the probe puts them at). Filled on first use: concurrent probes may each compute
     * a block, and they store the same value, so no lock is needed.
     */
    private float blockMaximum(int level, int br, int bc) {
        float[] maxima = blockMaxima[level];
        int index = br * blockCols[level] + bc;
        float m = maxima[index];
        if (!Float.isNaN(m)) {
            return m;
        }
        if (level == 0) {
            fillBand(br);
            return maxima[index];
        }
        m = Float.NEGATIVE_INFINITY;
        int ratio = BLOCK_CELLS[level] / BLOCK_CELLS[level - 1];
        int rEnd = Math.min(blockRows[level - 1] - 1, (br + 1) * ratio), cEnd = Math.min(blockCols[level - 1] - 1, (bc + 1) * ratio);
        for (int r = br * ratio; r <= rEnd; r++) { // one finer block beyond the border: the shared border samples
            for (int c = bc * ratio; c <= cEnd; c++) {
                m = Math.max(m, blockMaximum(level - 1, r, c));
            }
        }
        maxima[index] = m;
        return m;
    }

    /**
     * Fills every finest block of block row {@code br} at once, reading its sample rows a tile's run
     * at a time (one sample at a time through {@link Mosaic#sample} was a tenth of a render's CPU).
     * Concurrent fills of one band store the same values.
     */
    private void fillBand(int br) {
        int cells = BLOCK_CELLS[0], cols = mosaic.cols(), blocks = blockCols[0];
        float[] band = new float[blocks];
        java.util.Arrays.fill(band, Float.NEGATIVE_INFINITY);
        float[] row = new float[cols];
        int rEnd = Math.min(mosaic.rows() - 1, (br + 1) * cells);
        for (int r = br * cells; r <= rEnd; r++) {
            mosaic.sampleRow(r, 0, cols, row, 0);
            for (int c = 0; c < cols; c++) {
                float h = Float.isNaN(row[c]) ? 0 : row[c]; // NaN counts as sea level, as in height()
                int b = c / cells;
                if (h > band[b]) {
                    band[b] = h;
                }
                if (c % cells == 0 && b > 0 && h > band[b - 1]) {
                    band[b - 1] = h; // a block's east border sample is its neighbour's first
                }
            }
        }
        System.arraycopy(band, 0, blockMaxima[0], br * blocks, blocks);
    }

    /** Height of the ray's point at distance t above the (lifted) surface, metres; NaN off the mosaic. */
    double clearance(double e, double n, double u, double t) {
        return clearance(e, n, u, t, new double[POINT]);
    }

    /**
     * The same, also filling {@code point} with where the ray is: latitude and longitude (degrees),
     * height above the ellipsoid and the refraction lift of the surface there (metres).
     */
    private double clearance(double e, double n, double u, double t, double[] point) {
        double[] ecef = new double[3];
        frame.enuToEcef(t * e, t * n, t * u, ecef);
        double x = ecef[0], y = ecef[1], z = ecef[2];
        double p = Math.sqrt(x * x + y * y);
        if (p < 1e3) {
            double c = clearanceNearPole(x, y, z, point);
            double lat = Math.toRadians(point[LAT]), lon = Math.toRadians(point[LON]), sinLat = Math.sin(lat);
            storeTrig(point, sinLat, Math.cos(lat), Math.sin(lon), Math.cos(lon));
            return c;
        }
        // Bowring's closed form (one step from the parametric latitude): under 1e-7 m in height
        // and 1e-12 rad in latitude for terrestrial heights (TerrainRayProbeTest), and trig-free,
        // which matters here: the probe runs a dozen of these per probed pixel.
        double za = z * Ellipsoid.A_METRES, pb = p * Ellipsoid.B_METRES, q = Math.sqrt(za * za + pb * pb);
        double st = za / q, ct = pb / q;
        double num = z + SECOND_ECCENTRICITY_SQ * Ellipsoid.B_METRES * st * st * st;
        double den = p - Ellipsoid.E2 * Ellipsoid.A_METRES * ct * ct * ct;
        double r = Math.sqrt(num * num + den * den), sinLat = num / r, cosLat = den / r;
        double nRadius = Ellipsoid.primeVerticalRadiusOfSinMetres(sinLat);
        double height = p * cosLat + z * sinLat - Ellipsoid.A_METRES * Ellipsoid.A_METRES / nRadius;
        // Latitude and longitude as angles from the eye's (atan2's fdlibm call is native in JDK 17, and this
        // runs a dozen times per probed pixel): within 1e-15 rad of atan2, SmallAnglesTest.
        double latDeg = eyeLatDeg + Math.toDegrees(SmallAngles.angleFrom(num, den, eyeCosLat, eyeSinLat));
        double lonDeg = eyeLonDeg + Math.toDegrees(SmallAngles.angleFrom(y, x, eyeCosLon, eyeSinLon));
        if (lonDeg > 180) {
            lonDeg -= 360;
        } else if (lonDeg < -180) {
            lonDeg += 360;
        }
        double fx = nRadius * cosLat * x / p - eyeFoot[0], fy = nRadius * cosLat * y / p - eyeFoot[1],
                fz = nRadius * (1 - Ellipsoid.E2) * sinLat - eyeFoot[2];
        double ground = Refraction.groundDistanceFromChordMetres(Math.sqrt(fx * fx + fy * fy + fz * fz));
        double c = clearanceAt(latDeg, lonDeg, height, ground, point);
        storeTrig(point, sinLat, cosLat, y / p, x / p);
        return c;
    }

    /** Stores the point's latitude and longitude as sines and cosines, and its prime-vertical radius (for {@link #rates}). */
    private static void storeTrig(double[] point, double sinLat, double cosLat, double sinLon, double cosLon) {
        point[SIN_LAT] = sinLat;
        point[COS_LAT] = cosLat;
        point[SIN_LON] = sinLon;
        point[COS_LON] = cosLon;
        point[N_RADIUS] = Ellipsoid.primeVerticalRadiusOfSinMetres(sinLat);
    }

    /**
     * Fills an anchor's rates per metre along the ray: of its height (the ray direction along the
     * ellipsoid normal there) and of its fractional grid row and column. Only anchors need them.
     *
     * @param dir the ray's unit direction in ECEF axes
     */
    private void rates(double[] point, double[] dir) {
        double sinLat = point[SIN_LAT], cosLat = point[COS_LAT], sinLon = point[SIN_LON], cosLon = point[COS_LON];
        double nRadius = point[N_RADIUS], height = point[HEIGHT];
        double rise = cosLat * (cosLon * dir[0] + sinLon * dir[1]) + sinLat * dir[2];
        double east = -sinLon * dir[0] + cosLon * dir[1];
        double north = -sinLat * (cosLon * dir[0] + sinLon * dir[1]) + cosLat * dir[2];
        double mRadius = Ellipsoid.meridianRadiusOfSinMetres(sinLat);
        double ipd = mosaic.intervalsPerDegree();
        point[RISE] = rise;
        point[ROW_RATE] = -Math.toDegrees(north / (mRadius + height)) * ipd;
        point[COL_RATE] = Math.toDegrees(east / ((nRadius + height) * Math.max(cosLat, 1e-9))) * ipd;
    }

    /** The same within 1 km of the axis, by the iterative conversion (Bowring's p divides there). */
    double clearanceNearPole(double x, double y, double z, double[] point) {
        double[] geo = Ellipsoid.toGeodetic(x, y, z);
        double[] foot = new double[3];
        Ellipsoid.toEcef(geo[0], geo[1], 0, foot);
        return clearanceAt(geo[0], geo[1], geo[2], Refraction.groundDistanceBetweenFeetMetres(foot, eyeFoot), point);
    }

    private double clearanceAt(double latDeg, double lonDeg, double heightMetres, double groundDistanceMetres, double[] point) {
        double lift = refraction.liftMetres(groundDistanceMetres);
        double row = mosaic.rowOf(latDeg), col = mosaic.colOf(lonDeg);
        point[LAT] = latDeg;
        point[LON] = lonDeg;
        point[HEIGHT] = heightMetres;
        point[LIFT] = lift;
        point[GROUND] = groundDistanceMetres;
        point[ROW] = row;
        point[COL] = col;
        int r = Floors.floorInt(row), c = Floors.floorInt(col);
        if (r < 0 || c < 0 || r + 1 >= mosaic.rows() || c + 1 >= mosaic.cols()) {
            return Double.NaN;
        }
        double v = row - r, w = col - c; // south and east fractions
        double nw = height(r, c), ne = height(r, c + 1), sw = height(r + 1, c), se = height(r + 1, c + 1);
        double surface = Triangulation.heightIn(r, c, nw, ne, sw, se, v, w);
        return heightMetres - surface - lift;
    }

    private double height(int r, int c) {
        float h = mosaic.sample(r, c);
        return Float.isNaN(h) ? 0 : h;
    }
}
