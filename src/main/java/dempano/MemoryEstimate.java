package dempano;

import dempano.panorama.PanoramaGeometry;
import dempano.panorama.ViewLayout;
import java.util.Locale;

/**
 * The Java heap a panorama needs, estimated before rendering so that a request too large for the
 * heap is refused with the figures instead of failing half-way with an {@link OutOfMemoryError}.
 *
 * <p>Model (bytes), from what the pipeline holds at its two peaks: while stitching, every view's
 * colour, range and inverse depth (12 per view pixel, {@code viewPixels}) besides the panorama's
 * colour and distance (8 per panorama pixel); while writing, the panorama, its layers (4 per pixel
 * each) and the pictures being encoded (colour, distance picture, labels: 12 per pixel). Added to the
 * larger peak: the tiles the mosaic holds and a base for the JVM, jME, the terrain mesh and caches.
 * The base and the headroom were set from the least {@code -Xmx} at which the CLI renders and writes
 * (bisection, 7 % steps, demo scene at 10, 30 and 50 px/°; figures below). So a request the estimate
 * accepts runs, and one it refuses would need at least about 75 % of the estimate. Exact per-pixel distances (the default) hold per view pixel also the surface ids read
 * back (8) and then the triangle seen (4), and 72 bytes per distinct triangle seen (one per 57 view
 * pixels at Mount Washington): fitted as 19 bytes per view pixel with a 70 MB base, the demo scene
 * needed 123, 725 and 1837 MB (exact) and is estimated 162, 741 and 1899 MB; without exact
 * distances 133, 508 and 1268 MB, estimated 141, 560 and 1398 MB. Direct buffers (one view's read-back, the terrain mesh) count against their own limit.
 *
 * @param viewPixels     pixels of all views together (0 for the CPU reference)
 * @param panoramaPixels pixels of the panorama before any automatic crop
 * @param layers         extra per-pixel layers requested
 * @param tileBytes      bytes of the tiles the range needs
 * @param exactDistances whether the views also carry what each sample saw (exact per-pixel distances)
 */
public record MemoryEstimate(long viewPixels, long panoramaPixels, int layers, long tileBytes, boolean exactDistances) {
    /** JVM, jME, shaders, terrain mesh and caches, bytes (measured; see the class comment). */
    static final long BASE_BYTES = 70L << 20;
    /** Heap the collector needs beyond the live data to keep going (measured; see the class comment). */
    static final double HEADROOM = 1.1;

    /** The estimate for a request (views as the OpenGL path lays them out, or none for the reference). */
    public static MemoryEstimate of(PanoramaRequest req, boolean withViews, long tileBytes) {
        PanoramaGeometry g = PanoramaGeometry.of(req.pixelsPerDegree(), req.elevationRange().bottomDeg(),
                req.elevationRange().topDeg());
        long views = 0;
        if (withViews) {
            ViewLayout layout = ViewLayout.forPanorama(g, req.views(), req.supersampling());
            views = (long) req.views() * layout.widthPx() * layout.heightPx();
        }
        return new MemoryEstimate(views, (long) g.widthPx() * g.heightPx(), req.layers().size(), tileBytes,
                withViews && req.exactDistances() && req.distance());
    }

    /**
     * The estimate for a camera's view: its views as {@link ViewLayout#forTarget} lays them out (null for the CPU
     * reference, which holds no views), the photo's pixels in place of the panorama's (colour, distance, layers and
     * the written pictures hold per pixel what a panorama's do).
     */
    public static MemoryEstimate of(CameraRequest req, ViewLayout layout, long tileBytes) {
        PanoramaRequest s = req.settings();
        long views = layout == null ? 0 : (long) layout.views() * layout.widthPx() * layout.heightPx();
        return new MemoryEstimate(views, (long) req.intrinsics().widthPx() * req.intrinsics().heightPx(), s.layers().size(),
                tileBytes, layout != null && s.exactDistances() && s.distance());
    }

