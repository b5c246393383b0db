package dempano;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import dempano.panorama.PanoramaGeometry;
import java.util.Arrays;
import org.junit.jupiter.api.Test;

/** The auto elevation range: from 1° above the highest terrain to 10° below the lowest skyline. */
class AutoCropTest {
    @Test
    void cropsToTheTerrainWithItsMargins() {
        double ppd = 10;
        PanoramaGeometry g = PanoramaGeometry.of(ppd, -30, 30); // 600 rows, row r's top edge at 30 − r/10 degrees
        int w = g.widthPx(), h = g.heightPx();
        float[] d = new float[w * h];
        Arrays.fill(d, Float.POSITIVE_INFINITY);
        // Skyline between row 200 (10° up) and row 300 (0°), varying with the column.
        for (int c = 0; c < w; c++) {
            int skyline = 200 + (c * 100) / (w - 1);
            for (int r = skyline; r < h; r++) {
                d[r * w + c] = 1000 + r;
            }
        }
        PanoramaGeometry cropped = PanoramaRenderer.AutoCrop.crop(g, d);
        assertEquals(11.0, cropped.topElevationDeg(), 1e-9, "1° above the highest skyline");
        // Down to and including the row whose top edge lies 10° below the lowest skyline (row 400).
        assertEquals(-10.1, cropped.bottomElevationDeg(), 1e-9);
        assertEquals(211, cropped.heightPx());
        int skip = (int) Math.round((g.topElevationDeg() - cropped.topElevationDeg()) * ppd);
        float[] rows = PanoramaRenderer.AutoCrop.rows(d, w, skip, cropped.heightPx());
        // The crop keeps rows exactly: the highest skyline column's first terrain pixel is row 10 now.
        assertEquals(Float.POSITIVE_INFINITY, rows[9 * w]);
        assertEquals(1000 + 200, rows[10 * w], 0);
    }

    @Test
    void allSkyOrTerrainAtTheEdgesIsKeptWhole() {
        PanoramaGeometry g = PanoramaGeometry.of(10, -5, 5);
        float[] sky = new float[g.widthPx() * g.heightPx()];
        Arrays.fill(sky, Float.POSITIVE_INFINITY);
        assertSame(g, PanoramaRenderer.AutoCrop.crop(g, sky), "nothing but sky: unchanged");
        float[] ground = new float[sky.length];
        Arrays.fill(ground, 500f);
        PanoramaGeometry all = PanoramaRenderer.AutoCrop.crop(g, ground);
        assertEquals(g.topElevationDeg(), all.topElevationDeg(), 1e-9, "terrain up to the top row: no margin to add");
        assertEquals(g.heightPx(), all.heightPx());
    }
}
