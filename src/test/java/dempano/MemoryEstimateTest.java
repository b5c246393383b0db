package dempano;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.panorama.ElevationRange;
import dempano.panorama.Layer;
import java.util.EnumSet;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The estimate against the least heap measured for the same requests, and its refusal message. */
class MemoryEstimateTest {
    /**
     * Rows: ppd, least -Xmx measured (MB) for the demo scene with the CLI (renders and writes), exact distances on or off. The
     * estimate must cover the measurement (accepted requests run) by less than 35 % (few needless refusals).
     */
    @ParameterizedTest
    @CsvSource({"10, 133, false", "30, 508, false", "50, 1268, false", "10, 123, true", "30, 725, true", "50, 1837, true"})
    void theEstimateCoversTheMeasuredLeastHeapWithoutMuchWaste(double ppd, long measuredMb, boolean exact) {
        MemoryEstimate e = MemoryEstimate.of(PanoramaRequest.at(0, 0).withPixelsPerDegree(ppd).withExactDistances(exact),
                true, 4 * 2_884_802L);
        double ratio = e.heapBytes() / (measuredMb * 1024.0 * 1024.0);
        assertTrue(ratio >= 1 && ratio < 1.35, "estimate / measured = " + ratio);
    }

    @Test
    void picturesAndLayersCountAsThePipelineHoldsThem() {
        PanoramaRequest req = PanoramaRequest.at(0, 0).withPixelsPerDegree(10)
                .withElevationRange(new ElevationRange(-10, 10, false));
        MemoryEstimate reference = MemoryEstimate.of(req, false, 0);
        assertEquals(0, reference.viewPixels());
        assertEquals(3600L * 200, reference.panoramaPixels());
        assertEquals(20L * 3600 * 200, reference.writingBytes(), "writing is the peak without views");
        MemoryEstimate layered = MemoryEstimate.of(req.withLayers(EnumSet.of(Layer.ELEVATION, Layer.LATITUDE)), false, 0);
        assertEquals(reference.writingBytes() + 2 * 4L * 3600 * 200, layered.writingBytes());
        MemoryEstimate gl = MemoryEstimate.of(req, true, 0);
        assertTrue(gl.viewPixels() >= reference.panoramaPixels(), "views cover the panorama");
        assertEquals(19 * gl.viewPixels() + 8 * gl.panoramaPixels(), gl.stitchingBytes(), "exact distances (default)");
        MemoryEstimate interpolated = MemoryEstimate.of(req.withExactDistances(false), true, 0);
        assertEquals(12 * interpolated.viewPixels() + 8 * interpolated.panoramaPixels(), interpolated.stitchingBytes());
    }

    @Test
    void aRequestBeyondTheHeapIsRefusedWithTheFiguresAndTheWayOut() {
        MemoryEstimate e = MemoryEstimate.of(PanoramaRequest.at(0, 0).withPixelsPerDegree(60).withRangeMetres(30_000), true, 0);
        InsufficientMemoryException x = assertThrows(InsufficientMemoryException.class, () -> e.check(400L << 20));
        assertTrue(x.getMessage().startsWith(String.format(java.util.Locale.ROOT, "this panorama needs about %.2f GB of Java heap",
                e.heapBytes() / 1e9)), x.getMessage());
        assertTrue(x.getMessage().contains("but the limit is 0.42 GB") && x.getMessage().contains("--ppd")
                && x.getMessage().contains("DEMPANO_OPTS=-Xmx"), x.getMessage());
        e.check(e.heapBytes()); // exactly enough: accepted
    }

    @Test
    void aPhotosViewIsAdvisedWhatAPhotoCanDo() {
        // A photo's size is its own: no --width-px (refused with a photo), no --ppd; more memory or a smaller copy.
        MemoryEstimate e = new MemoryEstimate(49_000_000, 48_000_000, 0, 3_000_000, true);
        String m = e.photoMessage(400L << 20);
        assertTrue(m.startsWith(String.format(java.util.Locale.ROOT, "the photo's view needs about %.2f GB of Java heap",
                e.heapBytes() / 1e9)) && m.contains("48 M photo pixels") && m.contains("but the limit is 0.42 GB"), m);
        assertTrue(m.contains("DEMPANO_OPTS=-Xmx3g") && m.contains("smaller copy of the photo"), m);
        assertTrue(!m.contains("--width-px") && !m.contains("--ppd"), m);
    }

    @Test
    void thePanoramaAPhotoIsMatchedAgainstIsAdvisedWhatThePhotoCommandTakes() {
        MemoryEstimate e = MemoryEstimate.of(PanoramaRequest.at(0, 0).withPixelsPerDegree(10), true, 0);
        String m = e.matchPanoramaMessage(100L << 20, "heading, pitch", "--heading-deg, --pitch-deg");
        assertTrue(m.startsWith(String.format(java.util.Locale.ROOT, "the 360° panorama the photo is matched against (to"
                + " estimate heading, pitch) needs about %.2f GB of Java heap", e.heapBytes() / 1e9)), m);
        assertTrue(m.contains("but the limit is 0.10 GB: give Java more memory, e.g. DEMPANO_OPTS=-Xmx")
                && m.endsWith("or give them (--heading-deg, --pitch-deg) so that nothing is estimated"), m);
        assertTrue(!m.contains("--ppd") && !m.contains("--elevation-range"), m);
    }
}
