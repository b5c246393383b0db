package dempano.dem;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.api.Test;

/** The void fills against closed-form surfaces with holes cut out of them. */
class VoidFillMethodsTest {
    /** Heights of a closed-form surface on an n × n grid. */
    private static float[] surface(int n, java.util.function.DoubleBinaryOperator z) {
        float[] h = new float[n * n];
        for (int r = 0; r < n; r++) {
            for (int c = 0; c < n; c++) {
                h[r * n + c] = (float) z.applyAsDouble(r, c);
            }
        }
        return h;
    }

    private static float[] cut(float[] h, int n, int r0, int r1, int c0, int c1) {
        float[] g = h.clone();
        for (int r = r0; r <= r1; r++) {
            for (int c = c0; c <= c1; c++) {
                g[r * n + c] = Float.NaN;
            }
        }
        return g;
    }

    private static double maxError(float[] a, float[] b) {
        double m = 0;
        for (int i = 0; i < a.length; i++) {
            m = Math.max(m, Math.abs(a[i] - b[i]));
        }
        return m;
    }

    @ParameterizedTest
    @EnumSource(value = VoidFill.class, names = {"LAPLACE", "THIN_PLATE"})
    void aPlaneWithAHoleIsRestored(VoidFill fill) {
        int n = 41;
        float[] truth = surface(n, (r, c) -> 1500 + 3.5 * r - 7.25 * c);
        float[] h = cut(truth, n, 12, 26, 8, 30);
        VoidReport rep = fill.fill(h, n);
        assertEquals(15 * 23, rep.voidCells());
        assertEquals(1, rep.regions());
        assertTrue(maxError(h, truth) < 1e-3, fill + ": worst error " + maxError(h, truth) + " m");
    }

    @ParameterizedTest
    @EnumSource(value = VoidFill.class, names = {"LAPLACE", "THIN_PLATE"})
    void aLargeHoleGoesThroughTheCoarseGridsAndStillRestoresThePlane(VoidFill fill) {
        int n = 201; // 61 × 61 = 3721 voids: solved from coarser grids first
        float[] truth = surface(n, (r, c) -> 800 + 12.0 * r + 4.0 * c);
        float[] h = cut(truth, n, 70, 130, 100, 160);
        fill.fill(h, n);
        assertTrue(maxError(h, truth) < 0.05, fill + ": worst error " + maxError(h, truth) + " m");
    }

    /** A summit whose top (radius 6 samples) is a void: the fills' height at the summit, minus the truth. */
    private static double summitError(VoidFill fill, java.util.function.DoubleBinaryOperator z) {
        int n = 61;
        float[] truth = surface(n, z);
        float[] h = cut(truth, n, 24, 36, 24, 36);
        fill.fill(h, n);
        return h[30 * n + 30] - truth[30 * n + 30];
    }

    @Test
    void aParaboloidSummitIsRebuiltByTheThinPlateFillAndFlattenedByTheOthers() {
        // 3000 m at the centre, falling 2 m at one sample, 200 m at ten: ∇⁴ = 0, a thin plate's own shape.
        java.util.function.DoubleBinaryOperator dome = (r, c) -> 3000 - 2 * ((r - 30) * (r - 30) + (c - 30) * (c - 30));
        double idw = summitError(VoidFill.IDW, dome), laplace = summitError(VoidFill.LAPLACE, dome);
        double plate = summitError(VoidFill.THIN_PLATE, dome);
        // The rim lies 72 m below the summit (6 samples out): IDW and Laplace stay at or below it.
        assertTrue(idw < -60 && laplace < -60, "idw " + idw + ", laplace " + laplace);
        assertTrue(Math.abs(plate) < 5, "thin plate " + plate);
    }

    @Test
    void aConeSummitComesCloserWithTheThinPlateFill() {
        // A cone, 30 m per sample: the rim (6 samples out) is 180 m below the tip.
        java.util.function.DoubleBinaryOperator cone = (r, c) -> 3000 - 30 * Math.hypot(r - 30, c - 30);
        double idw = summitError(VoidFill.IDW, cone), laplace = summitError(VoidFill.LAPLACE, cone);
        double plate = summitError(VoidFill.THIN_PLATE, cone);
        assertTrue(idw < -150 && laplace < -150, "idw " + idw + ", laplace " + laplace);
        assertTrue(plate > idw + 60 && plate > laplace + 60 && plate < 0, "thin plate " + plate + ", idw " + idw);
    }

    @ParameterizedTest
    @EnumSource(VoidFill.class)
    void aVoidTouchingTheBorderAndCornerIsFilledSensibly(VoidFill fill) {
        int n = 31;
        float[] truth = surface(n, (r, c) -> 200 + 5.0 * r + 2.0 * c);
        float[] h = cut(truth, n, 0, 6, 20, 30); // the north-east corner
        VoidReport rep = fill.fill(h, n);
        assertEquals(7 * 11, rep.voidCells());
        for (float v : h) {
            assertTrue(Float.isFinite(v));
        }
        // Every fill stays within a plausible band around the plane (it cannot see the corner's truth).
        assertTrue(maxError(h, truth) < 40, fill + ": worst " + maxError(h, truth));
    }

