package dempano.summits;

import java.util.List;

/**
 * An immutable list of summits read from one source, with the entries skipped in lenient reading.
 *
 * @param source   where the list came from (a file name)
 * @param summits  the summits, in file order
 * @param skipped  one message per skipped entry ("line N: problem", or "feature N: problem" for
 *                 GeoJSON); empty in strict reading
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

    /** This list with other summits (same source and skipped entries). */
    public SummitList withSummits(List<Summit> replaced) {
        return new SummitList(source, replaced, skipped);
    }

    /**
     * What a user should be told about the list beyond the skipped entries, one sentence each without
     * a "warning:" prefix: an empty list ("no summits in FILE", with how many entries were skipped when all
     * were), or summits without an elevation in the list, which are placed at the DEM's height
     * ({@link SummitProjector#placedOnDem}; {@link SummitProjector#warnings} adds those it could not place).
     * Empty when there is nothing to say.
     */
    public List<String> warnings() {
        if (summits.isEmpty()) {
            return List.of("no summits in " + source + (skipped.isEmpty() ? ""
                    : " (all " + skipped.size() + " entries were skipped as bad)"));
        }
        List<Summit> noHeight = summits.stream().filter(s -> s.elevationFromDem() || Double.isNaN(s.elevationMetres())).toList();
        return noHeight.isEmpty() ? List.of() : List.of(noHeight.size() + " of the " + summits.size() + " summits in "
                + source + " have no elevation (e.g. " + noHeight.get(0).name() + "): each is placed at the DEM's height"
                + " at its position, a little low where the DEM flattens a summit");
    }
}
