package dempano.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.SharedData;
import dempano.dem.DemDirectory;
import dempano.panorama.DistanceComparison;
import dempano.panorama.ElevationRange;
import dempano.panorama.Panorama;
import org.junit.jupiter.api.Test;

/**
 * A summit viewpoint on a steep cell (Eggishorn, 46.4316 N 8.0929 E), the slope rising within metres of the eye. The
 * eye stood 2 m above the DEM's bilinear height there, 0.9 m above the surface drawn (the cell's triangle), and a 1 m
 * near plane cut the slope away: the views looked through the ground, 3.4 % of the pixels more than 5 % off the CPU
 * reference (10 px/°, 80 km, −15…15°). The ground is the drawn surface now, the eye 2 m above it, and the near plane
 * is kept within that clearance. Here at 5 px/°, 30 km.
 */
class NearPlaneOnSteepSummitTest {
    @Test
    void theSlopeUnderTheEyeIsDrawnAsTheReferenceSeesIt() {
        DemDirectory dem = new DemDirectory(SharedData.demDir());
        PanoramaRequest request = PanoramaRequest.at(46.4316, 8.0929).withRangeMetres(30_000).withPixelsPerDegree(5)
                .withElevationRange(new ElevationRange(-15, 15, false));
        Panorama gl;
        try (PanoramaRenderer r = PanoramaRenderer.open(dem)) {
            gl = r.render(request);
        }
        Panorama reference;
        try (PanoramaRenderer r = PanoramaRenderer.openReference(dem)) {
            reference = r.render(request);
        }
        double near = gl.metadata().nearMetres();
        DistanceComparison c = DistanceComparison.of(gl.distanceArray(), reference.distanceArray(), reference.widthPx());
        System.out.println("Eggishorn, near plane " + near + " m: " + c);
        assertTrue(c.shareOver5Percent() < 0.001, "pixels more than 5 % off the reference: " + c);
        assertTrue(near < 2, "the near plane within the eye's 2 m clearance over the drawn surface: " + near);
    }
}
