package dempano;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.dem.MissingTilePolicy;
import dempano.geo.Refraction;
import dempano.panorama.DepthMode;
import dempano.panorama.ElevationRange;
import dempano.panorama.Layer;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;
import java.util.function.UnaryOperator;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

/** The request's groups: each {@code with…} changes its own value and nothing else; checks stay where they were. */
class PanoramaRequestTest {
    /** Every value the request holds, read directly, by name. */
    static final Map<String, Function<PanoramaRequest, Object>> VALUES = new LinkedHashMap<>();

    static {
        VALUES.put("latDeg", PanoramaRequest::latDeg);
        VALUES.put("lonDeg", PanoramaRequest::lonDeg);
        VALUES.put("offsetMetres", PanoramaRequest::offsetMetres);
        VALUES.put("altitudeMetres", PanoramaRequest::altitudeMetres);
        VALUES.put("eyeHeightMetres", PanoramaRequest::eyeHeightMetres);
        VALUES.put("snapToSummitMetres", PanoramaRequest::snapToSummitMetres);
        VALUES.put("clearViewMetres", PanoramaRequest::clearViewMetres);
        VALUES.put("rangeMetres", PanoramaRequest::rangeMetres);
        VALUES.put("pixelsPerDegree", PanoramaRequest::pixelsPerDegree);
        VALUES.put("elevationRange", PanoramaRequest::elevationRange);
        VALUES.put("refraction", PanoramaRequest::refraction);
        VALUES.put("missingTiles", PanoramaRequest::missingTiles);
        VALUES.put("depthMode", PanoramaRequest::depthMode);
        VALUES.put("nearMetres", PanoramaRequest::nearMetres);
        VALUES.put("supersampling", PanoramaRequest::supersampling);
        VALUES.put("views", PanoramaRequest::views);
        VALUES.put("lodErrorPx", PanoramaRequest::lodErrorPx);
        VALUES.put("colour", PanoramaRequest::colour);
        VALUES.put("distance", PanoramaRequest::distance);
        VALUES.put("exactDistances", PanoramaRequest::exactDistances);
        VALUES.put("layers", PanoramaRequest::layers);
    }

    /** Per value, a change away from the default. */
    static final Map<String, UnaryOperator<PanoramaRequest>> CHANGES = new LinkedHashMap<>();

    static {
        CHANGES.put("offsetMetres", r -> r.withOffsetMetres(12.5));
        CHANGES.put("altitudeMetres", r -> r.withAltitudeMetres(2100));
        CHANGES.put("eyeHeightMetres", r -> r.withEyeHeightMetres(7));
        CHANGES.put("snapToSummitMetres", r -> r.withSnapToSummitMetres(80));
        CHANGES.put("clearViewMetres", r -> r.withClearViewMetres(60));
        CHANGES.put("rangeMetres", r -> r.withRangeMetres(42_000));
        CHANGES.put("pixelsPerDegree", r -> r.withPixelsPerDegree(8));
        CHANGES.put("elevationRange", r -> r.withElevationRange(new ElevationRange(-7, 11, false)));
        CHANGES.put("refraction", r -> r.withRefraction(new Refraction(0.2)));
        CHANGES.put("missingTiles", r -> r.withMissingTiles(MissingTilePolicy.ERROR));
        CHANGES.put("depthMode", r -> r.withDepthMode(DepthMode.values()[(DepthMode.SHADER_RANGE.ordinal() + 1) % DepthMode.values().length]));
        CHANGES.put("nearMetres", r -> r.withNearMetres(3));
        CHANGES.put("supersampling", r -> r.withSupersampling(2));
        CHANGES.put("views", r -> r.withViews(12));
        CHANGES.put("lodErrorPx", r -> r.withLodErrorPx(1.5));
        CHANGES.put("colour", r -> r.withColour(false));
        CHANGES.put("distance", r -> r.withDistance(false));
        CHANGES.put("exactDistances", r -> r.withExactDistances(false));
        CHANGES.put("layers", r -> r.withLayers(Set.of(Layer.values()[0])));
    }

    @Test
    void eachWithChangesItsOwnValueAndNoOther() {
        PanoramaRequest base = PanoramaRequest.at(46.43, 8.09);
        assertEquals(VALUES.size() - 2, CHANGES.size(), "a change for every value but the coordinates");
        for (Map.Entry<String, UnaryOperator<PanoramaRequest>> change : CHANGES.entrySet()) {
            PanoramaRequest changed = change.getValue().apply(base);
            for (Map.Entry<String, Function<PanoramaRequest, Object>> value : VALUES.entrySet()) {
                Object before = value.getValue().apply(base), after = value.getValue().apply(changed);
                if (value.getKey().equals(change.getKey())) {
                    assertNotEquals(before, after, change.getKey() + " changed");
                } else {
                    assertEquals(before, after, "with " + change.getKey() + ": " + value.getKey() + " kept");
                }
            }
        }
    }

