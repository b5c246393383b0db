package dempano.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.stream.JsonReader;
import java.io.StringReader;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

class JsonTest {
    record Estimate(double headingDeg, double altitudeOffsetMetres, Double sigma, float distance, List<Double> values) {
    }

    /** A strict parse, as Python's json or JavaScript's JSON.parse reads a file: NaN and Infinity are refused. */
    static JsonElement strict(String json) {
        JsonReader r = new JsonReader(new StringReader(json));
        r.setLenient(false);
        return com.google.gson.JsonParser.parseReader(r);
    }

    @Test
    void nonFiniteNumbersAreWrittenAsNullAndTheFileParsesStrictly() {
        Map<String, Object> doc = new LinkedHashMap<>();
        doc.put("estimate", new Estimate(123.5, Double.NaN, Double.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY,
                List.of(1.0, Double.NaN)));
        doc.put("offsetMetres", Double.NaN);
        doc.put("rangeMetres", 1e5);
        String json = Json.writer().toJson(doc);
        JsonObject o = strict(json).getAsJsonObject();
        JsonObject e = o.getAsJsonObject("estimate");
        assertEquals(123.5, e.get("headingDeg").getAsDouble(), 0);
        for (String k : new String[] {"altitudeOffsetMetres", "sigma", "distance"}) {
            assertTrue(e.get(k).isJsonNull(), k + " in " + json);
        }
        assertTrue(e.getAsJsonArray("values").get(1).isJsonNull(), json);
        assertEquals(1.0, e.getAsJsonArray("values").get(0).getAsDouble(), 0);
        assertTrue(o.get("offsetMetres").isJsonNull(), json);
        assertEquals(1e5, o.get("rangeMetres").getAsDouble(), 0);
    }

    @Test
    void aTreeMadeFromARecordKeepsTheNulls() {
        // The photo job adds fields to the estimate's tree before writing it.
        JsonObject tree = Json.writer().toJsonTree(new Estimate(1, Double.NaN, 2.0, 3f, List.of())).getAsJsonObject();
        tree.addProperty("matchedWidthPx", 480);
        JsonObject back = strict(Json.writer().toJson(tree)).getAsJsonObject();
        assertTrue(back.get("altitudeOffsetMetres").isJsonNull());
        assertEquals(480, back.get("matchedWidthPx").getAsInt());
    }
}
