package dempano.terrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

/** Deviations of coarse levels against closed forms; the level chosen against the pixel bound. */
class LevelOfDetailTest {
    static float[] grid(int n, Height h) {
        float[] a = new float[(n + 1) * (n + 1)];
        for (int i = 0; i <= n; i++) {
            for (int j = 0; j <= n; j++) {
                a[i * (n + 1) + j] = (float) h.at(i, j);
            }
        }
        return a;
    }

    interface Height {
        double at(int row, int col);
    }

    @Test
    void aPlaneLosesNothingAtAnyLevel() {
        float[] h = grid(64, (i, j) -> 100 + 3 * i - 2 * j);
        double[] dev = LevelOfDetail.deviationsMetres(h, 65, 0, 0, 64);
        assertEquals(7, dev.length);
        for (double d : dev) {
            assertEquals(0, d, 1e-9);
        }
        // Nothing lost: the coarsest level even right at the eye.
        assertEquals(6, LevelOfDetail.chooseLevel(dev, 1, 20, 0.5));
    }

    @Test
    void aParabolaDeviatesByTheChordSag() {
        // h = a·j²: the chord over [0, s] lies a·(s/2)² above the parabola at its middle.
        double a = 0.25;
        float[] h = grid(64, (i, j) -> a * j * j);
        double[] dev = LevelOfDetail.deviationsMetres(h, 65, 0, 0, 64);
        assertEquals(0, dev[0]);
        for (int level = 1; level <= 6; level++) {
            double s = 1 << level;
            assertEquals(a * (s / 2) * (s / 2), dev[level], 1e-3, "level " + level);
        }
    }

    @Test
    void aSpikeBetweenCoarseSamplesIsSeenAtEveryCoarseLevel() {
        float[] h = grid(64, (i, j) -> i == 33 && j == 17 ? 250 : 0);
        double[] dev = LevelOfDetail.deviationsMetres(h, 65, 0, 0, 64);
        assertEquals(0, dev[0]);
        for (int level = 1; level <= 6; level++) {
            assertEquals(250, dev[level], 1e-9, "level " + level);
        }
        // A patch inside a larger grid: offsets are honoured.
        float[] big = grid(128, (i, j) -> i == 64 + 33 && j == 64 + 17 ? 250 : 0);
        assertEquals(250, LevelOfDetail.deviationsMetres(big, 129, 64, 64, 64)[3], 1e-9);
        assertEquals(0, LevelOfDetail.deviationsMetres(big, 129, 0, 0, 64)[3], 1e-9);
    }

    @Test
    void interpolationIsExactAtCornersAndLinearOnEachTriangle() {
        for (boolean split : new boolean[] {true, false}) {
            assertEquals(1, LevelOfDetail.interpolate(1, 2, 3, 4, 0, 0, split), 1e-12);
            assertEquals(2, LevelOfDetail.interpolate(1, 2, 3, 4, 1, 0, split), 1e-12);
            assertEquals(3, LevelOfDetail.interpolate(1, 2, 3, 4, 0, 1, split), 1e-12);
            assertEquals(4, LevelOfDetail.interpolate(1, 2, 3, 4, 1, 1, split), 1e-12);
        }
        // Not a plane (nw + se ≠ ne + sw): the centre lies on the diagonal that splits the cell.
        assertEquals((0 + 10) / 2.0, LevelOfDetail.interpolate(0, 0, 0, 10, 0.5, 0.5, true), 1e-12);
        assertEquals((0 + 0) / 2.0, LevelOfDetail.interpolate(0, 0, 0, 10, 0.5, 0.5, false), 1e-12);
    }

    @Test
    void levelFollowsTheScreenErrorBound() {
        double[] dev = {0, 10, 20, 40, 80};
        // 0.5 px at 20 px/deg is 0.025° = 4.363e-4 rad.
        double rad = 0.5 / 20 * Math.PI / 180;
        assertEquals(0, LevelOfDetail.chooseLevel(dev, 9.99 / rad, 20, 0.5));
        assertEquals(1, LevelOfDetail.chooseLevel(dev, 10.01 / rad, 20, 0.5));
        assertEquals(2, LevelOfDetail.chooseLevel(dev, 39.9 / rad, 20, 0.5));
        assertEquals(4, LevelOfDetail.chooseLevel(dev, 1e9, 20, 0.5));
        assertEquals(0, LevelOfDetail.chooseLevel(dev, 1e9, 20, 0), "0 px = full resolution");
        // A level beyond a failing one is not taken even if it happens to hold the bound.
        assertEquals(0, LevelOfDetail.chooseLevel(new double[] {0, 50, 1}, 10 / rad, 20, 0.5));
    }

    @Test
    void patchSideMustBeAPowerOfTwo() {
        assertThrows(IllegalArgumentException.class, () -> LevelOfDetail.deviationsMetres(new float[49], 7, 0, 0, 6));
    }

    @Test
    void chordSagMatchesTheCircleItCuts() {
        // A chord of length L on a circle of radius R lies R − √(R² − L²/4) ≈ L²/8R below the arc.
        double side = 5_000, r = 6_356_000, chord = Math.sqrt(2) * side;
        assertEquals(r - Math.sqrt(r * r - chord * chord / 4), LevelOfDetail.chordSagMetres(side, 0.13), 1e-3);
        assertEquals(LevelOfDetail.chordSagMetres(side, 0), LevelOfDetail.chordSagMetres(side, 0.13), 0, "k > 0 never lowers it");
        assertEquals(1.5 * LevelOfDetail.chordSagMetres(side, 0), LevelOfDetail.chordSagMetres(side, -0.5), 1e-9);
    }
}
