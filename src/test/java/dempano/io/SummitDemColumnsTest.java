package dempano.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import dempano.summits.Summit;
import dempano.summits.SummitSighting;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The summit files carry the DEM's height at each summit and whether it lies in a filled void. */
class SummitDemColumnsTest {
    private static final List<SummitSighting> SIGHTINGS = List.of(
            new SummitSighting(new Summit("Schreckhorn", 46.59, 8.118, 4078), 250, 3, 10, 20, 30000, 29990, 30000, 30000,
                    true).withDem(3601.5, true),
            new SummitSighting(new Summit("Eggishorn", 46.43, 8.09, 2927), 200, 1, 30, 40, 40000, 39990, 40000, 40000,
                    false),
            new SummitSighting(new Summit("Unsurveyed", 46.5, 8.1, 2511.25, true), 210, 1, 30, 40, 40000, 39990, 40000,
                    40000, true).withDem(2511.25, false));

    @Test
    void csvHasTheDemHeightAndTheVoidFlag() {
        String[] lines = SummitWriter.csv(SIGHTINGS).split("\n");
        assertTrue(lines[0].endsWith(",visible,dem_height_m,in_filled_void,elevation_from_dem"), lines[0]);
        assertTrue(lines[1].endsWith(",true,3601.5,true,false"), lines[1]);
        assertTrue(lines[2].endsWith(",false,,false,false"), lines[2]);
        assertTrue(lines[3].startsWith("Unsurveyed,46.500000,8.100000,2511,") && lines[3].endsWith(",true,2511.3,false,true"), lines[3]);
    }

    @Test
    void aHeightFromTheDemIsMarkedInTheLabel() {
        assertEquals("Schreckhorn 4078 m · 30.0 km", SummitWriter.text(SIGHTINGS.get(0)));
        assertEquals("Unsurveyed ~2511 m · 40.0 km", SummitWriter.text(SIGHTINGS.get(2)));
    }

    @Test
    void jsonHasTheDemHeightAndTheVoidFlag() {
        JsonObject root = JsonParser.parseString(SummitWriter.json(SIGHTINGS)).getAsJsonObject();
        JsonObject first = root.getAsJsonArray("summits").get(0).getAsJsonObject();
        assertEquals(3601.5, first.get("demHeightMetres").getAsDouble());
        assertTrue(first.get("inFilledVoid").getAsBoolean());
        JsonObject second = root.getAsJsonArray("summits").get(1).getAsJsonObject();
        // Not looked up: null, as the file's note says (a member left out read as a missing column).
        assertTrue(second.has("demHeightMetres") && second.get("demHeightMetres").isJsonNull(), second.toString());
        assertEquals(false, second.get("inFilledVoid").getAsBoolean());
        assertFalse(second.get("elevationFromDem").getAsBoolean());
        assertTrue(root.getAsJsonArray("summits").get(2).getAsJsonObject().get("elevationFromDem").getAsBoolean());
    }

    /** A summit whose pixel shows sky (its tip on the skyline) has a null map distance, not a missing one. */
    @Test
    void valuesJsonCannotHoldAreNull() {
        SummitSighting tip = new SummitSighting(new Summit("Tip", 46.5, 8.1, 3000), 100, 2, 5, 6, 20000, 19990,
                Double.POSITIVE_INFINITY, Double.NaN, false);
        JsonObject o = JsonParser.parseString(SummitWriter.json(List.of(tip))).getAsJsonObject().getAsJsonArray("summits")
                .get(0).getAsJsonObject();
        for (String key : List.of("mapDistanceMetres", "seenDistanceMetres", "demHeightMetres")) {
            assertTrue(o.has(key) && o.get(key).isJsonNull(), key + " in " + o);
        }
    }
}
