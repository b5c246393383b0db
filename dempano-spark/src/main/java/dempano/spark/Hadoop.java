package dempano.spark;

import java.util.HashMap;
import java.util.Map;
import org.apache.hadoop.conf.Configuration;

/** Hadoop settings carried from the driver to the executors as plain strings. */
final class Hadoop {
    private Hadoop() {
    }

    /** The driver's Hadoop configuration as key/value pairs (its resolved values). */
    static Map<String, String> settings(Configuration c) {
        Map<String, String> out = new HashMap<>();
        for (Map.Entry<String, String> e : c) {
            out.put(e.getKey(), c.get(e.getKey()));
        }
        return out;
    }

    /** Whether a path option or cell is a Hadoop URI ({@code hdfs://…}, {@code s3a://…}, {@code file:/…}), not a plain path. */
    static boolean isUri(String pathOrUri) {
        return pathOrUri.strip().matches("[A-Za-z][A-Za-z0-9+.-]*:/.*");
    }

    /** A configuration on an executor with the driver's settings on top of the node's defaults. */
    static Configuration configuration(Map<String, String> settings) {
        Configuration c = new Configuration();
        settings.forEach((k, v) -> {
            if (v != null) {
                c.set(k, v);
            }
        });
        return c;
    }
}
