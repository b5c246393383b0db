package dempano.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.CameraImage;
import dempano.CameraRequest;
import dempano.InsufficientMemoryException;
import dempano.MemoryEstimate;
import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.Synthetic;
import dempano.dem.InMemoryDem;
import dempano.geo.Ellipsoid;
import dempano.geo.EllipsoidRay;
import dempano.geo.Geodesy;
import dempano.geo.LocalFrame;
import dempano.geo.Refraction;
import dempano.io.CameraWriter;
import dempano.panorama.Layer;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A camera's layers on the photo's pixel grid against the closed form (a sea view on the WGS84 ellipsoid), their
 * files, the near-terrain warning for a camera beside a slope, and the memory check before a camera render.
 */
class CameraLayersTest {
    private static final double LAT = 43.5, LON = 7.5, EYE_METRES = 200;

    /** A rolled, pitched, distorted camera over the sea, 200 m up; refraction 0. */
    private static CameraRequest seaCamera(Iterable<Layer> layers) {
        CameraIntrinsics k = CameraIntrinsics.fromHorizontalFov(240, 160, 60)
                .withDistortion(new LensDistortion(-0.15, 0, 0.01, 0, 0));
        CameraPose pose = new CameraPose(LAT, LON, 0, EYE_METRES, 0, new CameraOrientation(57, -6, 12));
        EnumSet<Layer> set = EnumSet.noneOf(Layer.class);
        layers.forEach(set::add);
        return CameraRequest.of(k, pose).withSettings(PanoramaRequest.at(LAT, LON).withRangeMetres(60_000)
                .withRefraction(Refraction.NONE).withLayers(set));
    }

    private static InMemoryDem sea() {
        return Synthetic.tiles((la, lo) -> 0, 1201, Synthetic.block(43, 7, 1, 1));
    }

    @Test
    void aSeaCamerasLayersMatchTheEllipsoidOnEveryPixel(@TempDir Path tmp) throws Exception {
        CameraRequest req = seaCamera(EnumSet.allOf(Layer.class));
        CameraImage img;
        try (PanoramaRenderer cpu = PanoramaRenderer.openReference(sea())) {
            img = cpu.render(req);
        }
        assertEquals(EnumSet.allOf(Layer.class), EnumSet.copyOf(img.layers()));
        LocalFrame f = new LocalFrame(LAT, LON, EYE_METRES);
        double[] eye = new double[3], scratch = new double[3], dir = new double[3], ray = new double[3];
        Ellipsoid.toEcef(LAT, LON, EYE_METRES, eye);
        float[] elev = img.layerArray(Layer.ELEVATION), lat = img.layerArray(Layer.LATITUDE),
                lon = img.layerArray(Layer.LONGITUDE), ground = img.layerArray(Layer.GROUND_DISTANCE),
                inc = img.layerArray(Layer.INCIDENCE), unc = img.layerArray(Layer.UNCERTAINTY), d = img.distanceArray();
        int w = img.widthPx(), h = img.heightPx(), sea = 0, sky = 0;
        double worstElev = 0, worstLatLonMetres = 0, worstGround = 0, worstInc = 0;
        for (int row = 0; row < h; row++) {
            for (int col = 0; col < w; col++) {
                int i = row * w + col;
                img.view().rayOf(col, row, ray);
                EllipsoidRay.enuDirectionToEcef(f, eye, ray[0], ray[1], ray[2], scratch, dir);
                double t = EllipsoidRay.distanceToWgs84Metres(eye, dir);
                if (!Double.isFinite(t) || !Float.isFinite(d[i])) {
                    if (Double.isInfinite(t) && Float.isInfinite(d[i])) {
                        sky++;
                        assertTrue(Float.isNaN(elev[i]) && Float.isNaN(inc[i]) && Float.isNaN(lat[i]), "sky has no layers");
                    }
                    continue;
                }
                if (t > 20_000) {
                    continue; // beyond 20 km the facets' sag moves grazing points: checked by the distance tests
                }
                sea++;
                double[] p = {eye[0] + t * dir[0], eye[1] + t * dir[1], eye[2] + t * dir[2]};
                double[] geo = Ellipsoid.toGeodetic(p[0], p[1], p[2]);
                worstElev = Math.max(worstElev, Math.abs(elev[i]));
                double dLatM = Math.toRadians(lat[i] - geo[0]) * Ellipsoid.A_METRES;
                double dLonM = Math.toRadians(lon[i] - geo[1]) * Ellipsoid.A_METRES * Math.cos(Math.toRadians(LAT));
                worstLatLonMetres = Math.max(worstLatLonMetres, Math.hypot(dLatM, dLonM));
                worstGround = Math.max(worstGround, Math.abs(ground[i] - Geodesy.distanceMetres(LAT, LON, geo[0], geo[1])));
                double incidence = EllipsoidRay.incidenceDeg(p, dir, Ellipsoid.A_METRES, Ellipsoid.B_METRES);
                worstInc = Math.max(worstInc, Math.abs(inc[i] - incidence));
                assertEquals(Math.min(10 / Math.sin(Math.toRadians(inc[i])), d[i]), unc[i], 1e-3 * unc[i]);
            }
        }
        String report = String.format(Locale.ROOT, "%d sea pixels within 20 km, %d sky: worst elevation %.2e m, position %.2e m,"
                + " ground distance %.2e m, incidence %.2e°", sea, sky, worstElev, worstLatLonMetres, worstGround, worstInc);
        System.out.println(report);
        assertTrue(sea > w * h / 4 && sky > w * h / 10, report);
        // Float32 layers: a latitude in degrees holds ~0.4 m at 43°; the sea facets lie within 0.3 mm of the ellipsoid.
        assertTrue(worstElev < 0.01, report);
        assertTrue(worstLatLonMetres < 1.0, report);
        assertTrue(worstGround < 0.05, report);
        // Facets are planes through ellipsoid points: their tilt from the ellipsoid is below a cell's angle, 90 m / R.
        assertTrue(worstInc < 0.002, report);

        List<Path> files = CameraWriter.write(img, tmp.resolve("p").toString(), CameraWriter.Extras.NONE);
        for (Layer l : Layer.values()) {
            Path npy = tmp.resolve("p-" + l.fileName() + ".npy");
            assertTrue(files.contains(npy), "written: " + npy);
            float[] back = readNpy(npy, h, w);
            assertEquals(0, java.util.Arrays.compare(img.layerArray(l), back), l + " round trip");
        }
    }

