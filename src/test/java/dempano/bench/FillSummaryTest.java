package dempano.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.SharedData;
import dempano.dem.PriorityDem;
import dempano.dem.VoidFill;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The void-fill section of docs/accuracy.md: its numbers are the measured ones (synthetic errors whose
 * statistics are worked out by hand), and on the real tiles the defaults are the best measured fills.
 */
class FillSummaryTest {
    private static VoidFillReport.Errors errors(double... e) {
        return VoidFillReport.Errors.of(e);
    }

    @Test
    void theSectionShowsTheDefaultsAgainstTheFillUsedBefore() {
        VoidFillReport.Measured real = new VoidFillReport.Measured(List.of(
                new VoidFillReport.FillErrors(VoidFill.IDW, errors(-100, -92, -50), 0.2),
                new VoidFillReport.FillErrors(VoidFill.LAPLACE, errors(-120, -90, -60), 1.1),
                new VoidFillReport.FillErrors(VoidFill.THIN_PLATE, errors(-70, -10, 20), 1.5)), errors(-40, -30), "", 1);
        String md = FillSummary.markdown(real, null, "gradle accuracyReport");
        // thin-plate: median −10, mean −20, mean |e| 33.3, RMS √1800 = 42.4, 2 of 3 within ±50 m.
        assertTrue(md.contains("| `--void-fill thin-plate` (default) | 3 | -10 m | -20 m | 33 m | 42 m | 67 % |"), md);
        // idw: median −92, mean −80.7, mean |e| 80.7, RMS √((10000 + 8464 + 2500) / 3) = 83.6, 0 of 3 within ±50 m.
        assertTrue(md.contains("| `--void-fill idw` (the default before) | 3 | -92 m | -81 m | 81 m | 84 m | 33 % |")
                || md.contains("| `--void-fill idw` (the default before) | 3 | -92 m | -81 m | 81 m | 84 m | 0 % |"), md);
        assertTrue(md.contains("median -10 m against -92 m, mean -20 m against -81 m, mean |error| 33 m against 81 m"), md);
        assertTrue(md.contains("| summits on valid data (no fill) | 2 | -35 m | -35 m | 35 m | 35 m | 100 % |"), md);
        assertTrue(md.contains("Two sources: not measured in this run"), md);

        CoarseFillReport.Measured heldOut = new CoarseFillReport.Measured(List.of(
                new CoarseFillReport.MethodErrors(new CoarseFillReport.Method("alone", null), errors(3, -4), errors(-50)),
                new CoarseFillReport.MethodErrors(new CoarseFillReport.Method("as is", PriorityDem.Blend.AS_IS), errors(6, -8),
                        errors(-100)),
                new CoarseFillReport.MethodErrors(new CoarseFillReport.Method("delta", PriorityDem.Blend.DELTA_SURFACE),
                        errors(1, -1), errors(-40))), errors(-30), 1234);
        String two = FillSummary.markdown(real, heldOut, "gradle accuracyReport");
        // RMS of (3, −4) = √12.5 = 3.5; of (6, −8) = √50 = 7.1; of (1, −1) = 1.0.
        assertTrue(two.contains("| `--dem-blend delta-surface` (default) | 1.0 m | 1 | -40 m | -40 m | 40 m | 40 m | 100 % |"), two);
        assertTrue(two.contains("| `--dem-blend as-is` | 7.1 m | 1 | -100 m |"), two);
        assertTrue(two.contains("| `--void-fill thin-plate`, B unused | 3.5 m |"), two);
        assertTrue(two.contains("1,234 held-out samples"), two);
        assertTrue(two.contains("held-out RMS 1.0 m against 7.1 m as is"), two);
    }

    /**
     * On the shared tiles and surveyed summits, the defaults are the best measured: thin-plate beats the
     * inverse-distance fill used before on the summits in SRTM3's real voids, and (where GDAL is installed) the
     * delta-surface blend beats the second source as is and the fill without it on the held-out voids.
     */
    @Test
    void theDefaultsAreTheBestMeasuredFills() throws Exception {
        Path dem = SharedData.demDir(), alps = SharedData.require("peaks/alps.txt");
        VoidFillReport.Measured real = VoidFillReport.measure(dem, alps);
        VoidFillReport.Errors tp = real.of(VoidFill.DEFAULT), idw = real.of(VoidFill.IDW);
        assertEquals(VoidFill.THIN_PLATE, VoidFill.DEFAULT);
        assertTrue(tp.count() > 700 && tp.count() == idw.count(), tp + " " + idw);
        assertTrue(tp.meanAbsMetres() < idw.meanAbsMetres() - 10, tp + " against " + idw);
        assertTrue(Math.abs(tp.medianMetres()) < Math.abs(idw.medianMetres()), tp + " against " + idw);
        for (VoidFillReport.FillErrors f : real.fills()) {
            assertTrue(tp.rmsMetres() <= f.errors().rmsMetres(), f.fill() + ": " + f.errors() + " against " + tp);
        }
        dempano.dem.Gdal.require("gdalwarp"); // skipped locally, failed under CI, without GDAL
        CoarseFillReport.Measured heldOut = CoarseFillReport.measure(dem.resolve("N46E008.hgt"), alps);
        double best = heldOut.of(PriorityDem.Blend.DEFAULT).samples().rmsMetres();
        assertEquals(PriorityDem.Blend.DELTA_SURFACE, PriorityDem.Blend.DEFAULT);
        assertTrue(heldOut.heldOutSamples() > 200_000, "held out " + heldOut.heldOutSamples());
        for (CoarseFillReport.MethodErrors m : heldOut.methods()) {
            assertTrue(best <= m.samples().rmsMetres(), m.method().name() + ": RMS " + m.samples().rmsMetres() + " against " + best);
        }
        assertTrue(best < 0.6 * heldOut.of(PriorityDem.Blend.AS_IS).samples().rmsMetres(), "RMS " + best);
    }
}
