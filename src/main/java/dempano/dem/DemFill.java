package dempano.dem;

import java.util.Objects;

/**
 * How the voids of a DEM are filled, the two choices that travel together from the command line (or a Java
 * caller) to where the DEM is opened: first from the later sources in priority, put in as {@link #blend()}
 * says, then, where no source has data, interpolated by {@link #voidFill()}. The defaults are the fills that
 * measured best: {@link VoidFill#THIN_PLATE} on surveyed summits in SRTM3's real voids (docs/void-fill.md),
 * {@link PriorityDem.Blend#DELTA_SURFACE} on held-out voids with a coarser second source
 * (docs/coarse-fill.md).
 *
 * @param voidFill how voids no source has data for are interpolated
 * @param blend    how a lower-priority source's heights go into a higher one's voids
 */
public record DemFill(VoidFill voidFill, PriorityDem.Blend blend) implements java.io.Serializable {
    /** The best measured: thin-plate interpolation, delta-surface blend. */
    public static final DemFill DEFAULT = new DemFill(VoidFill.DEFAULT, PriorityDem.Blend.DEFAULT);

    /** @throws NullPointerException if either is null */
    public DemFill {
        Objects.requireNonNull(voidFill, "voidFill");
        Objects.requireNonNull(blend, "blend");
    }
}
