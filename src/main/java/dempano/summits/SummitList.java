package dempano.summits;

import java.util.List;

/**
 * An immutable list of summits read from one source, with the lines skipped in lenient reading.
 *
 * @param source   where the list came from (a file name)
 * @param summits  the summits, in file order
 * @param skipped  one message per skipped line ("line N: problem"); empty in strict reading
 */
public record SummitList(String source, List<Summit> summits, List<String> skipped) {
    public SummitList {
        summits = List.copyOf(summits);
        skipped = List.copyOf(skipped);
    }

    public static SummitList of(String source, List<Summit> summits) {
        return new SummitList(source, summits, List.of());
    }

    public int size() {
        return summits.size();
    }
}