    @ParameterizedTest
    @EnumSource(VoidFill.class)
    void aVoidOnTheBorderBelowASteepRimIsNotExtrapolatedAboveIt(VoidFill fill) {
        // A ridge rising 80 m per sample towards the western border, its last 8 columns void: bending
        // alone would carry the rise on to the border (+640 m); no fill may go above the rim.
        int n = 41;
        float[] truth = surface(n, (r, c) -> 3000 - 80 * c - 5 * Math.abs(r - 20));
        float[] h = cut(truth, n, 10, 30, 0, 7);
        float rimMax = -Float.MAX_VALUE;
        for (float v : h) {
            if (!Float.isNaN(v)) {
                rimMax = Math.max(rimMax, v);
            }
        }
        fill.fill(h, n);
        for (float v : h) {
            assertTrue(v <= rimMax + 1e-3, fill + ": " + v + " m above the highest valid " + rimMax + " m");
        }
    }

    @ParameterizedTest
    @EnumSource(VoidFill.class)
    void anAllVoidTileBecomesSeaLevelAndATileWithoutVoidsIsUntouched(VoidFill fill) {
        float[] all = new float[16];
        Arrays.fill(all, Float.NaN);
        assertEquals(16, fill.fill(all, 4).voidCells());
        assertArrayEquals(new float[16], all);
        float[] plain = surface(5, (r, c) -> r * c);
        float[] copy = plain.clone();
        assertSame(VoidReport.NONE, fill.fill(copy, 5));
        assertArrayEquals(plain, copy);
    }

    @ParameterizedTest
    @EnumSource(VoidFill.class)
    void oneValidSampleFillsEverything(VoidFill fill) {
        float[] h = new float[25];
        Arrays.fill(h, Float.NaN);
        h[7] = 42;
        fill.fill(h, 5);
        for (float v : h) {
            assertEquals(42, v, 1e-3);
        }
    }

    @Test
    void fillsAreDeterministicAndKeepValidSamples() {
        int n = 101;
        java.util.Random random = new java.util.Random(20);
        float[] base = surface(n, (r, c) -> 1000 + 300 * Math.sin(r / 9.0) * Math.cos(c / 13.0));
        float[] holes = base.clone();
        for (int k = 0; k < 40; k++) {
            int r = random.nextInt(n - 10), c = random.nextInt(n - 10), s = 1 + random.nextInt(9);
            holes = cut(holes, n, r, r + s, c, c + s);
        }
        for (VoidFill f : VoidFill.values()) {
            float[] a = holes.clone(), b = holes.clone();
            f.fill(a, n);
            f.fill(b, n);
            assertArrayEquals(a, b, f.toString());
            for (int i = 0; i < a.length; i++) {
                if (!Float.isNaN(holes[i])) {
                    assertEquals(holes[i], a[i], 0, f + " changed a valid sample");
                }
            }
        }
    }

    @Test
    void namesOnTheCommandLine() {
        assertEquals(VoidFill.THIN_PLATE, VoidFill.parse("thin-plate"));
        assertEquals(VoidFill.IDW, VoidFill.parse("IDW"));
        assertEquals(VoidFill.LAPLACE, VoidFill.parse("laplace"));
        assertEquals(VoidFill.THIN_PLATE, VoidFill.DEFAULT);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> VoidFill.parse("kriging"));
        assertTrue(e.getMessage().contains("thin-plate"), e.getMessage());
    }

    /**
     * The thin-plate fill's operator runs in parallel chunks: on the real N46E008 (7.2 % voids, ~104 000 at the
     * finest level) the parallel and the one-thread fill agree bit for bit, and both equal the fill before the
     * operator was split (tolerance 0: the SHA-256 of the filled tile as big-endian float32, recorded with the code
     * of commit cc1cc3c). The Laplace fill goes through the same operator.
     */
    @Test
    void theParallelThinPlateFillOfARealTileEqualsTheOneThreadFillAndTheFillBefore() throws Exception {
        HgtTile t = HgtReader.read(dempano.SharedData.demFile("N46E008.hgt"), VoidFill.IDW);
        int n = t.samplesPerSide();
        float[] raw = new float[n * n];
        for (int r = 0; r < n; r++) {
            for (int c = 0; c < n; c++) {
                raw[r * n + c] = t.isFilledVoid(r, c) ? Float.NaN : t.heightMetres(r, c);
            }
        }
        float[] parallel = raw.clone(), oneThread = raw.clone();
        try {
            SplineVoidFill.parallel = true;
            VoidFill.THIN_PLATE.fill(parallel, n);
            SplineVoidFill.parallel = false;
            VoidFill.THIN_PLATE.fill(oneThread, n);
        } finally {
            SplineVoidFill.parallel = true;
        }
        assertArrayEquals(oneThread, parallel);
        java.nio.ByteBuffer bytes = java.nio.ByteBuffer.allocate(4 * n * n);
        for (float h : parallel) {
            bytes.putFloat(h);
        }
        String sha = java.util.HexFormat.of().formatHex(java.security.MessageDigest.getInstance("SHA-256").digest(bytes.array()));
        assertEquals("e6b934ed8d727f6a1c79f119ff1e4ce9933353de0cc33c666f0ca7ad19710cd7", sha, "the fill before the split");
    }
}
