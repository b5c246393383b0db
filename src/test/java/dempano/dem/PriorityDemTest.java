package dempano.dem;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.List;
import java.util.function.DoubleBinaryOperator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class PriorityDemTest {
    @TempDir
    Path dir;

    private static final TileId WEST = TileId.of(46, 8), EAST = TileId.of(46, 9);

    /** Source A's heights: a plane in lat/lon. */
    private static double fa(double lat, double lon) {
        return 1000 + 800 * (lat - 46) + 300 * (lon - 8);
    }

    /** Source B's heights: another plane, so every sample tells which source served it. */
    private static double fb(double lat, double lon) {
        return 3000 - 500 * (lat - 46) + 100 * (lon - 8);
    }

    /** A tile sampling f on an ipd grid, void where the predicate holds. */
    private static HgtTile tile(TileId id, int ipd, DoubleBinaryOperator f, RowCol isVoid, String source) {
        int n = ipd + 1;
        float[] h = new float[n * n];
        for (int r = 0; r < n; r++) {
            for (int c = 0; c < n; c++) {
                h[r * n + c] = isVoid.test(r, c) ? Float.NaN
                        : (float) f.applyAsDouble(id.latSouthDeg() + 1 - (double) r / ipd, id.lonWestDeg() + (double) c / ipd);
            }
        }
        return HgtTile.of(id, n, h, source);
    }

    interface RowCol {
        boolean test(int row, int col);
    }

    private static boolean hole(int r, int c) {
        return r >= 30 && r < 50 && c >= 40 && c < 70;
    }

    @Test
    void aWinsWhereItHasDataAndBFillsItsVoidsAndMissingTiles() {
        DemSource a = new InMemoryDem("A", List.of(tile(WEST, 120, PriorityDemTest::fa, PriorityDemTest::hole, "A/N46E008")));
        DemSource b = new InMemoryDem("B", List.of(tile(WEST, 120, PriorityDemTest::fb, (r, c) -> false, "B/N46E008"),
                tile(EAST, 120, PriorityDemTest::fb, (r, c) -> false, "B/N46E009")));
        // As-is: every sample tells which source served it (the default delta surface is tested below).
        Mosaic m = Mosaic.around(new PriorityDem(List.of(a, b), VoidFill.DEFAULT, PriorityDem.Blend.AS_IS), 46.5, 9.0, 20_000,
                MissingTilePolicy.ERROR);
        assertEquals(List.of(WEST, EAST), m.tilesUsed());
        assertEquals("A, then B", m.sourceDescription());
        for (int row = 0; row < m.rows(); row++) {
            for (int col = 0; col < m.cols(); col++) {
                double lat = m.latOfRow(row), lon = m.lonOfCol(col);
                // The edge at 9°E is the eastern tile's (B's); west of it A's, except A's hole.
                boolean fromA = col < 120 && !hole(row, col);
                double expected = fromA ? fa(lat, lon) : fb(lat, lon);
                assertEquals(expected, m.sample(row, col), 1e-3, "sample " + row + ", " + col);
                assertEquals(0, m.flags(row, col), "nothing interpolated at " + row + ", " + col);
            }
        }
        assertEquals(List.of(new DemContribution("A/N46E008", "unknown", 121 * 121 - 600),
                new DemContribution("B/N46E008", "unknown", 600)), m.tileSources().get(WEST));
        assertEquals(List.of(new DemContribution("B/N46E009", "unknown", 121 * 121)), m.tileSources().get(EAST));
    }

    @Test
    void voidsNoSourceHasAreInterpolatedAndNotCounted() {
        HgtTile a = tile(WEST, 120, PriorityDemTest::fa, PriorityDemTest::hole, "A");
        // B is void over the hole's first five rows too.
        HgtTile b = tile(WEST, 120, PriorityDemTest::fb, (r, c) -> r < 35, "B");
        HgtTile merged = PriorityDem.merge(a, List.of(b), VoidFill.DEFAULT, PriorityDem.Blend.AS_IS);
        assertEquals(5 * 30, merged.voids().voidCells());
        assertTrue(merged.isFilledVoid(32, 50));
        assertEquals(fb(47 - 40 / 120.0, 8 + 50 / 120.0), merged.heightMetres(40, 50), 1e-3);
        assertEquals(List.of(121L * 121 - 600, 600L - 150), merged.contributions().stream().map(DemContribution::samples).toList());
    }

    @Test
    void aFillerOfAnotherResolutionIsSampledOnThePrimaryGrid() {
        HgtTile a = tile(WEST, 120, PriorityDemTest::fa, PriorityDemTest::hole, "A");
        for (int ipd : new int[] {240, 60, 90}) {
            HgtTile b = tile(WEST, ipd, PriorityDemTest::fb, (r, c) -> false, "B" + ipd);
            HgtTile merged = PriorityDem.merge(a, List.of(b), VoidFill.DEFAULT, PriorityDem.Blend.AS_IS);
            assertEquals(121, merged.samplesPerSide());
            for (int r = 30; r < 50; r++) {
                for (int c = 40; c < 70; c++) {
                    // Bilinear interpolation reproduces a plane: exact wherever B's samples lie.
                    assertEquals(fb(47 - r / 120.0, 8 + c / 120.0), merged.heightMetres(r, c), 2e-3, ipd + ": " + r + ", " + c);
                }
            }
            assertEquals(0, merged.voids().voidCells());
        }
        // A coarser filler's void: the A samples on it and those interpolated from it stay voids.
        HgtTile holey = tile(WEST, 60, PriorityDemTest::fb, (r, c) -> r == 20 && c == 25, "B");
        HgtTile merged = PriorityDem.merge(a, List.of(holey), VoidFill.DEFAULT, PriorityDem.Blend.AS_IS);
        assertTrue(merged.isFilledVoid(40, 50), "on B's void (20, 25)");
        assertTrue(merged.isFilledVoid(41, 50), "half-way to B's void");
        assertTrue(merged.isFilledVoid(40, 51), "half-way to B's void");
        assertTrue(!merged.isFilledVoid(43, 50), "from B's (21, 25) and (22, 25)");
        assertEquals(fb(47 - 43 / 120.0, 8 + 50 / 120.0), merged.heightMetres(43, 50), 2e-3);
        assertEquals(9, merged.voids().voidCells(), "A's samples 39…41 × 49…51 touch B's void");
    }

    @Test
    void aTileWithoutVoidsIsThePrimarysOwn() {
        HgtTile a = tile(WEST, 120, PriorityDemTest::fa, (r, c) -> false, "A");
        DemSource p = new PriorityDem(List.of(new InMemoryDem("A", List.of(a)),
                new InMemoryDem("B", List.of(tile(WEST, 120, PriorityDemTest::fb, (r, c) -> false, "B")))));
        assertSame(a, p.tile(WEST).orElseThrow());
        assertTrue(p.tile(TileId.of(0, 0)).isEmpty());
        assertThrows(IllegalArgumentException.class, () -> new PriorityDem(List.of()));
    }

    /** A GeoTIFF directory before an .hgt directory, through the files; a changed file is read again. */
    @Test
    void directoriesInPriorityAndAChangedFileIsNeverServedStale() throws IOException {
        Path aDir = Files.createDirectory(dir.resolve("copernicus")), bDir = Files.createDirectory(dir.resolve("srtm"));
        double d = 1.0 / 1200;
        GeoTiffTestFiles.Spec spec = GeoTiffTestFiles.geographic(1200, 1200, 8, 47, d, d, true).withNodata("-9999")
                .withCompression(GeoTiffTestFiles.DEFLATE, 2).withLayout(256, 0, java.nio.ByteOrder.LITTLE_ENDIAN);
        Path tif = aDir.resolve("Copernicus_DSM_COG_30_N46_00_E008_00_DEM.tif");
        GeoTiffTestFiles.write(tif, spec, (r, c) -> r >= 100 && r < 110 && c >= 200 && c < 230 ? -9999 : 500 + r % 7);
        Path hgt = HgtTestFiles.write(bDir, "N46E008.hgt", HgtTestFiles.bytes(1201, (r, c) -> 2000 + c % 5));
        // As-is, so that each sample tells its source (the default blend is tested below).
        PriorityDem p = new PriorityDem(List.of(new DemDirectory(aDir), new DemDirectory(bDir)), VoidFill.DEFAULT,
                PriorityDem.Blend.AS_IS);
        HgtTile t = p.tile(WEST).orElseThrow();
        assertEquals(500 + 104 % 7, t.heightMetres(104, 199));
        assertEquals(2000 + 210 % 5, t.heightMetres(105, 210));
        assertEquals(List.of(new DemContribution(tif.toString(), "EGM2008", 1201L * 1201 - 300),
                new DemContribution(hgt.toString(), "EGM96", 300)), t.contributions());
        assertSame(t, p.tile(WEST).orElseThrow(), "unchanged files: the cached merge");

        // B rewritten: the merge follows.
        HgtTestFiles.write(bDir, "N46E008.hgt", HgtTestFiles.bytes(1201, (r, c) -> 3000 + c % 5));
        Files.setLastModifiedTime(hgt, FileTime.fromMillis(Files.getLastModifiedTime(hgt).toMillis() + 2000));
        assertEquals(3000 + 210 % 5, p.tile(WEST).orElseThrow().heightMetres(105, 210));
        // A rewritten without the hole: A alone.
        GeoTiffTestFiles.write(tif, spec, (r, c) -> 600);
        Files.setLastModifiedTime(tif, FileTime.fromMillis(Files.getLastModifiedTime(tif).toMillis() + 2000));
        HgtTile again = p.tile(WEST).orElseThrow();
        assertEquals(600, again.heightMetres(105, 210));
        assertEquals(List.of(new DemContribution(tif.toString(), "EGM2008", 1201L * 1201)), again.contributions());
    }

    @Test
    void aTileFileRemovedAfterIndexingIsReportedByName() throws IOException {
        Path hgt = HgtTestFiles.write(dir, "N46E008.hgt", HgtTestFiles.bytes(1201, (r, c) -> 100));
        DemDirectory d = new DemDirectory(dir);
        assertEquals(100, d.tile(WEST).orElseThrow().heightMetres(5, 5));
        Files.delete(hgt);
        DemException e = assertThrows(DemException.class, () -> d.tile(WEST));
        assertEquals("tile N46E008: " + hgt + " is gone (removed since the folder was indexed)", e.getMessage());
    }

    @Test
    void anHgtAndAGeoTiffForOneTileInOneDirectoryAreAmbiguous() throws IOException {
        HgtTestFiles.write(dir, "N46E008.hgt", HgtTestFiles.bytes(1201, (r, c) -> 100));
        GeoTiffTestFiles.write(dir.resolve("N46E008.tif"), GeoTiffTestFiles.geographic(121, 121, 8, 47, 1 / 120.0, 1 / 120.0, true),
                (r, c) -> 100);
        DemException e = assertThrows(DemException.class, () -> new DemDirectory(dir).tile(WEST));
        assertTrue(e.getMessage().contains("is ambiguous") && e.getMessage().contains("N46E008.tif"), e.getMessage());
    }

    /**
     * Delta surface fill: B (a coarser grid, 30″ vs 60″) is another plane than A, so pasted in as it is
     * it leaves a step at the hole's rim; the difference A − B is then a plane too, which the thin-plate
     * (and Laplace) interpolation restores exactly in a void away from the tile border, so B plus the
     * interpolated difference is A's own plane in the hole.
     * Where B agrees with A, the delta is zero and B's heights go in unchanged.
     */
    @Test
    void theDeltaSurfaceBlendMeetsThePrimaryAtTheRimWithoutAStep() {
        for (VoidFill fill : List.of(VoidFill.THIN_PLATE, VoidFill.LAPLACE)) {
            HgtTile a = tile(WEST, 120, PriorityDemTest::fa, PriorityDemTest::hole, "A");
            HgtTile b = tile(WEST, 60, PriorityDemTest::fb, (r, c) -> false, "B");
            HgtTile asIs = PriorityDem.merge(a, List.of(b), fill, PriorityDem.Blend.AS_IS);
            HgtTile blended = PriorityDem.merge(a, List.of(b), fill, PriorityDem.Blend.DELTA_SURFACE);
            double step = Math.abs(asIs.heightMetres(30, 50) - asIs.heightMetres(29, 50));
            assertTrue(step > 500, "pasted in as it is, B leaves a step at the rim: " + step + " m");
            for (int r = 30; r < 50; r++) {
                for (int c = 40; c < 70; c++) {
                    double lat = 47 - r / 120.0, lon = 8 + c / 120.0;
                    assertEquals(fb(lat, lon), asIs.heightMetres(r, c), 2e-3, "as is " + r + ", " + c);
                    assertEquals(fa(lat, lon), blended.heightMetres(r, c), 0.05, fill + " blended " + r + ", " + c);
                }
            }
            assertEquals(List.of(121L * 121 - 600, 600L), blended.contributions().stream().map(DemContribution::samples).toList());
            assertEquals(0, blended.voids().voidCells());

            HgtTile truth = tile(WEST, 120, PriorityDemTest::fa, (r, c) -> false, "truth");
            HgtTile restored = PriorityDem.merge(a, List.of(truth), fill, PriorityDem.Blend.DELTA_SURFACE);
            for (int r = 0; r < 121; r++) {
                for (int c = 0; c < 121; c++) {
                    assertEquals(truth.heightMetres(r, c), restored.heightMetres(r, c), fill + " restored exactly at " + r + ", " + c);
                }
            }
        }
    }

    /**
     * The default is the best measured fill: thin-plate interpolation, delta-surface blend. Through the default
     * constructor B (another plane) fills A's hole with A's own plane (the A − B plane interpolated, added to B),
     * as with the blend named; B's samples are still counted as B's.
     */
    @Test
    void theDefaultIsTheDeltaSurfaceBlendWithTheThinPlateFill() throws IOException {
        assertEquals(new DemFill(VoidFill.THIN_PLATE, PriorityDem.Blend.DELTA_SURFACE), DemFill.DEFAULT);
        DemSource a = new InMemoryDem("A", List.of(tile(WEST, 120, PriorityDemTest::fa, PriorityDemTest::hole, "A/N46E008")));
        DemSource b = new InMemoryDem("B", List.of(tile(WEST, 60, PriorityDemTest::fb, (r, c) -> false, "B/N46E008")));
        PriorityDem p = new PriorityDem(List.of(a, b));
        assertEquals(DemFill.DEFAULT, p.fill());
        HgtTile t = p.tile(WEST).orElseThrow();
        for (int r = 30; r < 50; r++) {
            for (int c = 40; c < 70; c++) {
                assertEquals(fa(47 - r / 120.0, 8 + c / 120.0), t.heightMetres(r, c), 0.05, "default blend at " + r + ", " + c);
            }
        }
        assertEquals(List.of(new DemContribution("A/N46E008", "unknown", 121 * 121 - 600),
                new DemContribution("B/N46E008", "unknown", 600)), t.contributions());

        // Opened from folders as the command line does: the fill asked for is the one used; one folder is itself.
        Path one = Files.createDirectory(dir.resolve("one")), two = Files.createDirectory(dir.resolve("two"));
        HgtTestFiles.write(one, "N46E008.hgt", HgtTestFiles.bytes(1201, (r, c) -> 100));
        HgtTestFiles.write(two, "N46E008.hgt", HgtTestFiles.bytes(1201, (r, c) -> 200));
        List<String> warnings = new java.util.ArrayList<>();
        Files.writeString(one.resolve("N99E999.hgt"), "x");
        DemFill idwAsIs = new DemFill(VoidFill.IDW, PriorityDem.Blend.AS_IS);
        DemSource both = PriorityDem.open(List.of(one, two), idwAsIs, warnings::add);
        assertEquals(idwAsIs, ((PriorityDem) both).fill());
        assertTrue(PriorityDem.open(List.of(one), DemFill.DEFAULT, w -> { }) instanceof DemDirectory);
        assertEquals(1, warnings.size(), warnings.toString());
        assertTrue(warnings.get(0).contains("N99E999.hgt"), warnings.toString());
        assertThrows(IllegalArgumentException.class, () -> PriorityDem.open(List.of(), DemFill.DEFAULT, w -> { }));
    }

    /**
     * Issue 20: a two-source render where B holds the true heights of A's voids restores them exactly, with the
     * default (delta-surface) blend. A is the real N46E008 with a 101 × 201-sample hole punched into the terrain
     * south of the viewpoint (on top of its own SRTM voids); B is the tile as it is. On every sample where both
     * have data A − B is 0, so the interpolated difference is 0 and B's heights go in unchanged; the voids
     * neither has are interpolated from the same samples as B's own. So the merged tile equals B's, sample for
     * sample, and the panorama from (A, B) equals the one from B alone, bit for bit.
     */
    @Test
    void aTwoSourceRenderWhereBHoldsTheTruthOfAsVoidsRestoresThemExactly() throws IOException {
        Path hgt = dempano.SharedData.demFile("N46E008.hgt");
        byte[] bytes = Files.readAllBytes(hgt);
        int n = 1201, punched = 0;
        for (int r = 560; r <= 660; r++) {
            for (int c = 300; c <= 500; c++) {
                int i = 2 * (r * n + c);
                punched += bytes[i] == (byte) 0x80 && bytes[i + 1] == 0 ? 0 : 1;
                bytes[i] = (byte) 0x80;
                bytes[i + 1] = 0;
            }
        }
        assertTrue(punched > 15_000, "the hole lies mostly on valid data: " + punched);
        Path aDir = Files.createDirectory(dir.resolve("a"));
        HgtTestFiles.write(aDir, "N46E008.hgt", bytes);
        DemDirectory b = new DemDirectory(hgt.getParent());
        PriorityDem ab = new PriorityDem(List.of(new DemDirectory(aDir), b));
        assertEquals(PriorityDem.Blend.DELTA_SURFACE, ab.fill().blend());
        HgtTile truth = b.tile(WEST).orElseThrow(), merged = ab.tile(WEST).orElseThrow();
        for (int r = 0; r < n; r++) {
            for (int c = 0; c < n; c++) {
                assertEquals(Float.floatToIntBits(truth.heightMetres(r, c)), Float.floatToIntBits(merged.heightMetres(r, c)),
                        "sample " + r + ", " + c);
                assertEquals(truth.isFilledVoid(r, c), merged.isFilledVoid(r, c), "void at " + r + ", " + c);
            }
        }
        assertEquals(punched, merged.contributions().get(1).samples(), "B served the punched samples");

        // The hole lies 4–12 km south of the viewpoint, in view.
        dempano.PanoramaRequest req = dempano.PanoramaRequest.at(46.57, 8.33).withRangeMetres(15_000).withPixelsPerDegree(2)
                .withColour(true);
        dempano.panorama.Panorama fromB, fromAb;
        try (dempano.PanoramaRenderer r = dempano.PanoramaRenderer.openReference(b)) {
            fromB = r.render(req);
        }
        try (dempano.PanoramaRenderer r = dempano.PanoramaRenderer.openReference(ab)) {
            fromAb = r.render(req);
        }
        org.junit.jupiter.api.Assertions.assertArrayEquals(fromB.distanceArray(), fromAb.distanceArray(), "distances");
        for (int y = 0; y < fromB.heightPx(); y++) {
            for (int x = 0; x < fromB.widthPx(); x++) {
                assertEquals(fromB.argb(x, y), fromAb.argb(x, y), "colour at " + x + ", " + y);
            }
        }
    }
}
