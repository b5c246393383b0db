package dempano.summits;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.SharedData;
import dempano.Synthetic;
import dempano.dem.DemDirectory;
import dempano.geo.Geodesy;
import dempano.panorama.DistanceComparison;
import dempano.panorama.ElevationRange;
import dempano.panorama.Panorama;
import java.util.List;
import java.util.function.DoubleBinaryOperator;
import org.junit.jupiter.api.Test;

class SummitProjectorTest {
    static final double EYE_LAT = 46.5, EYE_LON = 8.5;
    // Peak A 2500 m (a cone) on a grid node, open to the eye; peak B 1700 m due south behind a 2000 m ridge.
    static final double A_LAT = 46.60, A_LON = 8.62, B_LAT = 46.35, B_LON = 8.5;
    static final DoubleBinaryOperator TERRAIN = (lat, lon) -> {
        double kx = 111_195 * Math.cos(Math.toRadians(46.5)), ky = 111_195;
        double ax = (lon - A_LON) * kx, ay = (lat - A_LAT) * ky;
        double bx = (lon - B_LON) * kx, by = (lat - B_LAT) * ky;
        double ry = (lat - 46.45) * ky;
        // A is a cone (slope 1:2): a rounded top would put the first pixel under the summit on its
        // front flank, a fraction of a pixel nearer than the summit itself.
        return 500 + 2000 * Math.max(0, 1 - Math.hypot(ax, ay) / 4000)
                + 1200 * Math.exp(-(bx * bx + by * by) / (2 * 1500.0 * 1500))
                + 1500 * Math.exp(-ry * ry / (2 * 800.0 * 800)) * (Math.abs(lon - EYE_LON) < 0.3 ? 1 : 0);
    };

    @Test
    void syntheticPeaksAreFoundAtTheirPixelAndDistanceAndTheHiddenOneIsHidden() {
        Panorama p;
        try (PanoramaRenderer r = PanoramaRenderer.open(Synthetic.dem(TERRAIN, 45, 7, 3, 3))) {
            p = r.render(PanoramaRequest.at(EYE_LAT, EYE_LON).withRangeMetres(40_000)
                    .withElevationRange(new ElevationRange(-5, 20, false)));
        }
        SummitList list = SummitList.of("synthetic", List.of(new Summit("A", A_LAT, A_LON, 2500),
                new Summit("B", B_LAT, B_LON, 1700 + 0.0), new Summit("far away", 47.5, 8.5, 3000)));
        List<SummitSighting> seen = p.summits(list);
        assertEquals(2, seen.size(), "the summit 111 km away is beyond the 40 km range");
        SummitSighting a = seen.get(0), b = seen.get(1);
        assertTrue(a.visible(), a.toString());
        assertFalse(b.visible(), b.toString());
        // B's pixel shows the ridge, 5.5 km away instead of 16.7 km.
        assertTrue(b.seenDistanceMetres() < 8_000, b.toString());
        // A: azimuth is the geodesic azimuth; the skyline's top lies in A's column (within one pixel)
        // and the topmost terrain row there is the row of A's projected top (within one pixel).
        assertEquals(Geodesy.azimuthDeg(EYE_LAT, EYE_LON, A_LAT, A_LON), a.azimuthDeg(), 0.01);
        float[] d = p.distanceArray();
        int c0 = (int) Math.floor(a.pixelX()), best = c0, bestRow = Integer.MAX_VALUE;
        for (int c = c0 - 40; c <= c0 + 40; c++) {
            int row = DistanceComparison.skylineRow(d, p.widthPx(), p.heightPx(), c);
            if (row < bestRow) {
                bestRow = row;
                best = c;
            }
        }
        // A plateau of equal rows: take its middle.
        int last = best;
        while (DistanceComparison.skylineRow(d, p.widthPx(), p.heightPx(), last + 1) == bestRow) {
            last++;
        }
        assertEquals(a.pixelX(), (best + last) / 2.0 + 0.5, 1.0, "summit column");
        assertEquals(a.pixelY(), bestRow + 0.5, 1.0, "summit row");
        assertEquals(a.slantMetres(), a.seenDistanceMetres(), a.slantMetres() * 0.005, "distance within 0.5 %");
    }

