package dempano.dem;

import java.io.IOException;
import java.nio.file.Path;

/** GeoTIFF files for the CLI tests (in another package), written with {@link GeoTiffTestFiles}. */
public final class GeoTiffCliFixtures {
    /** Samples of the hole in {@link #copernicusWithHole}. */
    public static final long HOLE_SAMPLES = 40L * 50;

    private GeoTiffCliFixtures() {
    }

    /**
     * A Copernicus GLO-90-style tile (1200 × 1200 pixels of 3″ from the north-west corner, PixelIsPoint,
     * Deflate with the horizontal predictor, 256-pixel tiles) of smooth hills with a nodata hole of
     * 40 × 50 pixels.
     */
    public static Path copernicusWithHole(Path dir, int latSouth, int lonWest) throws IOException {
        double d = 1.0 / 1200;
        GeoTiffTestFiles.Spec s = GeoTiffTestFiles.geographic(1200, 1200, lonWest, latSouth + 1, d, d, true)
                .withNodata("-32767").withCompression(GeoTiffTestFiles.DEFLATE, 2)
                .withLayout(256, 0, java.nio.ByteOrder.LITTLE_ENDIAN);
        String name = String.format("Copernicus_DSM_COG_30_N%02d_00_E%03d_00_DEM.tif", latSouth, lonWest);
        return GeoTiffTestFiles.write(dir.resolve(name), s, (r, c) -> r >= 500 && r < 540 && c >= 600 && c < 650 ? -32767
                : Math.round(700 + 150 * Math.sin((latSouth + 1 - r * d) * 20) + 150 * Math.cos((lonWest + c * d) * 15)));
    }

    /** A small UTM zone 32N (EPSG:32632) GeoTIFF. */
    public static Path projected(Path file) throws IOException {
        GeoTiffTestFiles.Spec s = GeoTiffTestFiles.geographic(50, 50, 420_000, 5_200_000, 30, 30, false).withCrs(1, 32632, 0);
        return GeoTiffTestFiles.write(file, s, (r, c) -> 500);
    }
}
