package dempano.cli;

import dempano.CameraImage;
import dempano.CameraRequest;
import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.camera.LensDistortion;
import dempano.camera.PhotoCamera;
import dempano.camera.PhotoMetadata;
import dempano.camera.PhotoOverrides;
import dempano.dem.DemDirectory;
import dempano.geo.Refraction;
import dempano.io.CameraWriter;
import dempano.summits.SummitList;
import dempano.summits.SummitProjector;
import dempano.summits.SummitSighting;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import javax.imageio.ImageIO;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code dempano photo IMAGE --out P}: the photograph's own view, rendered on its pixel grid, with a distance for
 * every pixel. Pose and lens from the photo's EXIF/XMP, flags override; without IMAGE, a camera from flags alone
 * ({@code --width-px --height-px} and a lens) for synthetic use.
 */
@Command(name = "photo", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Render a photograph's own view: P.png, P-distance.npy (float32, metres, sky +inf), P.json,",
            "P-overlay.png (the photo with rendered silhouettes and summits) and, with --summits, P-summits.json/csv.",
            "Pose and lens come from the photo's EXIF/XMP; flags override. Without IMAGE, give --width-px, --height-px,",
            "--lat, --lon, --heading-deg and a lens (--hfov-deg, --focal35-mm or --focal-mm with --sensor-width-mm)."})
public final class PhotoCommand implements Callable<Integer> {
    @Parameters(index = "0", arity = "0..1", paramLabel = "IMAGE", description = "The photograph (JPEG, PNG, ...).")
    Path image;
    @Option(names = "--out", paramLabel = "P", description = "Output prefix (default: ${DEFAULT-VALUE}).", defaultValue = "build/photo")
    String out;
    @Option(names = "--dem-dir", paramLabel = "DIR", required = true, description = "Directory of DEM tiles; repeatable, in priority order.")
    List<Path> demDirs;
    @Option(names = PhotoOverrides.LAT, description = "Camera latitude, degrees north.")
    Double latDeg;
    @Option(names = PhotoOverrides.LON, description = "Camera longitude, degrees east.")
    Double lonDeg;
    @Option(names = PhotoOverrides.ALTITUDE, description = "Absolute standing altitude, metres above sea level.")
    Double altitudeMetres;
    @Option(names = PhotoOverrides.OFFSET, description = "Stand on the DEM corrected by this signed offset, metres.")
    Double offsetMetres;
    @Option(names = PhotoOverrides.CAMERA_HEIGHT, description = "Camera above the standing altitude, metres.")
    Double cameraHeightMetres;
    @Option(names = PhotoOverrides.HEADING, description = "True heading of the optical axis, degrees clockwise from north.")
    Double headingDeg;
    @Option(names = PhotoOverrides.DECLINATION, description = "Magnetic declination, degrees east positive (a magnetic EXIF direction is made true).")
    Double declinationDeg;
    @Option(names = PhotoOverrides.PITCH, description = "Pitch of the optical axis, degrees, positive up.")
    Double pitchDeg;
    @Option(names = PhotoOverrides.ROLL, description = "Roll, degrees, positive clockwise as the photographer sees it.")
    Double rollDeg;
    @Option(names = PhotoOverrides.FOCAL, description = "Focal length, mm (needs " + PhotoOverrides.SENSOR_WIDTH + ").")
    Double focalMm;
    @Option(names = PhotoOverrides.SENSOR_WIDTH, description = "Sensor's long side, mm.")
    Double sensorWidthMm;
    @Option(names = PhotoOverrides.FOCAL35, description = "35 mm-equivalent focal length, mm.")
    Double focal35Mm;
    @Option(names = PhotoOverrides.HFOV, description = "Horizontal field of view of the displayed image, degrees.")
    Double hfovDeg;
    @Option(names = "--distortion", paramLabel = "K1,K2,P1,P2,K3", split = ",", description = "OpenCV distortion coefficients.")
    double[] distortion;
    @Option(names = "--width-px", description = "Without IMAGE: image width, pixels.")
    Integer widthPx;
    @Option(names = "--height-px", description = "Without IMAGE: image height, pixels.")
    Integer heightPx;
    @Option(names = "--range-km", description = "Range of sight, km (default: ${DEFAULT-VALUE}).", defaultValue = "100")
    double rangeKm;
    @Option(names = "--refraction", paramLabel = "K", description = "Refraction coefficient (default: ${DEFAULT-VALUE}).", defaultValue = "0.13")
    double refraction;
    @Option(names = "--supersampling", description = "View pixels per photo pixel at the finest, linear (default: ${DEFAULT-VALUE}).", defaultValue = "1")
    double supersampling;
    @Option(names = "--exact-distances", negatable = true, defaultValue = "true", fallbackValue = "true",
            description = "Every pixel's distance along its own ray against the triangles seen (default); --no-exact-distances interpolates the views' depth.")
    boolean exactDistances;
    @Option(names = "--heading-range-deg", paramLabel = "DEG", description = "Estimate the heading within ± DEG of the one given (flag or EXIF compass) instead of taking it as is.")
    Double headingRangeDeg;
    @Option(names = "--summits", paramLabel = "FILE", description = "Summit list (as for panoramas): P-summits.json/csv and labels.")
    Path summitsFile;

