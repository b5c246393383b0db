package dempano.bench;

import dempano.dem.TileId;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.stream.IntStream;

/**
 * Deterministic mountain relief for benchmarks where real tiles are lacking: fractal value noise
 * (octaves from 40 km down to the cell size, amplitude falling as wavelength^0.9, as measured on
 * alpine DEMs), ridged in its coarse octaves, with valleys at sea level. Rough at every scale, so a
 * level of detail gains only what real mountains would give it. Written as ordinary .hgt files.
 */
public final class FractalRelief {
    private FractalRelief() {
    }

    /** Height in metres at a point given in metres east and north of 0°N 0°E (a flat-earth map is enough here). */
    public static double heightMetres(double eastMetres, double northMetres, double cellMetres) {
        double h = 0, amplitude = 900, wavelength = 40_000;
        int octave = 0;
        while (wavelength > 1.5 * cellMetres && octave < 12) {
            double n = noise(eastMetres / wavelength, northMetres / wavelength, octave);
            // Ridged coarse octaves make sharp crests; fine octaves add texture.
            h += octave < 3 ? amplitude * (1 - 2 * Math.abs(n)) : amplitude * n;
            amplitude *= Math.pow(0.5, 0.9);
            wavelength /= 2;
            octave++;
        }
        return Math.max(0, 900 + 1.6 * h);
    }

    /** Smooth value noise in [-1, 1]. */
    static double noise(double x, double y, int seed) {
        int x0 = (int) Math.floor(x), y0 = (int) Math.floor(y);
        double fx = x - x0, fy = y - y0;
        double sx = fx * fx * (3 - 2 * fx), sy = fy * fy * (3 - 2 * fy);
        double a = lattice(x0, y0, seed), b = lattice(x0 + 1, y0, seed);
        double c = lattice(x0, y0 + 1, seed), d = lattice(x0 + 1, y0 + 1, seed);
        return (a + sx * (b - a)) + sy * ((c + sx * (d - c)) - (a + sx * (b - a)));
    }

    private static double lattice(int x, int y, int seed) {
        long h = x * 0x9E3779B97F4A7C15L ^ y * 0xC2B2AE3D27D4EB4FL ^ (seed + 1) * 0x165667B19E3779F9L;
        h ^= h >>> 31;
        h *= 0xBF58476D1CE4E5B9L;
        h ^= h >>> 29;
        return ((h >>> 11) * 0x1.0p-53) * 2 - 1;
    }

    /**
     * Writes the tiles with south-west corners from (latSouth, lonWest) over rows × cols degrees,
     * each {@code samples}² (1201 = SRTM3, 3601 = SRTM1), unless already there with the right size.
     */
    public static Path ensure(Path dir, int latSouth, int lonWest, int rows, int cols, int samples) throws IOException {
        Files.createDirectories(dir);
        int intervals = samples - 1;
        for (int i = 0; i < rows; i++) {
            for (int j = 0; j < cols; j++) {
                TileId id = new TileId(latSouth + i, lonWest + j);
                Path f = dir.resolve(id.name() + ".hgt");
                if (Files.isRegularFile(f) && Files.size(f) == 2L * samples * samples) {
                    continue;
                }
                byte[] bytes = new byte[2 * samples * samples];
                double cell = 111_195.0 / intervals;
                int lat0 = id.latSouthDeg(), lon0 = id.lonWestDeg();
                IntStream.range(0, samples).parallel().forEach(r -> {
                    ByteBuffer b = ByteBuffer.wrap(bytes, 2 * r * samples, 2 * samples);
                    double north = (lat0 + 1 - r / (double) intervals) * 111_195.0;
                    double cosLat = Math.cos(Math.toRadians(lat0 + 1 - r / (double) intervals));
                    for (int c = 0; c < samples; c++) {
                        double east = (lon0 + c / (double) intervals) * 111_195.0 * cosLat;
                        b.putShort((short) Math.round(heightMetres(east, north, cell)));
                    }
                });
                Path tmp = Files.createTempFile(dir, id.name(), ".part");
                Files.write(tmp, bytes);
                Files.move(tmp, f, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            }
        }
        return dir;
    }
}
