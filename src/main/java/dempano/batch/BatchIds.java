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

    /** The id with control characters shown as {@code ?}, for one-line messages. */
    static String printable(String id) {
        StringBuilder b = new StringBuilder(id.length());
        id.codePoints().forEach(c -> b.appendCodePoint(Character.isISOControl(c) ? '?' : c));
        return b.toString();
    }
}