    @Test
    void movedToKeepsEverythingButTheCoordinates() {
        PanoramaRequest r = PanoramaRequest.at(46.43, 8.09);
        for (Map.Entry<String, UnaryOperator<PanoramaRequest>> change : CHANGES.entrySet()) {
            if (!change.getKey().equals("distance")) { // colour is switched off: distances stay on
                r = change.getValue().apply(r);
            }
        }
        PanoramaRequest moved = r.movedTo(-33.9, 151.2);
        assertEquals(-33.9, moved.latDeg());
        assertEquals(151.2, moved.lonDeg());
        for (Map.Entry<String, Function<PanoramaRequest, Object>> value : VALUES.entrySet()) {
            if (!value.getKey().endsWith("Deg")) {
                assertEquals(value.getValue().apply(r), value.getValue().apply(moved), value.getKey());
            }
        }
        // A fresh standpoint there instead: the eye's placement back to its defaults, the rest kept.
        PanoramaRequest fresh = r.withStandpoint(PanoramaRequest.Standpoint.at(-33.9, 151.2));
        assertEquals(PanoramaRequest.at(-33.9, 151.2).standpoint(), fresh.standpoint());
        assertEquals(r.coverage(), fresh.coverage());
        assertEquals(r.viewSettings(), fresh.viewSettings());
        assertEquals(r.products(), fresh.products());
    }

    @Test
    void theTallestViewsAGlRenderbufferHoldsAreAccepted() {
        // ±80° at 20 px/°: views of 950 × 14 081 pixels, under the 16 384 limit.
        PanoramaRequest r = PanoramaRequest.at(46.43, 8.09).withElevationRange(new ElevationRange(-80, 80, false));
        dempano.panorama.ViewLayout l = dempano.panorama.ViewLayout.forPanorama(dempano.panorama.PanoramaGeometry.of(
                r.pixelsPerDegree(), -80, 80), r.views(), r.supersampling());
        assertTrue(l.heightPx() > 14_000 && l.heightPx() <= dempano.panorama.ViewLayout.MAX_VIEW_PX, l.toString());
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
            "latitude 91 | latitude",
            "offset 1e7 | offset must be a number of metres within ±1e6",
            "altitude NaN is 'from the DEM', 2e6 is not | altitude must be a number of metres within ±1e6",
            "eye height -1 | eye height must be a number of metres in [0, 1e6)",
            "range 50 m | range must be between 0.1 and",
            "ppd 0 | ",
            "near 0 | near plane must be in (0, 1000) metres",
            "lod 101 | level-of-detail error bound must be in [0, 100] pixels",
            "snap radius 0 | snap-to-summit radius must be in (0,",
            "nothing to render | nothing to render: both colour and distance are switched off",
            "layers without distance | are computed from distances: they need the distance map",
            // Views taller than a GL renderbuffer may be (jME failed on the GL thread at render time).
            "views too tall | pixels would be needed (at most 16384): a view's height grows as the tangent",
            // 178° at 0.1 px/° is 17.8 rows: 18 whole rows from the top reach -91° (the message said 'must lie within').
            "rows past -90 | at 0.1 pixels per degree takes 18 whole rows from the top, which reach down to -91.0000°",
    })
    void badValuesAreRefusedWithTheirMessage(String what, String message) {
        PanoramaRequest r = PanoramaRequest.at(46.43, 8.09);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> {
            switch (what.split(" ")[0] + " " + what.split(" ")[1]) {
                case "latitude 91" -> PanoramaRequest.at(91, 8);
                case "offset 1e7" -> r.withOffsetMetres(1e7);
                case "altitude NaN" -> r.withAltitudeMetres(Double.NaN).withAltitudeMetres(2e6);
                case "eye height" -> r.withEyeHeightMetres(-1);
                case "range 50" -> r.withRangeMetres(50);
                case "ppd 0" -> r.withPixelsPerDegree(0);
                case "near 0" -> r.withNearMetres(0);
                case "lod 101" -> r.withLodErrorPx(101);
                case "snap radius" -> r.withSnapToSummitMetres(0);
                case "nothing to" -> r.withColour(false).withDistance(false);
                case "layers without" -> r.withDistance(false).withLayers(Set.of(Layer.values()[0]));
                case "views too" -> r.withPixelsPerDegree(5).withElevationRange(new ElevationRange(-89, 89, false));
                case "rows past" -> r.withPixelsPerDegree(0.1).withElevationRange(new ElevationRange(-89, 89, false));
                default -> throw new AssertionError(what);
            }
        });
        assertTrue(message == null || e.getMessage().contains(message), e.getMessage());
    }

    /** A null argument is refused by its name (they were bare NullPointerExceptions), a renderer's before any context is made. */
    @Test
    void nullArgumentsAreRefusedByName() {
        PanoramaRequest r = PanoramaRequest.at(46.43, 8.09);
        Map<String, org.junit.jupiter.api.function.Executable> calls = new LinkedHashMap<>();
        calls.put("elevationRange", () -> r.withElevationRange(null));
        calls.put("refraction", () -> r.withRefraction(null));
        calls.put("missingTiles", () -> r.withMissingTiles(null));
        calls.put("depthMode", () -> r.withDepthMode(null));
        calls.put("layers", () -> r.withLayers(null));
        calls.put("standpoint", () -> r.withStandpoint(null));
        calls.put("dem", () -> PanoramaRenderer.open(null));
        calls.put("dem ", () -> PanoramaRenderer.openReference(null));
        calls.put("request", () -> {
            try (PanoramaRenderer cpu = PanoramaRenderer.openReference(new dempano.dem.InMemoryDem("none", java.util.List.of()))) {
                cpu.render((PanoramaRequest) null);
            }
        });
        calls.forEach((name, call) -> {
            NullPointerException e = assertThrows(NullPointerException.class, call, name);
            assertEquals(name.trim(), e.getMessage());
        });
    }
}
