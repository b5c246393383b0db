package dempano.orient;

import dempano.panorama.Panorama;
import dempano.panorama.PanoramaGeometry;
import dempano.panorama.Silhouettes;

/**
 * The depth edges of a 360° panorama (its skyline and every ridge standing in front of farther terrain) and their
 * distance transform: for any azimuth and elevation, the angular distance to the nearest depth edge. Photo edges
 * are scored against it by a chamfer match (see {@link OrientationEstimator}). Pure arithmetic on the distance map;
 * immutable.
 *
 * <p>A pixel is an edge when {@link Silhouettes#isEdge} says so and the terrain above it is at least
 * {@link #MIN_DEPTH_RATIO} times farther (or sky): small distance steps are rarely visible in a photo. The edge
 * lies on the pixel's top boundary, at azimuth (c + 0.5)/ppd and elevation top − r/ppd (as in
 * {@link HorizonProfile}). The transform is the exact Euclidean one (Felzenszwalb and Huttenlocher), in panorama
 * pixels, wrapping around in azimuth.
 */
public final class SilhouetteField {
    /** The far side of a depth edge is at least this many times farther than the near side. */
    public static final double MIN_DEPTH_RATIO = 1.25;
    /** Distances are capped here, panorama pixels. */
    static final double CAP_PX = 40;

    private final float[] distancePx;
    private final int width, height;
    private final double pixelsPerDegree, topElevationDeg;
    private final int edgePixels;

    /**
     * @param edge            edge flags, row-major, row 0 on top
     * @param width           columns (360·ppd)
     * @param height          rows
     * @param pixelsPerDegree panorama pixels per degree
     * @param topElevationDeg elevation of row 0's top boundary, degrees
     */
    public SilhouetteField(boolean[] edge, int width, int height, double pixelsPerDegree, double topElevationDeg) {
        if (edge.length != width * height || width < 4 || height < 2) {
            throw new IllegalArgumentException("a silhouette field needs width × height edge flags");
        }
        this.width = width;
        this.height = height;
        this.pixelsPerDegree = pixelsPerDegree;
        this.topElevationDeg = topElevationDeg;
        this.distancePx = transform(edge, width, height);
        int n = 0;
        for (boolean e : edge) {
            n += e ? 1 : 0;
        }
        this.edgePixels = n;
    }

    /** The depth edges of a panorama's distance map (sky = +∞). */
    public static SilhouetteField of(Panorama panorama) {
        return of(panorama.distanceArray(), panorama.geometry());
    }

    /** The depth edges of a distance map (row-major, row 0 on top, sky +∞ or NaN) in a panorama layout. */
    public static SilhouetteField of(float[] distanceMetres, PanoramaGeometry geometry) {
        int w = geometry.widthPx(), h = geometry.heightPx();
        boolean[] edge = new boolean[w * h];
        for (int r = 1; r < h; r++) {
            for (int c = 0; c < w; c++) {
                int i = r * w + c;
                if (Silhouettes.isEdge(distanceMetres, w, h, c, r)) {
                    double above = distanceMetres[i - w];
                    edge[i] = !Double.isFinite(above) || above >= MIN_DEPTH_RATIO * distanceMetres[i];
                }
            }
        }
        return new SilhouetteField(edge, w, h, geometry.pixelsPerDegree(), geometry.topElevationDeg());
    }

    public double pixelsPerDegree() {
        return pixelsPerDegree;
    }

    /** Number of edge pixels. */
    public int edgePixels() {
        return edgePixels;
    }

    /**
     * Angular distance from (azimuth, elevation) to the nearest depth edge, degrees (bilinear between grid points;
     * at most {@link #CAP_PX}/ppd; outside the panorama's rows, the cap).
     */
    public double distanceDeg(double azimuthDeg, double elevationDeg) {
        double x = azimuthDeg * pixelsPerDegree - 0.5, y = (topElevationDeg - elevationDeg) * pixelsPerDegree;
        if (!(y >= 0 && y <= height - 1)) {
            return CAP_PX / pixelsPerDegree;
        }
        double fx = Math.floor(x), fy = Math.floor(y);
        int c0 = Math.floorMod((int) fx, width), c1 = (c0 + 1) % width, r0 = (int) fy, r1 = Math.min(height - 1, r0 + 1);
        double tx = x - fx, ty = y - fy;
        double a = distancePx[r0 * width + c0], b = distancePx[r0 * width + c1];
        double c = distancePx[r1 * width + c0], d = distancePx[r1 * width + c1];
        return ((a + tx * (b - a)) * (1 - ty) + (c + tx * (d - c)) * ty) / pixelsPerDegree;
    }

    /**
     * Exact Euclidean distance transform, capped at {@link #CAP_PX}, wrapping in x: the columns' squared distances,
     * then the rows' (each pass spread over the cores a column or row at a time; the same values as one thread).
     */
    static float[] transform(boolean[] edge, int w, int h) {
        double inf = 1e12;
        double[] sq = new double[w * h];
        dempano.util.Parallel.forEachWorker(w, nextColumn -> {
            double[] col = new double[h], colOut = new double[h];
            for (int c = nextColumn.getAsInt(); c < w; c = nextColumn.getAsInt()) {
                for (int r = 0; r < h; r++) {
                    col[r] = edge[r * w + c] ? 0 : inf;
                }
                dt1d(col, h, colOut);
                for (int r = 0; r < h; r++) {
                    sq[r * w + c] = colOut[r];
                }
            }
        });
        int pad = (int) Math.ceil(CAP_PX) + 1, n = w + 2 * pad;
        float[] out = new float[w * h];
        dempano.util.Parallel.forEachWorker(h, nextRow -> {
            double[] row = new double[n], rowOut = new double[n];
            for (int r = nextRow.getAsInt(); r < h; r = nextRow.getAsInt()) {
                for (int k = 0; k < n; k++) {
                    row[k] = sq[r * w + Math.floorMod(k - pad, w)];
                }
                dt1d(row, n, rowOut);
                for (int c = 0; c < w; c++) {
                    out[r * w + c] = (float) Math.min(CAP_PX, Math.sqrt(rowOut[c + pad]));
                }
            }
        });
        return out;
    }

    /** One-dimensional squared distance transform of sampled function f (lower envelope of parabolas). */
    static void dt1d(double[] f, int n, double[] d) {
        int[] v = new int[n];
        double[] z = new double[n + 1];
        int k = 0;
        v[0] = 0;
        z[0] = Double.NEGATIVE_INFINITY;
        z[1] = Double.POSITIVE_INFINITY;
        for (int q = 1; q < n; q++) {
            double s;
            while (true) {
                int p = v[k];
                s = ((f[q] + (double) q * q) - (f[p] + (double) p * p)) / (2.0 * q - 2.0 * p);
                if (s <= z[k] && k > 0) {
                    k--;
                } else {
                    break;
                }
            }
            if (s <= z[k]) {
                // k == 0 and the new parabola is lower everywhere.
                v[0] = q;
                z[0] = Double.NEGATIVE_INFINITY;
                z[1] = Double.POSITIVE_INFINITY;
                continue;
            }
            k++;
            v[k] = q;
            z[k] = s;
            z[k + 1] = Double.POSITIVE_INFINITY;
        }
        k = 0;
        for (int q = 0; q < n; q++) {
            while (z[k + 1] < q) {
                k++;
            }
            double dq = q - v[k];
            d[q] = dq * dq + f[v[k]];
        }
    }
}