    @Test
    void aSummitWithoutAHeightIsPlacedAtTheDemsHeightWithinRangeOnly() {
        Panorama p;
        dempano.dem.DemSource dem = Synthetic.dem(TERRAIN, 45, 7, 3, 3);
        try (PanoramaRenderer r = PanoramaRenderer.open(dem)) {
            p = r.render(PanoramaRequest.at(EYE_LAT, EYE_LON).withRangeMetres(40_000)
                    .withElevationRange(new ElevationRange(-5, 20, false)));
        }
        // A again without its height; one 111 km away on a tile the DEM has (beyond the range: not looked up);
        // one where the eye stands.
        SummitList list = SummitList.of("synthetic", List.of(new Summit("A", A_LAT, A_LON, 2500),
                new Summit("A, no height", A_LAT, A_LON, Double.NaN), new Summit("far, no height", 47.5, 8.5, Double.NaN),
                new Summit("here", EYE_LAT, EYE_LON, 2000)));
        SummitList placed = SummitProjector.placedOnDem(list, dem, p.metadata());
        Summit noHeight = placed.summits().get(1);
        // A lies on a grid node: the DEM's height there is the cone's apex, 2500 m.
        assertEquals(2500, noHeight.elevationMetres(), 0.01);
        assertTrue(noHeight.elevationFromDem());
        assertFalse(placed.summits().get(0).elevationFromDem());
        assertTrue(Double.isNaN(placed.summits().get(2).elevationMetres()), "beyond the range: not placed");
        assertEquals(list.summits().get(0), placed.summits().get(0));

        List<SummitSighting> seen = p.summits(placed);
        assertEquals(2, seen.size(), "A twice; the far one and the one at the eye are left out");
        assertEquals(seen.get(0).pixelX(), seen.get(1).pixelX(), 1e-6);
        assertEquals(seen.get(0).pixelY(), seen.get(1).pixelY(), 1e-3);
        assertTrue(seen.get(1).visible(), seen.get(1).toString());
        String listWarning = "2 of the 4 summits in synthetic have no elevation (e.g. A, no height): each is placed at"
                + " the DEM's height at its position, a little low where the DEM flattens a summit";
        String atTheEye = "summit here is where the eye stands: it has no direction from there and is left out";
        assertEquals(List.of(listWarning, atTheEye), SummitProjector.warnings(placed, p.metadata()));
        // Not placed: the one within range is said to be left out (the far one, beyond the range, is not named).
        assertEquals(List.of(listWarning, "1 of them within range has no DEM height either and is left out (e.g. A, no height)",
                atTheEye),
                SummitProjector.warnings(list, p.metadata()));
    }

    @Test
    void alpesMaritimesSummitsFromTheSurveyList() throws Exception {
        SummitList alps = SummitReader.read(SharedData.require("peaks/alps.txt"), false);
        Panorama p;
        try (PanoramaRenderer r = PanoramaRenderer.open(new DemDirectory(SharedData.demDir()))) {
            p = r.render(PanoramaRequest.at(43.8167, 6.9667)); // Cime du Cheiron, 100 km
        }
        List<SummitSighting> seen = p.summits(alps);
        List<SummitSighting> visible = seen.stream().filter(SummitSighting::visible).toList();
        assertTrue(seen.size() > 500, "summits within 100 km: " + seen.size());
        // North of 44N the tiles are missing (sea level): nothing there can be seen.
        assertTrue(seen.stream().noneMatch(s -> s.visible() && s.summit().latDeg() > 44), "a summit in a missing tile seen");
        assertTrue(visible.size() >= 3, "visible: " + visible);
        assertTrue(visible.stream().anyMatch(s -> s.summit().name().equals("POINTE DE QUATRE CANTONS")), visible.toString());
        for (SummitSighting s : visible) {
            // Surveyed position and height against the DEM's: within 0.5 % at 20+ km.
            assertEquals(s.slantMetres(), s.seenDistanceMetres(), s.slantMetres() * 0.005, s.toString());
        }
    }
}
