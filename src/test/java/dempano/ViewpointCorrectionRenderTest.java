package dempano;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.dem.HgtTile;
import dempano.dem.InMemoryDem;
import dempano.dem.TileId;
import dempano.geo.Ellipsoid;
import dempano.panorama.Panorama;
import dempano.summits.Summit;
import dempano.summits.SummitList;
import dempano.summits.SummitSighting;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * End to end on the CPU reference: an eye 40 m beside a cone's apex sees the cone's flank as a wall
 * (warned) and not the second peak behind it; snapped onto the apex it sees the peak, judged from the
 * moved eye, and is not warned.
 */
class ViewpointCorrectionRenderTest {
    private static final int N = 1201;
    private static final double LAT = 46.5, LON = 8.5;
    private static final double M_PER_DEG_LAT = Ellipsoid.MEAN_RADIUS_METRES * Math.PI / 180;
    private static final double M_PER_DEG_LON = M_PER_DEG_LAT * Math.cos(Math.toRadians(LAT));
    /** The second peak, on the sample 47 columns (3.0 km) west of the apex. */
    private static final double PEAK_LON = 8 + 553 / 1200.0;

    private static double terrain(double lat, double lon) {
        double main = 3000 - 0.4 * Math.hypot((lat - LAT) * M_PER_DEG_LAT, (lon - LON) * M_PER_DEG_LON);
        double second = 2900 - 0.4 * Math.hypot((lat - LAT) * M_PER_DEG_LAT, (lon - PEAK_LON) * M_PER_DEG_LON);
        return Math.max(500, Math.max(main, second));
    }

    private static InMemoryDem dem() {
        float[] h = new float[N * N];
        for (int r = 0; r < N; r++) {
            for (int c = 0; c < N; c++) {
                h[r * N + c] = (float) terrain(47 - r / (N - 1.0), 8 + c / (N - 1.0));
            }
        }
        return new InMemoryDem("cones", List.of(HgtTile.of(new TileId(46, 8), N, h, "cones")));
    }

    @Test
    void besideTheApexWarnsAndHidesThePeakSnappedItSeesIt() {
        SummitList summits = SummitList.of("test", List.of(new Summit("Second", LAT, PEAK_LON, 2900)));
        PanoramaRequest beside = PanoramaRequest.at(LAT, LON + 40 / M_PER_DEG_LON).withRangeMetres(6000)
                .withPixelsPerDegree(4).withColour(false);
        try (PanoramaRenderer cpu = PanoramaRenderer.openReference(dem())) {
            Panorama wall = cpu.render(beside);
            assertTrue(wall.metadata().warnings().stream().anyMatch(w -> w.contains("--snap-to-summit-m")),
                    "no near-terrain warning: " + wall.metadata().warnings());
            SummitSighting hidden = wall.summits(summits).get(0);
            assertFalse(hidden.visible(), "the peak behind the apex is reported visible: " + hidden);
            assertTrue(hidden.mapDistanceMetres() < 100, "the wall at its pixel: " + hidden.mapDistanceMetres());

            Panorama top = cpu.render(beside.withSnapToSummitMetres(100));
            assertTrue(top.metadata().warnings().isEmpty(), "warned on the apex: " + top.metadata().warnings());
            assertNotNull(top.metadata().viewpointMove());
            assertEquals(LON, top.metadata().lonDeg(), 1e-9);
            assertEquals(3002, top.metadata().eyeAltitudeMetres(), 1e-3);
            assertEquals(40, top.metadata().viewpointMove().shiftMetres(), 0.01);
            SummitSighting seen = top.summits(summits).get(0);
            assertTrue(seen.visible(), "the peak is hidden from the apex: " + seen);
            assertEquals(3000, seen.groundMetres(), 15); // judged from the moved eye: 3.0 km, not 3.04
        }
    }
}
