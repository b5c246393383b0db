package dempano.terrain;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.Synthetic;
import dempano.dem.DemSource;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@link DeviationStore}'s cache contract: deviations kept on disk are served to a later process (here a fresh
 * {@link DeviationCache}) only for the heights they were measured from; a changed tile is measured again, never
 * served stale; files that cannot be read are ignored and rewritten; a folder that cannot be written leaves the
 * build as it is without a store. Each build is compared with one that has no store at all.
 */
class DeviationStoreTest {
    private static final double LAT = 46.5, LON = 8.5, RANGE = 40_000;

    private static DemSource dem(double bump) {
        // The relief of TerrainBuilderTest, raised by `bump` metres in a small area north-east of the eye.
        return Synthetic.tiles((lat, lon) -> TerrainBuilderTest.relief(lat, lon)
                + (lat > 46.60 && lat < 46.62 && lon > 8.60 && lon < 8.63 ? bump : 0), Synthetic.N,
                Synthetic.block(45, 7, 3, 3));
    }

    private static TerrainBuilder.Terrain build(DemSource dem, DeviationStore store) {
        DeviationCache cache = new DeviationCache();
        cache.useDisk(store);
        return TerrainBuilderTest.build(dem, LAT, LON, RANGE, cache);
    }

    private static void assertSameTerrain(TerrainBuilder.Terrain expected, TerrainBuilder.Terrain actual) {
        assertArrayEquals(expected.patchesPerLevel(), actual.patchesPerLevel());
        assertEquals(expected.triangles(), actual.triangles());
        assertEquals(expected.vertices(), actual.vertices());
    }

    @Test
    void aLaterProcessIsServedTheSameDeviationsAndAChangedTileIsMeasuredAgain(@TempDir Path dir) {
        DemSource plain = dem(0), bumped = dem(250);
        TerrainBuilder.Terrain without = TerrainBuilderTest.build(plain, LAT, LON, RANGE, new DeviationCache());

        DeviationStore first = DeviationStore.in(dir);
        assertSameTerrain(without, build(plain, first));
        assertEquals(0, first.hits());
        long patches = first.misses();
        assertTrue(patches > 50, patches + " patches");
        assertNull(first.lastWriteError());

        DeviationStore second = DeviationStore.in(dir); // as a later process finds it
        assertSameTerrain(without, build(plain, second));
        assertEquals(patches, second.hits(), "every patch served from disk");
        assertEquals(0, second.misses());

        // The same places, other heights: those patches are measured again, and the result is the changed DEM's.
        DeviationStore third = DeviationStore.in(dir);
        TerrainBuilder.Terrain bumpedWithout = TerrainBuilderTest.build(bumped, LAT, LON, RANGE, new DeviationCache());
        assertSameTerrain(bumpedWithout, build(bumped, third));
        assertTrue(third.misses() > 0 && third.misses() < 20, third.misses() + " patches measured again");
        assertEquals(patches, third.hits() + third.misses());
        assertTrue(bumpedWithout.triangles() != without.triangles(), "the bump changes the level of detail somewhere");

        DeviationStore fourth = DeviationStore.in(dir); // and the new entries replaced the old ones
        assertSameTerrain(bumpedWithout, build(bumped, fourth));
        assertEquals(patches, fourth.hits());
    }

    @Test
    void filesThatCannotBeReadAreIgnoredAndRewritten(@TempDir Path root) throws IOException {
        DemSource plain = dem(0);
        TerrainBuilder.Terrain without = TerrainBuilderTest.build(plain, LAT, LON, RANGE, new DeviationCache());
        for (String damage : List.of("truncated", "foreign", "one bit of a value", "another format")) {
            Path dir = Files.createDirectory(root.resolve(damage.replace(' ', '-')));
            build(plain, DeviationStore.in(dir));
            List<Path> files;
            try (Stream<Path> s = Files.walk(dir)) {
                files = s.filter(p -> p.toString().endsWith(".dev")).toList();
            }
            assertTrue(!files.isEmpty());
            for (Path f : files) {
                byte[] bytes = Files.readAllBytes(f);
                switch (damage) {
                    case "truncated" -> Files.write(f, java.util.Arrays.copyOf(bytes, bytes.length / 2));
                    case "foreign" -> Files.write(f, "not a deviation file".getBytes());
                    case "one bit of a value" -> {
                        // The last stored value (the file's last 4 bytes are its checksum): still well formed, and the
                        // heights' hashes still match, so only the checksum tells.
                        bytes[bytes.length - 5] ^= 0x40;
                        Files.write(f, bytes);
                    }
                    default -> {
                        bytes[7] ^= 1; // another format number
                        Files.write(f, bytes);
                    }
                }
            }
            DeviationStore second = DeviationStore.in(dir);
            assertSameTerrain(without, build(plain, second));
            assertEquals(0, second.hits(), damage + ": nothing served");
            DeviationStore third = DeviationStore.in(dir);
            assertSameTerrain(without, build(plain, third));
            assertEquals(second.misses(), third.hits(), damage + ": rewritten whole");
            try (Stream<Path> s = Files.walk(dir)) {
                assertTrue(s.noneMatch(p -> p.toString().endsWith(".part")), "no file left aside");
            }
        }
    }

    @Test
    void aFolderThatCannotBeWrittenLeavesTheBuildAsWithoutAStore(@TempDir Path dir) throws IOException {
        Path blocked = dir.resolve("blocked");
        Files.writeString(blocked, "a file where the folder would be");
        DemSource plain = dem(0);
        DeviationStore store = DeviationStore.in(blocked);
        assertSameTerrain(TerrainBuilderTest.build(plain, LAT, LON, RANGE, new DeviationCache()), build(plain, store));
        assertNotNull(store.lastWriteError());
        assertTrue(store.lastWriteError().contains(blocked.toString()), store.lastWriteError());
    }

    @Test
    void theHashesTellApartHeightsThatDifferInOneSample() {
        float[] a = new float[65 * 65];
        for (int i = 0; i < a.length; i++) {
            a[i] = (float) (1000 + 100 * Math.sin(i * 0.37));
        }
        float[] b = a.clone();
        b[4000] = Math.nextUp(b[4000]);
        float[] c = a.clone();
        c[0] = a[1];
        c[1] = a[0]; // two samples swapped
        assertEquals(DeviationStore.hashA(a), DeviationStore.hashA(a.clone()));
        assertEquals(DeviationStore.hashB(a), DeviationStore.hashB(a.clone()));
        for (float[] other : new float[][] {b, c}) {
            assertTrue(DeviationStore.hashA(a) != DeviationStore.hashA(other));
            assertTrue(DeviationStore.hashB(a) != DeviationStore.hashB(other));
        }
    }
}