    /** Reads a float32 little-endian .npy, checking its shape. */
    private static float[] readNpy(Path npy, int rows, int cols) throws Exception {
        byte[] all = Files.readAllBytes(npy);
        ByteBuffer b = ByteBuffer.wrap(all).order(ByteOrder.LITTLE_ENDIAN);
        int headerLength = b.getShort(8) & 0xFFFF;
        String header = new String(all, 10, headerLength, java.nio.charset.StandardCharsets.US_ASCII);
        assertTrue(header.contains("'<f4'") && header.contains("(" + rows + ", " + cols + ")"), header);
        float[] out = new float[rows * cols];
        b.position(10 + headerLength);
        b.asFloatBuffer().get(out);
        return out;
    }

    /** A 31° cone; the camera stands on its flank 300 m from the apex, 2 m up. */
    private static final double K = 111_195, APEX_LAT = 46.55, APEX_LON = 8.56;

    private static double cone(double la, double lo) {
        double n = (la - APEX_LAT) * K, e = (lo - APEX_LON) * K * Math.cos(Math.toRadians(46.5));
        return 800 + Math.max(0, 1500 - 0.6 * Math.hypot(n, e));
    }

    @Test
    void aCameraFacingTheSlopeItStandsOnIsWarnedAndOneFacingAwayIsNot() {
        InMemoryDem dem = Synthetic.tiles(CameraLayersTest::cone, 601, Synthetic.block(46, 8, 1, 1));
        double lat = APEX_LAT - 300 / K, lon = APEX_LON; // 300 m south of the apex: the slope rises to the north
        CameraIntrinsics k = CameraIntrinsics.fromHorizontalFov(160, 120, 60);
        PanoramaRequest settings = PanoramaRequest.at(lat, lon).withRangeMetres(20_000);
        try (PanoramaRenderer cpu = PanoramaRenderer.openReference(dem)) {
            CameraImage uphill = cpu.render(new CameraRequest(k, new CameraPose(lat, lon, 0, Double.NaN, 2,
                    new CameraOrientation(0, 10, 0)), settings));
            CameraImage downhill = cpu.render(new CameraRequest(k, new CameraPose(lat, lon, 0, Double.NaN, 2,
                    new CameraOrientation(180, 0, 0)), settings));
            List<String> up = uphill.metadata().warnings(), down = downhill.metadata().warnings();
            System.out.println("uphill: " + up + "\ndownhill: " + down);
            // Uphill, the 31° slope 2 m below the eye rises above 3° within 50 m in every azimuth the camera sees,
            // except the outermost bins, which only the top corners' rays reach (elevation 29°–33°, azimuth out to
            // ±32.3° at 10° pitch): they look over the slope. Bins are a pixel wide (0.41° here), so no bin between
            // two columns is reached by the top rows alone.
            double share = dempano.panorama.NearTerrain.measure(uphill.view(), uphill.distanceArray(), 50).blockedColumnShare();
            assertTrue(share > 0.96, "blocked share " + share);
            assertTrue(up.stream().anyMatch(s -> s.contains("terrain nearer than 50 m") && s.contains("of the camera's azimuths")),
                    up.toString());
            // The longest blocked run is one unbroken run over nearly all the azimuths the camera covers above the
            // horizontal (327.7°–32.3°).
            var near = dempano.panorama.NearTerrain.measure(uphill.view(), uphill.distanceArray(), 50);
            double span = Math.floorMod(Math.round(10 * (near.spanToAzimuthDeg() - near.spanFromAzimuthDeg())), 3600) / 10.0;
            assertTrue(span > 60 && span <= 64.6 && near.spanFromAzimuthDeg() > 327.5 && near.spanToAzimuthDeg() < 32.5,
                    near.toString());
            assertFalse(down.stream().anyMatch(s -> s.contains("terrain nearer than")), down.toString());
        }
    }

