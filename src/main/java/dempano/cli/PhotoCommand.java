package dempano.cli;

import dempano.CameraImage;
import dempano.PanoramaRequest;
import dempano.camera.LensDistortion;
import dempano.camera.PhotoOverrides;
import dempano.summits.SummitList;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import dempano.photo.PhotoJob;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code dempano photo IMAGE --out P}: the photograph's own view, rendered on its pixel grid, with a distance for
 * every pixel. Pose and lens from the photo's EXIF/XMP, flags override; without IMAGE, a camera from flags alone
 * ({@code --width-px --height-px} and a lens) for synthetic use.
 */
@Command(name = "photo", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Render a photograph's own view, its distances and summits; estimate its pose where EXIF and flags leave it open.",
            "Writes P.png, P-distance.npy (float32, metres, sky +inf), P.json, P-overlay.png (the photo with rendered",
            "silhouettes and summits) and, with --summits, P-summits.json/csv.",
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
    @Option(names = PhotoOverrides.HFOV, description = "Horizontal field of view of the displayed image, degrees (with --distortion: of the"
            + " undistorted pinhole image; P.json's horizontalFovDeg is the distorted image's, edge to edge).")
    Double hfovDeg;
    @Option(names = "--distortion", paramLabel = "K1,K2,P1,P2,K3", split = ",", description = "OpenCV distortion coefficients.")
    double[] distortion;
    @Option(names = "--width-px", description = "Without IMAGE: image width, pixels.")
    Integer widthPx;
    @Option(names = "--height-px", description = "Without IMAGE: image height, pixels.")
    Integer heightPx;
    /** The render options shared with panoramas (range, refraction, supersampling, exact distances, layers, renderer, ...). */
    @Mixin
    RenderOptions render = new RenderOptions();
    @Option(names = "--heading-range-deg", paramLabel = "DEG", description = "Estimate the heading within ± DEG of the one given (flag or EXIF compass) instead of taking it as is.")
    Double headingRangeDeg;
    @Option(names = "--hfov-range-deg", paramLabel = "MIN,MAX", split = ",", description = "Estimate the horizontal field of view within MIN..MAX degrees (when neither flags nor EXIF give it).")
    double[] hfovRangeDeg;
    @Option(names = "--focal35-range-mm", paramLabel = "MIN,MAX", split = ",", description = "Estimate the field of view for a 35 mm-equivalent focal length within MIN..MAX mm (a zoom lens; when neither flags nor EXIF give it).")
    double[] focal35RangeMm;
    @Option(names = "--summits", paramLabel = "FILE", description = "Summit list (as for panoramas): P-summits.json/csv and labels.")
    Path summitsFile;

    /** Where relative paths lead and the renderer comes from (the resident process sets the client's). */
    RunContext context = RunContext.HERE;

    /** The search ranges from the flags; a range is two numbers. */
    dempano.orient.SearchRanges ranges() {
        double[] fov = pair(hfovRangeDeg, "--hfov-range-deg"), focal = pair(focal35RangeMm, "--focal35-range-mm");
        return new dempano.orient.SearchRanges(headingRangeDeg == null ? Double.NaN : headingRangeDeg, fov[0], fov[1],
                focal[0], focal[1]);
    }

    private static double[] pair(double[] v, String flag) {
        if (v == null) {
            return new double[] {Double.NaN, Double.NaN};
        }
        if (v.length != 2 || !Double.isFinite(v[0]) || !Double.isFinite(v[1])) {
            throw new IllegalArgumentException(flag + " must be MIN,MAX (two finite numbers), got "
                    + java.util.Arrays.toString(v));
        }
        return v;
    }

    @Override
    public Integer call() throws Exception {
        Path image = context.resolve(this.image), summitsFile = context.resolve(this.summitsFile);
        String out = context.resolve(this.out);
        List<Path> demDirs = this.demDirs.stream().map(context::resolve).toList();
        PanoramaRequest settings = render.applyTo(PanoramaRequest.at(0, 0), PanoramaRequest.DEFAULT_RANGE_METRES);
        boolean reference = render.referenceRenderer();
        dempano.dem.DemFill fill = render.demFill();
        PhotoOverrides overrides = overrides();
        if (image == null) {
            // Checked before anything is read, as before: a camera from flags needs its size.
            if (widthPx == null || heightPx == null || widthPx < 1 || heightPx < 1) {
                throw new IllegalArgumentException("no photo: give IMAGE, or --width-px and --height-px (≥ 1) for a"
                        + " camera from flags alone");
            }
        }
        if (headingRangeDeg != null && headingRangeDeg.isNaN()) {
            throw new IllegalArgumentException("--heading-range-deg must be in (0°, 180°], got NaN");
        }
        dempano.io.OutputSet.checkPrefix(out);
        Path outParent = Path.of(out).toAbsolutePath().getParent();
        if (outParent != null && this.out.startsWith("build/")) {
            java.nio.file.Files.createDirectories(outParent);
        }
        SummitList summits = summitsFile == null ? null : dempano.summits.SummitReader.read(summitsFile, false);
        // Its warnings come from the job, once the summits without a height are placed on the DEM.
        PhotoJob.Input input = new PhotoJob.Input(image, overrides, widthPx, heightPx, ranges(), settings, summits, out);
        dempano.dem.DemSource dem = dempano.dem.PriorityDem.open(demDirs, fill, w -> System.err.println("  warning: " + w));
        PhotoJob.Result done;
        // Meshes kept through the job (as with --repeat): the orientation's panoramas and the photo's view share them.
        try (Main.Renderers.Lease lease = context.renderers().lease(dem, reference, 2)) {
            done = PhotoJob.run(lease.renderer(), input, new PhotoJob.Log() {
                @Override
                public void progress(String line) {
                    System.err.println("  " + line);
                }

                @Override
                public void result(String line) {
                    System.out.println(line);
                }
            });
        } catch (IllegalStateException e) {
            if (!reference) {
                throw e;
            }
            throw new IllegalArgumentException("--renderer reference: " + e.getMessage(), e);
        }
        CameraImage rendered = done.image();
        // As the panorama's: kept in P.json, and said (a missing tile, a slope at the camera's feet).
        rendered.metadata().warnings().forEach(w -> System.err.println("  warning: " + w));
        System.out.println(String.format(Locale.ROOT, "%d×%d view at %.5f, %.5f (eye %.1f m), %d view(s) of %d×%d;"
                        + " timings %s", rendered.widthPx(), rendered.heightPx(), rendered.metadata().latDeg(),
                rendered.metadata().lonDeg(), rendered.metadata().eyeAltitudeMetres(), rendered.metadata().views(),
                rendered.metadata().viewWidthPx(), rendered.metadata().viewHeightPx(), rendered.metadata().timingsMillis()));
        context.asGiven(done.files(), this.out).forEach(f -> System.out.println("wrote " + f));
        return 0;
    }

    /** An angle within ±{@code limitDeg} degrees (a heading of 1e308 is a typo, not a direction). */
    private static double within(String flag, Double v, double limitDeg) {
        finite(flag, v);
        if (!(Math.abs(v) <= limitDeg)) {
            throw new IllegalArgumentException(flag + " must be within ±" + (int) limitDeg + " degrees, got " + v);
        }
        return v;
    }

    private static double finite(String flag, Double v) {
        if (!Double.isFinite(v)) {
            throw new IllegalArgumentException(flag + " must be a finite number, got " + v);
        }
        return v;
    }

    /** The camera values given as flags. */
    private PhotoOverrides overrides() {
        // NaN means "not given" inside: a NaN typed on the command line must not silently become "estimate it".
        for (int i = 0; distortion != null && i < distortion.length; i++) {
            finite("--distortion", distortion[i]);
        }
        PhotoOverrides o = PhotoOverrides.NONE;
        if ((latDeg == null) != (lonDeg == null)) { // (it was taken for no position at all)
            throw new IllegalArgumentException(latDeg == null ? PhotoOverrides.LON + " given without " + PhotoOverrides.LAT
                    : PhotoOverrides.LAT + " given without " + PhotoOverrides.LON);
        }
        if (latDeg != null || lonDeg != null) {
            o = o.withPosition(latDeg == null ? Double.NaN : finite(PhotoOverrides.LAT, latDeg),
                    lonDeg == null ? Double.NaN : finite(PhotoOverrides.LON, lonDeg));
        }
        o = altitudeMetres == null ? o : o.withAltitudeMetres(finite(PhotoOverrides.ALTITUDE, altitudeMetres));
        o = offsetMetres == null ? o : o.withOffsetMetres(finite(PhotoOverrides.OFFSET, offsetMetres));
        if (altitudeMetres != null && offsetMetres != null) { // the offset was ignored without a word
            throw new IllegalArgumentException(PhotoOverrides.ALTITUDE + " and " + PhotoOverrides.OFFSET + " both set the standing height (an absolute altitude, or the DEM's height plus an offset): give one");
        }
        o = cameraHeightMetres == null ? o : o.withCameraHeightMetres(finite(PhotoOverrides.CAMERA_HEIGHT, cameraHeightMetres));
        o = headingDeg == null ? o : o.withHeadingDeg(within(PhotoOverrides.HEADING, headingDeg, PhotoOverrides.HEADING_LIMIT_DEG));
        o = declinationDeg == null ? o : o.withDeclinationDeg(within(PhotoOverrides.DECLINATION, declinationDeg,
                PhotoOverrides.DECLINATION_LIMIT_DEG));
        o = pitchDeg == null ? o : o.withPitchDeg(within(PhotoOverrides.PITCH, pitchDeg, PhotoOverrides.PITCH_LIMIT_DEG));
        o = rollDeg == null ? o : o.withRollDeg(within(PhotoOverrides.ROLL, rollDeg, PhotoOverrides.ROLL_LIMIT_DEG));
        o = focalMm == null ? o : o.withFocalLengthMm(finite(PhotoOverrides.FOCAL, focalMm));
        o = sensorWidthMm == null ? o : o.withSensorWidthMm(finite(PhotoOverrides.SENSOR_WIDTH, sensorWidthMm));
        o = focal35Mm == null ? o : o.withFocal35mmMm(finite(PhotoOverrides.FOCAL35, focal35Mm));
        o = hfovDeg == null ? o : o.withHorizontalFovDeg(finite(PhotoOverrides.HFOV, hfovDeg));
        List<PhotoOverrides.Lens> lenses = o.lensesGiven();
        if (lenses.size() > 1) { // all but the first were left unused without a word
            throw new IllegalArgumentException(lenses.stream().map(l -> switch (l) {
                case FIELD_OF_VIEW -> PhotoOverrides.HFOV;
                case FOCAL35 -> PhotoOverrides.FOCAL35;
                case FOCAL_LENGTH_AND_SENSOR -> PhotoOverrides.FOCAL + "/" + PhotoOverrides.SENSOR_WIDTH;
                case CALIBRATION -> "a calibration";
            }).collect(java.util.stream.Collectors.joining(" and ")) + " each set the field of view: give one");
        }
        if (distortion != null) {
            if (distortion.length != 5) {
                throw new IllegalArgumentException("--distortion needs five numbers K1,K2,P1,P2,K3, got " + distortion.length);
            }
            o = o.withDistortion(new LensDistortion(distortion[0], distortion[1], distortion[2], distortion[3], distortion[4]));
        }
        return o;
    }
}
