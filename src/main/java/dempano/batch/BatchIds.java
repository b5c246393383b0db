package dempano.batch;

import java.util.Locale;
import java.util.regex.Pattern;

/**
 * Output ids of a batch: an id becomes the start of file names in the output folder
 * ({@code D/<id>.png}), so only plain names are accepted: 1 to 100 characters of ASCII letters,
 * digits, {@code .}, {@code _} and {@code -}, starting with a letter or digit and not ending with a
 * dot. That rules out path separators ({@code a/b}, {@code ../x}), hidden names ({@code .x}), spaces
 * and control characters, and names that differ between file systems. Ids are compared without
 * regard to case when looking for duplicates ({@code A} and {@code a} would share files on a
 * case-insensitive file system). Stateless.
 */
public final class BatchIds {
    /** Longest id accepted, characters. */
    public static final int MAX_LENGTH = 100;
    private static final Pattern SAFE = Pattern.compile("[A-Za-z0-9][A-Za-z0-9._-]*");

    private BatchIds() {
    }

    /**
     * Why an id cannot name output files, or null when it can.
     *
     * @param id the id as given (null is treated as empty)
     */
    public static String problem(String id) {
        if (id == null || id.isEmpty()) {
            return "the id is empty";
        }
        if (id.length() > MAX_LENGTH) {
            return "the id is longer than " + MAX_LENGTH + " characters";
        }
        if (!SAFE.matcher(id).matches() || id.endsWith(".")) {
            return "unsafe id '" + printable(id) + "': use letters, digits, '.', '_' and '-', starting with a letter "
                    + "or digit (no paths)";
        }
        return null;
    }

    /** The key two ids share when they would collide as file names: the id in lower case. */
    public static String collisionKey(String id) {
        return id.toLowerCase(Locale.ROOT);
    }

    /**
     * Every file name a batch row can write, after its id: a panorama's, a photo's, summits', layers' (a superset of
     * what one row writes, so that ids are judged alike whatever the options).
     */
    public static final java.util.List<String> FILE_SUFFIXES = fileSuffixes();

    private static java.util.List<String> fileSuffixes() {
        java.util.Set<String> all = new java.util.LinkedHashSet<>();
        for (boolean pfm : new boolean[] {false, true}) {
            all.addAll(dempano.io.PanoramaWriter.suffixes(true, true, java.util.EnumSet.allOf(dempano.panorama.Layer.class),
                    new dempano.io.PanoramaWriter.Options(pfm, java.util.List.of(), dempano.io.SummitWriter.LabelOptions.DEFAULT)));
        }
        all.addAll(dempano.io.CameraWriter.suffixes(true));
        all.addAll(java.util.List.of("-orientation.png", "-orientation.json"));
        return java.util.List.copyOf(all);
    }

    /**
     * The other ids (as {@link #collisionKey}s) whose files could share a name with this id's, each with that name:
     * {@code a} and {@code a-distance} both write {@code a-distance.png} (the one its distance picture, the other its
     * colour panorama), so the second would overwrite the first's file.
     *
     * @return collision key of the other id → the file name both would write (lower case)
     */
    public static java.util.Map<String, String> clashingIds(String id) {
        String key = collisionKey(id);
        java.util.Map<String, String> out = new java.util.LinkedHashMap<>();
        for (String mine : FILE_SUFFIXES) {
            String name = key + mine.toLowerCase(Locale.ROOT);
            for (String theirs : FILE_SUFFIXES) {
                String t = theirs.toLowerCase(Locale.ROOT);
                if (name.endsWith(t) && name.length() > t.length()) {
                    String other = name.substring(0, name.length() - t.length());
                    if (!other.equals(key)) {
                        out.putIfAbsent(other, name);
                    }
                }
            }
        }
        return out;
    }

    /** The id with control characters shown as {@code ?}, for one-line messages. */
    public static String printable(String id) {
        StringBuilder b = new StringBuilder(id.length());
        id.codePoints().forEach(c -> b.appendCodePoint(Character.isISOControl(c) ? '?' : c));
        return b.toString();
    }
}
