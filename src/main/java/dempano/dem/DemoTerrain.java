package dempano.dem;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;

/**
 * The demo DEM: four synthetic SRTM3 tiles around 0°N 0°E (N00E000, N00W001, S01E000, S01W001),
 * generated deterministically (fixed seed) so that a fresh clone renders a panorama offline.
 * Gaussian massifs and a long ridge on a rolling plain, with sea in the south-west corner.
 */
public final class DemoTerrain {
    /** Where the CLI keeps it, relative to the project. */
    public static final Path DEFAULT_DIR = Path.of("testdata", "demo-dem");
    private static final long SEED = 20261121L;
    private static final int N = HgtTile.SRTM3_SAMPLES;

    private DemoTerrain() {
    }

    /** Height of the demo terrain, metres, at a coordinate. */
    public static double heightMetres(double latDeg, double lonDeg, double[][] massifs) {
        double h = 300 + 120 * Math.sin(latDeg * 9.1) * Math.cos(lonDeg * 7.3) + 150 * (latDeg + lonDeg);
        for (double[] m : massifs) {
            double dy = (latDeg - m[0]) * 111.0, dx = (lonDeg - m[1]) * 111.0; // km near the equator
            h += m[2] * Math.exp(-Math.sqrt(dx * dx + dy * dy) / m[3]); // peaked, alpine-like massifs
        }
        // A ridge running north-east, 25 km away.
        double along = ((latDeg - 0.25) + (lonDeg + 0.1)) / Math.sqrt(2), across = ((latDeg - 0.25) - (lonDeg + 0.1)) / Math.sqrt(2);
        h += 1400 * Math.exp(-Math.pow(across * 111 / 3.0, 2)) * Math.exp(-Math.pow(along * 111 / 40.0, 2));
        return Math.max(0, h);
    }

    /**
     * The demo viewpoint, {latDeg, lonDeg}: the top of the lowest massif within 0.35° of 0°N 0°E,
     * so that the panorama shows higher mountains all around.
     */
    public static double[] viewpoint() {
        double[][] m = massifs();
        double best = Double.MAX_VALUE;
        double[] at = null;
        for (double[] c : m) {
            if (Math.hypot(c[0], c[1]) > 0.35) {
                continue;
            }
            double h = heightMetres(c[0], c[1], m);
            if (h < best) {
                best = h;
                at = new double[] {c[0], c[1]};
            }
        }
        return at;
    }

    static double[][] massifs() {
        Random rnd = new Random(SEED);
        double[][] m = new double[40][];
        for (int i = 0; i < m.length; i++) {
            // lat, lon, height m, sigma km
            m[i] = new double[] {-0.9 + 1.8 * rnd.nextDouble(), -0.9 + 1.8 * rnd.nextDouble(),
                    600 + 2400 * rnd.nextDouble(), 1.5 + 5 * rnd.nextDouble()};
        }
        return m;
    }

    /** Writes the four tiles into a directory (creating it) unless they are already there. */
    public static Path ensure(Path dir) throws IOException {
        Files.createDirectories(dir);
        double[][] massifs = massifs();
        for (int[] sw : new int[][] {{0, 0}, {0, -1}, {-1, 0}, {-1, -1}}) {
            TileId id = new TileId(sw[0], sw[1]);
            Path f = dir.resolve(id.name() + ".hgt");
            if (Files.isRegularFile(f) && Files.size(f) == 2L * N * N) {
                continue;
            }
            ByteBuffer b = ByteBuffer.allocate(2 * N * N);
            for (int r = 0; r < N; r++) {
                double lat = sw[0] + 1 - r / 1200.0;
                for (int c = 0; c < N; c++) {
                    b.putShort((short) Math.round(heightMetres(lat, sw[1] + c / 1200.0, massifs)));
                }
            }
            Path tmp = Files.createTempFile(dir, id.name(), ".part");
            Files.write(tmp, b.array());
            Files.move(tmp, f, java.nio.file.StandardCopyOption.ATOMIC_MOVE, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        }
        return dir;
    }
}
