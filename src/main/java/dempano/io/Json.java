package dempano.io;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
import com.google.gson.JsonNull;
import com.google.gson.JsonPrimitive;
import com.google.gson.JsonSerializer;

/**
 * The Gson that writes dempano's JSON files ({@code P.json}, {@code P-orientation.json}, summit lists): pretty
 * printed, nulls written, and numbers that JSON cannot hold (NaN, ±Infinity: "not computed", "not measured") written
 * as {@code null}, so that every file parses with a strict reader (Python's {@code json}, JavaScript's
 * {@code JSON.parse}, jq). Gson alone either refuses them or writes the bare words {@code NaN}/{@code Infinity}.
 */
public final class Json {
    private Json() {
    }

    private static final JsonSerializer<Double> DOUBLES = (v, type, context) ->
            Double.isFinite(v) ? new JsonPrimitive(v) : JsonNull.INSTANCE;
    private static final JsonSerializer<Float> FLOATS = (v, type, context) ->
            Float.isFinite(v) ? new JsonPrimitive(v) : JsonNull.INSTANCE;

    /** A new Gson for writing files, as above. */
    public static Gson writer() {
        return new GsonBuilder().setPrettyPrinting().serializeNulls()
                .registerTypeAdapter(Double.class, DOUBLES).registerTypeAdapter(double.class, DOUBLES)
                .registerTypeAdapter(Float.class, FLOATS).registerTypeAdapter(float.class, FLOATS).create();
    }
}
