package dempano.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.Synthetic;
import dempano.dem.InMemoryDem;
import dempano.panorama.DistanceComparison;
import dempano.panorama.ElevationRange;
import dempano.panorama.Panorama;
import java.util.function.DoubleBinaryOperator;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * Simplified terrain against the exact reference on rugged synthetic relief: the error stays near
 * the bound, the mesh shrinks, and skirts leave no cracks (no sky under terrain) even at a crude bound.
 */
class LevelOfDetailRenderTest {
    static final double LAT = 46.5, LON = 8.5;
    // Massifs and ridges of several wavelengths (20 km to 2 km): coarse levels lose real detail.
    static final DoubleBinaryOperator RUGGED = (lat, lon) -> {
        double y = (lat - LAT) * 111_195, x = (lon - LON) * 76_500;
        return 1200 + 700 * Math.sin(x / 3100) * Math.cos(y / 4300) + 250 * Math.sin((x + 2 * y) / 1900)
                + 60 * Math.cos((3 * x - y) / 2000);
    };
    static InMemoryDem dem;
    static PanoramaRenderer gl;

    @BeforeAll
    static void open() {
        dem = Synthetic.dem(RUGGED, 46, 8, 1, 1);
        gl = PanoramaRenderer.open(dem);
    }

    @AfterAll
    static void close() {
        gl.close();
    }

    static PanoramaRequest request(double lodPx) {
        return PanoramaRequest.at(LAT, LON).withRangeMetres(45_000).withEyeHeightMetres(30).withPixelsPerDegree(10)
                .withElevationRange(new ElevationRange(-20, 15, false)).withLodErrorPx(lodPx);
    }

    /** Pixels showing sky below terrain in the same column: a crack in the mesh (impossible on a heightfield). */
    static int skyBelowTerrain(Panorama p) {
        int holes = 0;
        for (int c = 0; c < p.widthPx(); c++) {
            boolean terrainAbove = false;
            for (int r = 0; r < p.heightPx(); r++) {
                boolean sky = !Float.isFinite(p.distanceMetres(c, r));
                if (!sky) {
                    terrainAbove = true;
                } else if (terrainAbove) {
                    holes++;
                }
            }
        }
        return holes;
    }

    @Test
    void halfPixelBoundKeepsTheDefaultAccuracyWithFewerTriangles() {
        Panorama ref;
        try (PanoramaRenderer cpu = PanoramaRenderer.openReference(dem)) {
            ref = cpu.render(request(0));
        }
        Panorama full = gl.render(request(0));
        Panorama lod = gl.render(request(0.5));
        DistanceComparison cFull = DistanceComparison.of(full.distanceArray(), ref.distanceArray(), ref.widthPx());
        DistanceComparison cLod = DistanceComparison.of(lod.distanceArray(), ref.distanceArray(), ref.widthPx());
        long tFull = full.metadata().terrainTriangles(), tLod = lod.metadata().terrainTriangles();
        System.out.printf("full: %d triangles %s%nlod 0.5 px: %d triangles %s%n", tFull, cFull, tLod, cLod);
        assertTrue(tLod < tFull / 2, "triangles " + tLod + " vs " + tFull);
        // The accuracy issue's default targets: median < 0.1 %, p99 < 1 %, skyline < 0.5 px.
        assertTrue(cLod.medianRelative() < 1e-3, "median " + cLod);
        assertTrue(cLod.p99Relative() < 0.01, "p99 " + cLod);
        assertTrue(cLod.skylineMeanAbsPx() < 0.5, "skyline " + cLod);
        assertTrue(cLod.skylineMaxAbsPx() <= 2, "skyline " + cLod);
        assertEquals(0, skyBelowTerrain(lod));
        assertEquals(0, skyBelowTerrain(full));
    }

    @Test
    void crudeBoundStillLeavesNoCracks() {
        Panorama crude = gl.render(request(20));
        assertEquals(0, skyBelowTerrain(crude), "sky seen through cracks between patches");
        assertTrue(crude.metadata().terrainTriangles() > 0);
        assertFalse(Double.isNaN(crude.metadata().lodErrorPx()));
    }

    @Test
    void badBoundIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> request(-1));
        assertThrows(IllegalArgumentException.class, () -> request(Double.NaN));
    }
}
