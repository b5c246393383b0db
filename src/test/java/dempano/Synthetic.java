package dempano;

import dempano.dem.HgtTile;
import dempano.dem.InMemoryDem;
import dempano.dem.TileId;
import dempano.geo.LocalFrame;
import java.util.ArrayList;
import java.util.List;
import java.util.function.DoubleBinaryOperator;

/** Synthetic DEMs from analytic terrain, and an independent double-precision ray march through it. */
public final class Synthetic {
    /** Samples per tile side of synthetic tiles (6 arc-seconds). */
    public static final int N = 601;

    private Synthetic() {
    }

    /** Tiles rows × cols from (latS, lonW), sampled from f(lat, lon) in metres. */
    public static InMemoryDem dem(DoubleBinaryOperator f, int latS, int lonW, int rows, int cols) {
        List<HgtTile> tiles = new ArrayList<>();
        for (int i = 0; i < rows; i++) {
            for (int j = 0; j < cols; j++) {
                float[] h = new float[N * N];
                for (int r = 0; r < N; r++) {
                    for (int c = 0; c < N; c++) {
                        h[r * N + c] = (float) f.applyAsDouble(latS + i + 1 - r / (N - 1.0), lonW + j + c / (N - 1.0));
                    }
                }
                tiles.add(HgtTile.of(TileId.of(latS + i, lonW + j), N, h, "synthetic"));
            }
        }
        return new InMemoryDem("synthetic", tiles);
    }

    /**
     * Tiles at the given south-west corners ({lat, lon} pairs, lon in −180…179), n samples a side,
     * sampled from f(lat, lon) with lon in the tile's own range.
     */
    public static InMemoryDem tiles(DoubleBinaryOperator f, int n, int[]... corners) {
        List<HgtTile> tiles = new ArrayList<>();
        for (int[] sw : corners) {
            float[] h = new float[n * n];
            for (int r = 0; r < n; r++) {
                for (int c = 0; c < n; c++) {
                    h[r * n + c] = (float) f.applyAsDouble(sw[0] + 1 - r / (n - 1.0), sw[1] + c / (n - 1.0));
                }
            }
            tiles.add(HgtTile.of(TileId.of(sw[0], sw[1]), n, h, "synthetic"));
        }
        return new InMemoryDem("synthetic", tiles);
    }

    /**
     * Writes an SRTM3 file (1201 × 1201 big-endian int16, whole metres) of the tile with south-west corner
     * (latS, lonW), sampled from f(lat, lon) in metres; returns the file.
     */
    public static java.nio.file.Path writeHgt(java.nio.file.Path dir, DoubleBinaryOperator f, int latS, int lonW)
            throws java.io.IOException {
        int n = 1201;
        java.nio.ByteBuffer bytes = java.nio.ByteBuffer.allocate(2 * n * n);
        for (int r = 0; r < n; r++) {
            for (int c = 0; c < n; c++) {
                bytes.putShort((short) Math.round(f.applyAsDouble(latS + 1 - r / (n - 1.0), lonW + c / (n - 1.0))));
            }
        }
        java.nio.file.Path file = dir.resolve(TileId.of(latS, lonW).name() + ".hgt");
        java.nio.file.Files.write(file, bytes.array());
        return file;
    }

    /** All tiles of a block of rows × cols from (latS, lonW), wrapping longitude at ±180. */
    public static int[][] block(int latS, int lonW, int rows, int cols) {
        int[][] out = new int[rows * cols][];
        for (int i = 0; i < rows; i++) {
            for (int j = 0; j < cols; j++) {
                int lon = lonW + j;
                out[i * cols + j] = new int[] {latS + i, lon >= 180 ? lon - 360 : lon};
            }
        }
        return out;
    }

    /** March a ray in double precision through the analytic terrain (5 m steps), then bisect; +∞ if none within max. */
    public static double rayMarch(LocalFrame eye, DoubleBinaryOperator terrain, double azDeg, double elDeg, double max) {
        double az = Math.toRadians(azDeg), el = Math.toRadians(elDeg);
        double de = Math.cos(el) * Math.sin(az), dn = Math.cos(el) * Math.cos(az), du = Math.sin(el);
        double step = 5, prev = 0;
        for (double t = step; t <= max; t += step) {
            if (below(eye, terrain, de * t, dn * t, du * t)) {
                double lo = prev, hi = t;
                for (int i = 0; i < 60; i++) {
                    double mid = (lo + hi) / 2;
                    if (below(eye, terrain, de * mid, dn * mid, du * mid)) {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                return (lo + hi) / 2;
            }
            prev = t;
        }
        return Double.POSITIVE_INFINITY;
    }

    private static boolean below(LocalFrame eye, DoubleBinaryOperator terrain, double e, double n, double u) {
        double[] g = eye.toGeodetic(e, n, u);
        return g[2] <= terrain.applyAsDouble(g[0], g[1]);
    }
}
