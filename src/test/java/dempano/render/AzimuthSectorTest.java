package dempano.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;

import com.jme3.math.Vector3f;
import com.jme3.scene.Geometry;
import com.jme3.scene.shape.Box;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The sector of azimuths under which a box is seen from the eye (jME axes: x east, z south), against the azimuths
 * of points sampled densely over the box's footprint (an independent covering arc), and which views a sector
 * overlaps, across north (0°/360°) and south (±180°).
 */
class AzimuthSectorTest {
    private static Geometry box(double x0, double z0, double x1, double z1) {
        return new Geometry("box", new Box(new Vector3f((float) x0, -1, (float) z0), new Vector3f((float) x1, 1, (float) z1)));
    }

    /** The smallest arc holding the azimuths of a dense grid over the footprint: {from, span}, degrees. */
    private static double[] coveringArc(double x0, double z0, double x1, double z1) {
        int n = 400;
        double[] az = new double[(n + 1) * (n + 1)];
        int k = 0;
        for (int i = 0; i <= n; i++) {
            for (int j = 0; j <= n; j++) {
                double x = x0 + (x1 - x0) * i / n, z = z0 + (z1 - z0) * j / n;
                az[k++] = ((Math.toDegrees(Math.atan2(x, -z)) % 360) + 360) % 360;
            }
        }
        java.util.Arrays.sort(az);
        // The arc is the circle less its widest gap between sorted azimuths.
        double widest = az[0] + 360 - az[az.length - 1];
        double from = az[0];
        for (int i = 1; i < az.length; i++) {
            if (az[i] - az[i - 1] > widest) {
                widest = az[i] - az[i - 1];
                from = az[i];
            }
        }
        return new double[] {from, 360 - widest};
    }

    @ParameterizedTest(name = "x {0}..{2}, z {1}..{3}")
    @CsvSource({
            "1, -2, 2, -1",       // north-east
            "-1, -3, 1, -2",      // across north
            "-1, 2, 1, 3",        // across south (±180°)
            "-5, -0.5, -4, 0.5",  // due west
            "3, 1, 40, 2",        // long and thin, east-south-east
            "-1000, -1000, -999, 1000", // tall wall in the west, near 180° wide
    })
    void aBoxIsSeenUnderTheArcOfItsFootprintsAzimuths(double x0, double z0, double x1, double z1) {
        double[] sector = AzimuthSector.of(box(x0, z0, x1, z1));
        assertNotNull(sector);
        double[] truth = coveringArc(x0, z0, x1, z1);
        assertEquals(truth[1], sector[1], 1e-3, "span");
        double offset = ((sector[0] - truth[0]) % 360 + 540) % 360 - 180;
        assertEquals(0, offset, 1e-3, "from " + sector[0] + " against " + truth[0]);
    }

    @ParameterizedTest
    @CsvSource({"-1, -1, 1, 1", "0, 0, 5, 5", "-3, -2, 0, 0"})
    void aBoxAroundOrAtTheEyeIsSeenEverywhere(double x0, double z0, double x1, double z1) {
        assertNull(AzimuthSector.of(box(x0, z0, x1, z1)));
        for (double from = 0; from < 360; from += 45) {
            assertEquals(true, AzimuthSector.overlaps(null, from, 45));
        }
    }

    @ParameterizedTest(name = "sector {0}+{1} vs view {2}+{3}: {4}")
    @CsvSource({
            "10, 20, 0, 45, true",
            "10, 20, 40, 45, false",     // 10°-30° against 40°-85°
            "85.3, 5, 0, 85, true",      // within the half-degree margin
            "86, 5, 0, 85, false",
            "350, 20, 0, 45, true",      // across north
            "-26.57, 53.13, 315, 45, true",
            "100, 10, 315, 45, false",
            "170, 20, 180, 45, true",    // across south
            "120, 20, 180, 45, false",
            "0, 359, 200, 10, true",     // nearly the whole circle
            "225.4, 5, 180, 45, true",   // starts within the half-degree margin past the view's end
            "226, 5, 180, 45, false",
    })
    void aSectorOverlapsTheViewsItMeets(double from, double span, double viewFrom, double viewSpan, boolean overlaps) {
        assertEquals(overlaps, AzimuthSector.overlaps(new double[] {from, span}, viewFrom, viewSpan));
    }
}