    @Test
    void aCameraViewTooLargeForTheHeapIsRefusedBeforeRendering() {
        CameraIntrinsics huge = CameraIntrinsics.fromFocal35mm(20_000, 15_000, 50);
        CameraRequest req = CameraRequest.of(huge, new CameraPose(LAT, LON, 0, EYE_METRES, 0,
                new CameraOrientation(0, 0, 0))).withSettings(PanoramaRequest.at(LAT, LON).withRangeMetres(20_000));
        // 3e8 photo pixels at 20 bytes while writing: over 6 GB, more than the test JVM's heap.
        MemoryEstimate cpuEstimate = MemoryEstimate.of(req, null, 0);
        assertTrue(cpuEstimate.heapBytes() > 6e9, "estimate " + cpuEstimate.heapBytes());
        InsufficientMemoryException small = assertThrows(InsufficientMemoryException.class,
                () -> MemoryEstimate.of(seaCamera(List.of()), null, 0).checkCamera(50L << 20));
        assertTrue(small.getMessage().contains("camera view"), small.getMessage());
        MemoryEstimate.of(seaCamera(List.of()), null, 0).checkCamera(1L << 30); // a small camera fits in 1 GB
        try (PanoramaRenderer r = PanoramaRenderer.openReference(sea())) {
            InsufficientMemoryException e = assertThrows(InsufficientMemoryException.class, () -> r.render(req));
            assertTrue(e.getMessage().startsWith("this camera view needs about") && e.getMessage().contains("-Xmx")
                    && e.getMessage().contains("300 M photo pixels"), e.getMessage());
            assertTrue(e.estimate().heapBytes() > Runtime.getRuntime().maxMemory());
        }
        // OpenGL: 20000 px wide needs views wider than GL allows, refused by name; 16000 × 16000 fits the views
        // (27 bytes per photo pixel while stitching: 7.6 GB) but not the heap.
        CameraRequest square = new CameraRequest(CameraIntrinsics.fromFocal35mm(16_000, 16_000, 50), req.pose(), req.settings());
        try (PanoramaRenderer r = PanoramaRenderer.open(sea())) {
            IllegalArgumentException wide = assertThrows(IllegalArgumentException.class, () -> r.render(req));
            assertTrue(wide.getMessage().contains("at most 16384"), wide.getMessage());
            InsufficientMemoryException e = assertThrows(InsufficientMemoryException.class, () -> r.render(square));
            assertTrue(e.getMessage().startsWith("this camera view needs about") && e.getMessage().contains("256 M photo pixels"),
                    e.getMessage());
            assertTrue(e.estimate().viewPixels() >= 256_000_000L, e.getMessage());
        }
    }
}