    private BufferedImage orientationOverlay;
    private String orientationJson;

    @Override
    public Integer call() throws Exception {
        PhotoOverrides o = PhotoOverrides.NONE;
        if (latDeg != null || lonDeg != null) {
            o = o.withPosition(latDeg == null ? Double.NaN : latDeg, lonDeg == null ? Double.NaN : lonDeg);
        }
        o = altitudeMetres == null ? o : o.withAltitudeMetres(altitudeMetres);
        o = offsetMetres == null ? o : o.withOffsetMetres(offsetMetres);
        o = cameraHeightMetres == null ? o : o.withCameraHeightMetres(cameraHeightMetres);
        o = headingDeg == null ? o : o.withHeadingDeg(headingDeg);
        o = declinationDeg == null ? o : o.withDeclinationDeg(declinationDeg);
        o = pitchDeg == null ? o : o.withPitchDeg(pitchDeg);
        o = rollDeg == null ? o : o.withRollDeg(rollDeg);
        o = focalMm == null ? o : o.withFocalLengthMm(focalMm);
        o = sensorWidthMm == null ? o : o.withSensorWidthMm(sensorWidthMm);
        o = focal35Mm == null ? o : o.withFocal35mmMm(focal35Mm);
        o = hfovDeg == null ? o : o.withHorizontalFovDeg(hfovDeg);
        if (distortion != null) {
            if (distortion.length != 5) {
                throw new IllegalArgumentException("--distortion needs five numbers K1,K2,P1,P2,K3, got " + distortion.length);
            }
            o = o.withDistortion(new LensDistortion(distortion[0], distortion[1], distortion[2], distortion[3], distortion[4]));
        }
        PhotoMetadata meta;
        BufferedImage photo = null;
        if (image != null) {
            if (widthPx != null || heightPx != null) {
                throw new IllegalArgumentException("--width-px and --height-px are for a camera without a photo: the"
                        + " photo's own size is used");
            }
            meta = PhotoMetadata.read(image);
            BufferedImage stored = ImageIO.read(image.toFile());
            if (stored != null) {
                photo = CameraWriter.displayed(stored, meta.orientation());
            }
        } else {
            if (widthPx == null || heightPx == null || widthPx < 1 || heightPx < 1) {
                throw new IllegalArgumentException("no photo: give IMAGE, or --width-px and --height-px (≥ 1) for a"
                        + " camera from flags alone");
            }
            meta = new PhotoMetadata("camera from flags", widthPx, heightPx, 1, Double.NaN, Double.NaN, Double.NaN,
                    Double.NaN, null, Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN, null, List.of());
        }
        // Heading, pitch, roll and field of view that neither flags nor metadata give are estimated from the skyline.
        dempano.orient.PhotoOrientation open = photo == null ? new dempano.orient.PhotoOrientation(false, false, false, false)
                : dempano.orient.PhotoOrientation.open(meta, o, headingRangeDeg != null);
        PhotoOverrides given = o;
        if (open.any()) {
            System.err.println("  estimating from the skyline: " + String.join(", ", open.names()));
            o = open.placeholders(o);
        }
        PhotoCamera camera;
        try {
            camera = meta.resolve(o);
        } catch (dempano.camera.PhotoMetadataException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
        camera.provenance().forEach(line -> System.err.println("  " + line));
        dempano.io.OutputSet.checkPrefix(out);
        Path outParent = Path.of(out).toAbsolutePath().getParent();
        if (outParent != null && out.startsWith("build/")) {
            java.nio.file.Files.createDirectories(outParent);
        }
        SummitList summits = summitsFile == null ? null : dempano.summits.SummitReader.read(summitsFile, false);
        List<DemDirectory> sources = new ArrayList<>();
        for (Path d : demDirs) {
            DemDirectory one = new DemDirectory(d);
            one.warnings().forEach(w -> System.err.println("  warning: " + w));
            sources.add(one);
        }
        PanoramaRequest settings = PanoramaRequest.at(camera.pose().latDeg(), camera.pose().lonDeg())
                .withRangeMetres(rangeKm * 1000).withRefraction(new Refraction(refraction))
                .withSupersampling(supersampling).withExactDistances(exactDistances);
        CameraImage rendered;
        try (PanoramaRenderer r = PanoramaRenderer.open(dempano.dem.PriorityDem.of(sources))) {
            if (open.any()) {
                dempano.camera.CameraOrientation k = camera.pose().orientation();
                dempano.orient.PhotoOrientation.Result est;
                try {
                    est = open.estimate(r, settings.withOffsetMetres(camera.pose().offsetMetres())
                                    .withAltitudeMetres(camera.pose().altitudeMetres()).withEyeHeightMetres(camera.pose().cameraHeightMetres()),
                            photo, new double[] {k.headingDeg(), k.pitchDeg(), k.rollDeg(), camera.intrinsics().horizontalFovDeg()},
                            // The range is a prior only around a heading that was given (flag or metadata).
                            headingRangeDeg == null || meta.missing(given.withHeadingDeg(0)).size() < meta.missing(given).size()
                                    ? Double.NaN : headingRangeDeg);
                } catch (IllegalArgumentException e) {
                    List<String> missing = meta.missing(given);
                    throw new IllegalArgumentException("could not estimate the " + String.join(", ", open.names())
                            + " from the photo: " + e.getMessage() + (missing.isEmpty() ? "" : "; give them instead:\n  - "
                            + String.join("\n  - ", missing)), e);
                }
                String line = est.provenance(open);
                System.out.println(line);
                try {
                    camera = meta.resolve(open.apply(given, est.estimate()));
                } catch (dempano.camera.PhotoMetadataException e) {
                    throw new IllegalArgumentException(e.getMessage(), e);
                }
                List<String> prov = new ArrayList<>(camera.provenance());
                prov.add(line);
                camera = new PhotoCamera(camera.intrinsics(), camera.pose(), prov);
                orientationOverlay = est.overlay();
                orientationJson = new com.google.gson.GsonBuilder().setPrettyPrinting().serializeSpecialFloatingPointValues()
                        .create().toJson(est.estimate());
            }
            rendered = r.render(CameraRequest.of(camera).withSettings(settings),
                    stage -> System.err.println("  " + stage));
        }
        List<SummitSighting> sightings = summits == null ? null : SummitProjector.project(rendered, summits);
        List<Path> files = CameraWriter.write(rendered, out, new CameraWriter.Extras(photo, sightings, camera.provenance()));
        System.out.println(String.format(Locale.ROOT, "%d×%d view at %.5f, %.5f (eye %.1f m), %d view(s) of %d×%d;"
                        + " timings %s", rendered.widthPx(), rendered.heightPx(), rendered.metadata().latDeg(),
                rendered.metadata().lonDeg(), rendered.metadata().eyeAltitudeMetres(), rendered.metadata().views(),
                rendered.metadata().viewWidthPx(), rendered.metadata().viewHeightPx(), rendered.metadata().timingsMillis()));
        if (orientationOverlay != null) {
            Path png = Path.of(out + "-orientation.png"), json = Path.of(out + "-orientation.json");
            ImageIO.write(orientationOverlay, "png", png.toFile());
            java.nio.file.Files.writeString(json, orientationJson + "\n");
            files = new ArrayList<>(files);
            files.add(png);
            files.add(json);
        }
        files.forEach(f -> System.out.println("wrote " + f));
        return 0;
    }
}