    /**
     * Refuses a camera view that needs more than {@code maxHeapBytes}.
     *
     * @throws InsufficientMemoryException with the figures and the way out
     */
    public void checkCamera(long maxHeapBytes) {
        if (heapBytes() <= maxHeapBytes) {
            return;
        }
        throw new InsufficientMemoryException(needs("this camera view", maxHeapBytes, true) + ": render a smaller image"
                + " (--width-px/--height-px, the intrinsics scaled with it; half the width and height needs a quarter), or"
                + " give Java more memory, e.g. " + heapOption(), this);
    }

    /**
     * The message for a photo's own view that needs more than {@code maxHeapBytes}: its size is the photo's, so
     * the way out is more memory or a smaller copy of the photo (no flag sets it).
     */
    public String photoMessage(long maxHeapBytes) {
        return needs("the photo's view", maxHeapBytes, true) + ": give Java more memory, e.g. " + heapOption()
                + ", or render a smaller copy of the photo (half the width and height needs a quarter)";
    }

    /**
     * The message for the 360° panorama a photo is matched against, needing more than {@code maxHeapBytes}: its grid
     * is fixed (no --ppd or --elevation-range to lower), so the way out is more memory, or the values given so that
     * nothing is estimated.
     *
     * @param estimated what the match would estimate ("heading, pitch")
     * @param flags     the flags that give those values
     */
    public String matchPanoramaMessage(long maxHeapBytes, String estimated, String flags) {
        return needs("the 360° panorama the photo is matched against (to estimate " + estimated + ")", maxHeapBytes, false)
                + ": give Java more memory, e.g. " + heapOption() + ", or give them (" + flags + ") so that nothing is estimated";
    }

    /** "WHAT needs about 1.53 GB of Java heap (BREAKDOWN) but the limit is 0.42 GB"; a camera's pixels as photo pixels. */
    private String needs(String what, long maxHeapBytes, boolean camera) {
        String breakdown = camera ? breakdown().replace("panorama pixels", "photo pixels") : breakdown();
        return String.format(Locale.ROOT, "%s needs about %.2f GB of Java heap (%s) but the limit is %.2f GB", what,
                heapBytes() / 1e9, breakdown, maxHeapBytes / 1e9);
    }

    /** The JVM option that would fit it: a whole number of GiB with one to spare, e.g. "DEMPANO_OPTS=-Xmx3g". */
    private String heapOption() {
        return "DEMPANO_OPTS=-Xmx" + ((int) Math.ceil(heapBytes() / (double) (1L << 30)) + 1) + "g";
    }

    /** Bytes held while the views are stitched. */
    public long stitchingBytes() {
        return (exactDistances ? 19 : 12) * viewPixels + 8 * panoramaPixels;
    }

    /** Bytes held while the files are written. */
    public long writingBytes() {
        return (20L + 4L * layers) * panoramaPixels;
    }

    /** The heap the request needs, bytes: live data at the larger peak plus base, times the collector's headroom. */
    public long heapBytes() {
        return (long) (HEADROOM * (BASE_BYTES + tileBytes + Math.max(stitchingBytes(), writingBytes())));
    }

    /**
     * Refuses a request that needs more than {@code maxHeapBytes}.
     *
     * @throws InsufficientMemoryException with the figures and the way out
     */
    public void check(long maxHeapBytes) {
        if (heapBytes() <= maxHeapBytes) {
            return;
        }
        throw new InsufficientMemoryException(needs("this panorama", maxHeapBytes, false) + ": lower the pixels per degree"
                + " (--ppd; half the ppd needs a quarter) or the elevation range (--elevation-range), or give Java more"
                + " memory, e.g. " + heapOption(), this);
    }

    private String breakdown() {
        return String.format(Locale.ROOT, "%s M view pixels, %s M panorama pixels%s, tiles %.0f MB",
                millions(viewPixels), millions(panoramaPixels), layers > 0 ? ", " + layers + " layers" : "", tileBytes / 1e6);
    }

    /** A pixel count in millions: whole above 10, else two decimals (a small view read "0 M"). */
    private static String millions(long pixels) {
        return String.format(Locale.ROOT, pixels >= 10_000_000 ? "%.0f" : "%.2f", pixels / 1e6);
    }
}
