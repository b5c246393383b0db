package dempano.terrain;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.Synthetic;
import dempano.dem.DemSource;
import dempano.dem.HgtTile;
import dempano.dem.InMemoryDem;
import dempano.dem.MissingTilePolicy;
import dempano.dem.Mosaic;
import dempano.dem.TileId;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

/**
 * The in-memory caches ({@link DeviationCache}, {@link MeshCache}) key entries by place only; {@link TileVersions}
 * tells them which entries a changed tile makes stale. A tile read again with the same heights is no change (a
 * source's cache evicted it); other heights are, and so is a tile appearing where sea level was.
 */
class TileVersionsTest {
    private static final double LAT = 46.5, LON = 8.5, RANGE = 40_000;
    private static final int[][] BLOCK = Synthetic.block(45, 7, 3, 3);

    /** The relief of TerrainBuilderTest, raised by {@code bump} metres in a small area north-east of the eye. */
    private static InMemoryDem dem(double bump) {
        return dem(bump, 46.60, 8.60);
    }

    /** The same, the bump's south-west corner given (it spans 0.02° north, 0.03° east). */
    private static InMemoryDem dem(double bump, double latDeg, double lonDeg) {
        return Synthetic.tiles((lat, lon) -> TerrainBuilderTest.relief(lat, lon)
                + (lat > latDeg && lat < latDeg + 0.02 && lon > lonDeg && lon < lonDeg + 0.03 ? bump : 0), Synthetic.N, BLOCK);
    }

    /** {@code dem} without one tile (held at sea level). */
    private static DemSource without(DemSource dem, TileId gone) {
        return new DemSource() {
            @Override
            public Optional<HgtTile> tile(TileId id) {
                return id.equals(gone) ? Optional.empty() : dem.tile(id);
            }

            @Override
            public String describe() {
                return "without " + gone;
            }
        };
    }

    private static Mosaic mosaic(DemSource dem) {
        return Mosaic.around(dem, LAT, LON, RANGE, MissingTilePolicy.SEA_LEVEL);
    }

    @Test
    void theSameHeightsAreNoChangeOtherHeightsAndAppearingTilesAre() {
        TileVersions versions = new TileVersions();
        InMemoryDem plain = dem(0);
        TileId bumpedTile = TileId.of(46, 8);
        assertEquals(List.of(), versions.changed(mosaic(plain)), "first sight");
        assertEquals(List.of(), versions.changed(mosaic(plain)), "the same objects");
        assertEquals(List.of(), versions.changed(mosaic(dem(0))), "new objects, the same heights (read again)");
        assertEquals(List.of(bumpedTile), versions.changed(mosaic(dem(250))), "one tile's heights changed");
        assertEquals(List.of(bumpedTile), versions.changed(mosaic(plain)), "and changed back");
        TileId gone = TileId.of(46, 9);
        assertEquals(List.of(gone), versions.changed(mosaic(without(plain, gone))), "a tile gone: sea level there");
        assertEquals(List.of(), versions.changed(mosaic(without(plain, gone))), "still gone");
        assertEquals(List.of(gone), versions.changed(mosaic(plain)), "a tile appearing where sea level was");

        // Tiles seen once and no longer held by anyone (a source's cache let them go), then read again with the
        // same heights: no change, whether or not they were collected meanwhile.
        TileVersions once = new TileVersions();
        assertEquals(List.of(), once.changed(mosaic(dem(0))));
        System.gc();
        assertEquals(List.of(), once.changed(mosaic(dem(0))));
        assertEquals(List.of(bumpedTile), once.changed(mosaic(dem(250))));
    }

    /** Tile N46E008 at 1200 intervals a degree: rows 43 × 1200 … 44 × 1200, columns 188 × 1200 … 189 × 1200. */
    @ParameterizedTest(name = "patch at row {0}, column {1}: {2}")
    @CsvSource({
            "51600, 225600, true",   // its north-west corner
            "52736, 226736, true",   // inside, near its south-east corner
            "51536, 225600, true",   // north of it, ending on its north edge row
            "51534, 225600, true",   // ending 2 samples north of it: within the margin
            "51533, 225600, false",  // ending 3 samples north of it
            "52802, 225600, true",   // starting 2 samples south of its south edge
            "52803, 225600, false",  // starting 3 samples south of it
            "51600, 225534, true",   // ending 2 samples west of its west edge
            "51600, 225533, false",  // ending 3 samples west of it
            "51600, 226802, true",   // starting 2 samples east of its east edge
            "51600, 226803, false",  // starting 3 samples east of it
            "52803, 226803, false",  // diagonally beyond its south-east corner
    })
    void aPatchTouchesATileWithinTwoSamples(long row, long col, boolean touches) {
        assertEquals(touches, TileVersions.touches(TileId.of(46, 8), 1200, row, col));
    }

