package dempano.dem;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dempano.SharedData;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import mil.nga.tiff.FieldTagType;
import mil.nga.tiff.FieldType;
import mil.nga.tiff.FileDirectory;
import mil.nga.tiff.Rasters;
import mil.nga.tiff.TIFFImage;
import mil.nga.tiff.TiffWriter;
import mil.nga.tiff.util.TiffConstants;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The real tile N46E008 converted at test time to a GeoTIFF as gdal_translate lays it out
 * (PixelIsArea, the corner half a pixel outside the tile, GDAL_NODATA −32768), written by another
 * TIFF writer than the tests' own: the mosaic built from it equals the one from the .hgt, sample by sample.
 */
class GeoTiffRealTileTest {
    @TempDir
    Path dir;

    @Test
    void aGeoTiffOfN46E008GivesTheSameMosaicAsTheHgt() throws IOException {
        Path hgt = SharedData.demFile("N46E008.hgt");
        byte[] bytes = Files.readAllBytes(hgt);
        int n = HgtTile.SRTM3_SAMPLES;
        Rasters rasters = new Rasters(n, n, 1, FieldType.SSHORT);
        java.nio.ByteBuffer b = java.nio.ByteBuffer.wrap(bytes); // big-endian int16, -32768 voids
        for (int r = 0; r < n; r++) {
            for (int c = 0; c < n; c++) {
                rasters.setFirstPixelSample(c, r, b.getShort());
            }
        }
        FileDirectory d = new FileDirectory();
        d.setImageWidth(n);
        d.setImageHeight(n);
        d.setBitsPerSample(16);
        d.setCompression(TiffConstants.COMPRESSION_DEFLATE);
        d.setPhotometricInterpretation(TiffConstants.PHOTOMETRIC_INTERPRETATION_BLACK_IS_ZERO);
        d.setSamplesPerPixel(1);
        d.setRowsPerStrip(rasters.calculateRowsPerStrip(TiffConstants.PLANAR_CONFIGURATION_CHUNKY));
        d.setPlanarConfiguration(TiffConstants.PLANAR_CONFIGURATION_CHUNKY);
        d.setSampleFormat(TiffConstants.SAMPLE_FORMAT_SIGNED_INT);
        d.setWriteRasters(rasters);
        double px = 1.0 / 1200;
        d.setModelPixelScale(List.of(px, px, 0.0));
        d.setModelTiepoint(List.of(0.0, 0.0, 0.0, 8 - px / 2, 47 + px / 2, 0.0));
        // GTModelType geographic, GTRasterType PixelIsArea, GeographicType WGS 84, vertical CS EGM96 height.
        d.setUnsignedIntegerListEntryValue(FieldTagType.GeoKeyDirectory,
                List.of(1, 1, 0, 4, 1024, 0, 1, 2, 1025, 0, 1, 1, 2048, 0, 1, 4326, 4096, 0, 1, 5773));
        d.setStringEntryValue(FieldTagType.GDAL_NODATA, "-32768");
        Path tifDir = Files.createDirectory(dir.resolve("tif"));
        TiffWriter.writeTiff(tifDir.resolve("N46E008.tif").toFile(), new TIFFImage(d));

        long t0 = System.nanoTime();
        Mosaic fromHgt = Mosaic.around(new DemDirectory(hgt.getParent()), 46.5, 8.5, 30_000, MissingTilePolicy.ERROR);
        long t1 = System.nanoTime();
        Mosaic fromTif = Mosaic.around(new DemDirectory(tifDir), 46.5, 8.5, 30_000, MissingTilePolicy.ERROR);
        long t2 = System.nanoTime();
        System.out.printf(java.util.Locale.ROOT, "N46E008: .hgt read in %.0f ms, GeoTIFF (Deflate, %d bytes) in %.0f ms%n",
                (t1 - t0) / 1e6, Files.size(tifDir.resolve("N46E008.tif")), (t2 - t1) / 1e6);
        assertEquals(List.of(TileId.of(46, 8)), fromTif.tilesUsed());
        assertEquals(fromHgt.rows(), fromTif.rows());
        assertEquals(fromHgt.cols(), fromTif.cols());
        for (int r = 0; r < fromHgt.rows(); r++) {
            for (int c = 0; c < fromHgt.cols(); c++) {
                assertEquals(fromHgt.sample(r, c), fromTif.sample(r, c), "sample " + r + ", " + c);
                assertEquals(fromHgt.flags(r, c), fromTif.flags(r, c), "flags " + r + ", " + c);
            }
        }
        assertEquals(List.of("EGM96"), fromTif.tileSources().get(TileId.of(46, 8)).stream()
                .map(DemContribution::verticalDatum).toList());
        assertEquals(fromHgt.tileSources().get(TileId.of(46, 8)).get(0).samples(),
                fromTif.tileSources().get(TileId.of(46, 8)).get(0).samples());
    }
}
