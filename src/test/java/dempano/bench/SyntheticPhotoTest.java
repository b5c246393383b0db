package dempano.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import dempano.camera.CameraOrientation;
import dempano.dem.TileId;
import dempano.panorama.DepthMode;
import dempano.panorama.Layer;
import dempano.panorama.Panorama;
import dempano.panorama.PanoramaGeometry;
import dempano.panorama.PanoramaMetadata;
import java.util.List;
import java.util.Map;
import java.util.function.DoubleUnaryOperator;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

/**
 * The benchmark's missing-data rule on a panorama built from arrays: sky above the horizontal, terrain below,
 * every terrain pixel at latitude 44.5° and at a longitude set per azimuth; only tile N44E007 has data.
 */
class SyntheticPhotoTest {
    static final double PPD = 4, TOP_DEG = 30;
    static final int W = 1440, H = 240; // rows down to −30°
    static final TileId PRESENT = TileId.of(44, 7);

    /** A panorama whose terrain at azimuth a (degrees) lies at longitude lon(a). */
    static Panorama panorama(DoubleUnaryOperator lonOfAzimuth, boolean layers) {
        PanoramaGeometry g = new PanoramaGeometry(PPD, TOP_DEG, H);
        float[] d = new float[W * H], lat = new float[W * H], lon = new float[W * H];
        for (int r = 0; r < H; r++) {
            for (int c = 0; c < W; c++) {
                boolean terrain = g.elevationOfRow(r) < 0;
                d[r * W + c] = terrain ? 5000f : Float.POSITIVE_INFINITY;
                lat[r * W + c] = terrain ? 44.5f : Float.NaN;
                lon[r * W + c] = terrain ? (float) lonOfAzimuth.applyAsDouble(g.azimuthOfColumn(c)) : Float.NaN;
            }
        }
        PanoramaMetadata m = new PanoramaMetadata(new dempano.geo.Viewpoint(44.5, 7.5, 1000, 0, 1000, 2), 50_000, 0.13, DepthMode.SHADER_RANGE,
                1, 50_000, 8, 100, 100, List.of(), List.of(), List.of(), Map.of(), "test", 0, 0, null, List.of());
        return new Panorama(g, null, d, layers ? Map.of(Layer.LATITUDE, lat, Layer.LONGITUDE, lon) : Map.of(), m);
    }

    /** East half (azimuth 0–180°) on the present tile at 7.5°, west half on the missing N44E006 at 6.5°. */
    static final Panorama HALVES = panorama(az -> az < 180 ? 7.5 : 6.5, true);

    static double share(Panorama p, double headingDeg, double hfovDeg) {
        return new SyntheticPhoto.MissingData(p, PRESENT::equals).share(480, 320, new CameraOrientation(headingDeg, 0, 0), hfovDeg);
    }

    @ParameterizedTest(name = "heading {0}°, fov {1}° -> share {2}")
    @CsvSource({
            "90, 60, 0",      // all on the present tile
            "270, 60, 1",     // all on the missing one
            "180, 60, 0.5",   // half and half (columns left of the centre look east of south)
            "0, 60, 0.5",
    })
    void columnsShowingMissingDataAreCounted(double heading, double hfov, double expected) {
        assertEquals(expected, share(HALVES, heading, hfov), 1.5 / 120);
    }

    /** Terrain within 0.01° of a missing tile counts as the data's edge; 0.02° away it does not. */
    @ParameterizedTest(name = "longitude {0} -> share {1}")
    @CsvSource({
            "7.005, 1",   // 0.005° east of N44E006's edge
            "7.995, 1",   // 0.005° west of N44E008's (missing) edge
            "7.02, 0",
            "7.98, 0",
    })
    void aMarginAroundMissingTilesCounts(double lon, double expected) {
        assertEquals(expected, share(panorama(az -> lon, true), 90, 40), 1e-12);
    }

    @Test
    void skyOnlyPhotosShowNoMissingData() {
        SyntheticPhoto.MissingData m = new SyntheticPhoto.MissingData(HALVES, PRESENT::equals);
        assertEquals(0, m.share(480, 320, new CameraOrientation(270, 25, 0), 20), 1e-12);
    }

    @Test
    void aReferenceWithoutCoordinateLayersIsRefused() {
        Panorama p = panorama(az -> 7.5, false);
        assertThrows(IllegalArgumentException.class, () -> new SyntheticPhoto.MissingData(p, PRESENT::equals));
    }
}