    @Test
    void patchesAcrossTheAntimeridianTouchTheTileOnTheOtherSide() {
        int n = 1200;
        // Tile N00E179 ends at 180°: column 360 × 1200 is also column 0 of the grid counted from 180°W.
        assertTrue(TileVersions.touches(TileId.of(0, 179), n, 89L * n, 0));
        assertTrue(TileVersions.touches(TileId.of(0, -180), n, 89L * n, 360L * n - 64));
        assertTrue(TileVersions.touches(TileId.of(0, -180), n, 89L * n, 360L * n + 64)); // a mosaic past 180°E
        assertEquals(false, TileVersions.touches(TileId.of(0, 179), n, 89L * n, 100));
    }

    @Test
    void aChangedTileDropsItsPatchesOnlyAndTheTerrainIsThatOfAFreshCache() {
        // An eye 1.5 km west of the tiles' shared edge at 9°E: the meshes kept (fine patches near the eye) lie in both.
        double lon = 8.98;
        DeviationCache cache = new DeviationCache();
        MeshCache meshes = new MeshCache();
        TerrainBuilder.Terrain first = TerrainBuilderTest.build(dem(0), LAT, lon, RANGE, cache, meshes);
        int patches = meshes.size();
        assertTrue(patches > 20, patches + " meshes kept");

        // The same heights read again: nothing dropped, every mesh reused.
        TerrainBuilder.Terrain again = TerrainBuilderTest.build(dem(0), LAT, lon, RANGE, cache, meshes);
        assertEquals(patches, again.reusedPatches());
        assertEquals(List.of(), again.evicted());

        // Other heights in the tile east of the edge (a bump 3 km from the eye): its patches (and those within two
        // samples of it) are built again, those west of the edge reused, and the terrain is a fresh cache's.
        InMemoryDem bumped = dem(250, 46.49, 9.02);
        TerrainBuilder.Terrain after = TerrainBuilderTest.build(bumped, LAT, lon, RANGE, cache, meshes);
        TerrainBuilder.Terrain fresh = TerrainBuilderTest.build(bumped, LAT, lon, RANGE, new DeviationCache(), new MeshCache());
        assertArrayEquals(fresh.patchesPerLevel(), after.patchesPerLevel());
        assertEquals(fresh.triangles(), after.triangles());
        assertEquals(fresh.vertices(), after.vertices());
        assertEquals(shapes(fresh), shapes(after), "every geometry's vertices as a fresh cache builds them");
        assertTrue(!shapes(fresh).equals(shapes(again)), "the bump changes vertices");
        assertTrue(after.evicted().size() > 0, "the changed tile's meshes are released");
        assertTrue(after.reusedPatches() > 0 && after.reusedPatches() < again.reusedPatches(),
                after.reusedPatches() + " of " + again.reusedPatches() + " patches reused");
        assertTrue(after.evicted().stream().noneMatch(after.drawn()::contains), "no released mesh is drawn");
    }

    @Test
    void deviationsKeptInMemoryAreMeasuredAgainForAChangedTile() {
        DeviationCache cache = new DeviationCache();
        TerrainBuilder.Terrain plain = TerrainBuilderTest.build(dem(0), LAT, LON, RANGE, cache);
        InMemoryDem bumped = dem(250);
        TerrainBuilder.Terrain fresh = TerrainBuilderTest.build(bumped, LAT, LON, RANGE, new DeviationCache());
        assertTrue(fresh.triangles() != plain.triangles(), "the bump changes the level of detail somewhere");
        TerrainBuilder.Terrain after = TerrainBuilderTest.build(bumped, LAT, LON, RANGE, cache);
        assertArrayEquals(fresh.patchesPerLevel(), after.patchesPerLevel());
        assertEquals(fresh.triangles(), after.triangles());
        assertEquals(0, cache.forgetChanged(mosaic(bumped)), "seen already");
        assertTrue(cache.forgetChanged(mosaic(dem(0))) > 0, "changed back: its patches dropped");
    }

    /** Each drawn geometry's vertex data (every buffer, element by element), hashed; sorted. */
    private static List<Integer> shapes(TerrainBuilder.Terrain t) {
        List<Integer> out = new java.util.ArrayList<>();
        for (com.jme3.scene.Geometry g : t.drawn()) {
            int h = 1;
            for (com.jme3.scene.VertexBuffer b : g.getMesh().getBufferList()) {
                java.nio.Buffer data = b.getData();
                for (int i = 0; i < data.limit(); i++) {
                    h = 31 * h + switch (b.getFormat()) {
                        case Float -> Float.floatToIntBits(((java.nio.FloatBuffer) data).get(i));
                        case Int, UnsignedInt -> ((java.nio.IntBuffer) data).get(i);
                        case Short, UnsignedShort -> ((java.nio.ShortBuffer) data).get(i);
                        case Byte, UnsignedByte -> ((java.nio.ByteBuffer) data).get(i);
                        default -> throw new IllegalStateException("format " + b.getFormat());
                    };
                }
            }
            out.add(h);
        }
        out.sort(null);
        return out;
    }
}
