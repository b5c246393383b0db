package dempano.bench;

import dempano.dem.PriorityDem;
import dempano.dem.VoidFill;
import java.util.Locale;

/**
 * The void-fill section of {@code docs/accuracy.md}: the terrain's own error where the DEM has voids, from the
 * two fill comparisons ({@link VoidFillReport} on SRTM3's real voids, {@link CoarseFillReport} on held-out voids
 * with a coarser second source), the defaults set against the fill used before (inverse-distance weighting).
 * Pure formatting of measured values: the numbers come from the measurements passed in.
 */
public final class FillSummary {
    /**
     * The figures the issue that asked for a better fill (issue 20) measured for the inverse-distance fill on
     * N46E008's void summits: median −92 m, mean |error| 138 m (711 summits, an earlier void criterion).
     */
    static final String ISSUE_IDW_FIGURES = "−92 m median, 138 m mean |error|";

    private FillSummary() {
    }

    /**
     * The section, in markdown, headed {@code ## Terrain: void fills}.
     *
     * @param realVoids the fills on SRTM3's real voids (summits only)
     * @param heldOut   the fills of held-out voids with a 30″ second source, or null where it was not measured
     *                  (no gdalwarp), which the section then says
     * @param command   the command that regenerates the section
     */
    public static String markdown(VoidFillReport.Measured realVoids, CoarseFillReport.Measured heldOut, String command) {
        StringBuilder b = new StringBuilder("## Terrain: void fills\n\n");
        b.append("Where the DEM has voids, the terrain itself is wrong before any rendering. Height error = the DEM's bilinear "
                + "height at a surveyed summit minus its surveyed height (`../shared/peaks/alps.txt`). Regenerated with the rest "
                + "of this file by `").append(command).append("`; the full tables and their method are in "
                + "[void-fill.md](void-fill.md) (`gradle voidFillReport`) and [coarse-fill.md](coarse-fill.md) "
                + "(`gradle coarseFillReport`).\n\n");
        b.append("One source (SRTM3's real voids; summits in or next to a void, all held out from every fill):\n\n");
        b.append("| fill | summits | median | mean | mean abs | RMS | within ±50 m |\n|---|---:|---:|---:|---:|---:|---:|\n");
        for (VoidFillReport.FillErrors f : realVoids.fills()) {
            String name = "`--void-fill " + f.fill().cliName() + "`" + (f.fill() == VoidFill.DEFAULT ? " (default)"
                    : f.fill() == VoidFill.IDW ? " (the default before)" : "");
            row(b, name, f.errors());
        }
        row(b, "summits on valid data (no fill)", realVoids.validData());
        VoidFillReport.Errors now = realVoids.of(VoidFill.DEFAULT), idw = realVoids.of(VoidFill.IDW);
        b.append(String.format(Locale.ROOT, "%nThe default (`%s`) against the inverse-distance fill used before, on the same %d "
                        + "void summits: median %+.0f m against %+.0f m, mean %+.0f m against %+.0f m, mean |error| %.0f m "
                        + "against %.0f m (the issue measured %s for the inverse-distance fill).%n%n",
                VoidFill.DEFAULT.cliName(), now.count(), now.medianMetres(), idw.medianMetres(), now.meanMetres(), idw.meanMetres(),
                now.meanAbsMetres(), idw.meanAbsMetres(), ISSUE_IDW_FIGURES));
        if (heldOut == null) {
            b.append("Two sources: not measured in this run (the held-out comparison needs GDAL's `gdalwarp`).\n\n");
            return b.toString();
        }
        b.append(String.format(Locale.ROOT, "Two sources (`--dem-dir A --dem-dir B`): N46E008's void mask shifted onto valid data "
                + "(%,d held-out samples), B a 30″ average of the tile; the errors of the held-out samples against SRTM3 and of "
                + "the summits in the held-out voids against their surveyed heights:%n%n", heldOut.heldOutSamples()));
        b.append("| fill | samples: RMS | summits | median | mean | mean abs | RMS | within ±50 m |\n"
                + "|---|---:|---:|---:|---:|---:|---:|---:|\n");
        for (CoarseFillReport.MethodErrors m : heldOut.methods()) {
            String name = m.method().blend() == null ? "`--void-fill " + VoidFill.DEFAULT.cliName() + "`, B unused"
                    : "`--dem-blend " + m.method().blend().cliName() + "`"
                            + (m.method().blend() == PriorityDem.Blend.DEFAULT ? " (default)" : "");
            b.append(String.format(Locale.ROOT, "| %s | %.1f m ", name, m.samples().rmsMetres()));
            summitCells(b, m.summits());
        }
        b.append("| the held-out SRTM3 itself | 0 ");
        summitCells(b, heldOut.heldOutSrtm());
        CoarseFillReport.MethodErrors blend = heldOut.of(PriorityDem.Blend.DEFAULT), asIs = heldOut.of(PriorityDem.Blend.AS_IS);
        b.append(String.format(Locale.ROOT, "%nThe default blend (`%s`): held-out RMS %.1f m against %.1f m as is; on the summits "
                        + "median %+.0f m, mean %+.0f m against %+.0f m, %+.0f m as is.%n%n", PriorityDem.Blend.DEFAULT.cliName(),
                blend.samples().rmsMetres(), asIs.samples().rmsMetres(), blend.summits().medianMetres(),
                blend.summits().meanMetres(), asIs.summits().medianMetres(), asIs.summits().meanMetres()));
        return b.toString();
    }

    private static void row(StringBuilder b, String name, VoidFillReport.Errors e) {
        b.append("| ").append(name).append(' ');
        summitCells(b, e);
    }

    private static void summitCells(StringBuilder b, VoidFillReport.Errors e) {
        b.append(String.format(Locale.ROOT, "| %d | %+.0f m | %+.0f m | %.0f m | %.0f m | %.0f %% |%n", e.count(), e.medianMetres(),
                e.meanMetres(), e.meanAbsMetres(), e.rmsMetres(), 100 * e.withinFiftyShare()));
    }
}
