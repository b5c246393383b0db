package dempano.photo;

import dempano.CameraImage;
import dempano.CameraRequest;
import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.camera.PhotoCamera;
import dempano.camera.PhotoMetadata;
import dempano.camera.PhotoMetadataException;
import dempano.camera.PhotoOverrides;
import dempano.io.CameraWriter;
import dempano.io.OutputSet;
import dempano.orient.OrientationEstimate;
import dempano.orient.PhotoOrientation;
import dempano.orient.SearchRanges;
import dempano.summits.SummitList;
import dempano.summits.SummitProjector;
import dempano.summits.SummitSighting;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import javax.imageio.ImageIO;

/**
 * One photograph's job, on a renderer the caller holds open (so that many photos share its tiles, caches and
 * GL context): the camera from the photo's EXIF/XMP and the overrides; the heading, pitch, roll or field of
 * view that neither gives estimated from the photo's skyline ({@link PhotoOrientation}); the camera view
 * rendered; the summits in frame; and the files for prefix P written as one {@link OutputSet}:
 * {@code P.png}, {@code P-distance.npy}, {@code P-overlay.png}, {@code P.json}, with summits
 * {@code P-summits.json/csv}, and after an estimate {@code P-orientation.png/json}. {@code dempano photo},
 * {@code dempano batch} and the Spark job all run photos through here. Stateless.
 *
 * <pre>{@code
 * try (PanoramaRenderer r = PanoramaRenderer.open(dem)) {
 *     for (Path jpg : photos) {
 *         PhotoJob.run(r, PhotoJob.Input.of(jpg, settings, "out/" + name(jpg)), PhotoJob.Log.NONE);
 *     }
 * }
 * }</pre>
 */
public final class PhotoJob {
    private PhotoJob() {
    }

    /**
     * What to render for one photo.
     *
     * @param image           the photograph (JPEG, PNG, ...); null for a camera from the overrides alone
     * @param overrides       values that replace (or stand in for) the photo's metadata
     * @param widthPx         without an image: the image width, pixels; null with one (its own size is used)
     * @param heightPx        without an image: the image height, pixels; null with one
     * @param ranges          where the estimate searches: the heading within ± some degrees of the one given (override
     *                        or compass; none: a given heading taken as it is), the field of view within a range
     *                        (or a zoom lens's focal lengths) where it is open; null = {@link SearchRanges#NONE}
     * @param settings        range, refraction, supersampling, exact distances, layers, ... for the render; its
     *                        viewpoint, offset, altitude and eye height are replaced by the camera's pose
     * @param summits         the summit list for {@code P-summits.json/csv} and overlay labels; null = none
     * @param outPrefix       the output prefix P (its folder must exist)
     */
    public record Input(Path image, PhotoOverrides overrides, Integer widthPx, Integer heightPx, SearchRanges ranges,
                        PanoramaRequest settings, SummitList summits, String outPrefix) {
        public Input {
            Objects.requireNonNull(overrides, "overrides");
            Objects.requireNonNull(settings, "settings");
            Objects.requireNonNull(outPrefix, "outPrefix");
            ranges = ranges == null ? SearchRanges.NONE : ranges;
        }

        /** The heading range, degrees; NaN: none. */
        public double headingRangeDeg() {
            return ranges.headingRangeDeg();
        }

        /** A photo with its metadata and no overrides, heading as given, no summits. */
        public static Input of(Path image, PanoramaRequest settings, String outPrefix) {
            return new Input(Objects.requireNonNull(image, "image"), PhotoOverrides.NONE, null, null, SearchRanges.NONE,
                    settings, null, outPrefix);
        }
    }

    /** Where the job's messages go: progress lines (stages, provenance) and result lines (an estimate's summary). */
    public interface Log {
        /** Says nothing. */
        Log NONE = new Log() { };

        /** A progress line: a render stage, where a camera value came from. */
        default void progress(String line) {
        }

        /** A result line: what an orientation estimate found. */
        default void result(String line) {
        }
    }

    /**
     * What the job made.
     *
     * @param camera the camera rendered (after any estimate), with where each value came from
     * @param image  the rendered camera view
     * @param files  the files written, {@code P.json} before the orientation files
     */
    public record Result(PhotoCamera camera, CameraImage image, List<Path> files) {
        public Result {
            files = List.copyOf(files);
        }
    }

    /**
     * Runs the job. Nothing is written unless everything succeeds.
     *
     * @throws IllegalArgumentException naming the problem (or the flag that supplies a missing value) for a
     *                                  photo whose camera cannot be had: unreadable or corrupt, missing
     *                                  metadata, a skyline that gives no estimate
     * @throws IOException              when the outputs cannot be written (the message names the file)
     */
    public static Result run(PanoramaRenderer renderer, Input in, Log log) throws IOException {
        return new Job(renderer, in, log).run();
    }

    /** A photo whose header declares more pixels on a side than a view can have (not a corrupt one). */
    static final class TooLarge extends IOException {
        TooLarge(String message) {
            super(message);
        }
    }

    /** A photo as read: its metadata and, where this Java decodes them, its pixels as displayed (else null). */
    private record Photo(PhotoMetadata meta, BufferedImage pixels) {
    }

    /** What an estimate adds to the files: the camera it gives, its overlay and its JSON. */
    private record Estimated(PhotoCamera camera, BufferedImage overlay, String json) {
    }

    /** One run of {@link #run}, its steps in order: the photo read, the camera resolved, estimated, rendered, written. */
    private static final class Job {
        final PanoramaRenderer renderer;
        final Input in;
        final Log log;

        Job(PanoramaRenderer renderer, Input in, Log log) {
            this.renderer = renderer;
            this.in = in;
            this.log = log;
        }

        Result run() throws IOException {
            Photo photo = readPhoto();
            // The output set is opened before anything is estimated or rendered: an unwritable destination, or one that
            // would write over the photo, is found first, not after seconds of work.
            try (OutputSet set = OutputSet.open(in.outPrefix())) {
                set.protect(in.image(), "the photo").protect(sourceFile(in.summits()), "the summit list");
                return estimateRenderAndStage(photo, set);
            }
        }

        /** The steps after the photo is read, the files staged in {@code set} and committed. */
        private Result estimateRenderAndStage(Photo photo, OutputSet set) throws IOException {
            PhotoMetadata meta = photo.meta();
            PhotoOverrides given = in.overrides();
            // Heading, pitch, roll and field of view that neither overrides nor metadata give are estimated from the skyline.
            PhotoOrientation open;
            try {
                open = photo.pixels() == null ? new PhotoOrientation(false, false, false, false, false)
                        : PhotoOrientation.open(meta, given, !Double.isNaN(in.headingRangeDeg()));
            } catch (PhotoMetadataException e) { // a value out of range (a field of view of 0°), named with its file
                throw new IllegalArgumentException(e.getMessage(), e);
            }
            PhotoOverrides o = given;
            if (open.any()) {
                log.progress("estimating from the skyline: " + String.join(", ", open.names())
                        + (open.altitude() ? "; the eye's altitude too where the skyline constrains it" : ""));
                // What the photo or the flags gave but could not be used (a magnetic compass without the declination,
                // a focal length without the sensor's size) is said: the estimate replaces it.
                for (String unused : photo.meta().missing(given)) {
                    if (!unused.startsWith("no ")) {
                        log.progress("estimated instead: " + unused);
                    }
                }
                o = open.placeholders(meta, o);
            }
            PhotoCamera camera = resolve(meta, o);
            // Where the altitude would be the EXIF one, the DEM's surface under it (once: the position does not change).
            double gpsGround = gpsGround(renderer, in.settings(), meta, o, camera);
            camera = Double.isNaN(gpsGround) ? camera : resolve(meta, o, gpsGround, java.util.Set.of());
            // The lines of the values to be estimated (placeholders until then) are not news: left out.
            List<String> withPlaceholdersNamed = resolve(meta, o, gpsGround, open.estimatedFlags(given, null)).provenance();
            for (int i = 0; i < withPlaceholdersNamed.size(); i++) {
                if (withPlaceholdersNamed.get(i).equals(camera.provenance().get(i))) {
                    log.progress(withPlaceholdersNamed.get(i));
                }
            }
            PanoramaRequest settings = atCamera(in.settings(), camera.pose().latDeg(), camera.pose().lonDeg());
            if (in.ranges().hasFovRange() && !open.hfov()) {
                log.progress("the field-of-view range " + in.ranges().describeFov(camera.intrinsics().widthPx(),
                        camera.intrinsics().heightPx()) + " not used: the field of view is "
                        + (photo.pixels() == null ? "given" : "known (flag or metadata)") + ", not estimated");
            }
            Estimated estimated = null;
            if (open.any()) {
                estimated = estimate(photo, given, open, camera, gpsGround, settings);
                camera = estimated.camera();
            }
            CameraImage rendered = render(camera, settings, photo.pixels() != null);
            List<SummitSighting> sightings = null;
            if (in.summits() != null) {
                SummitList placed = SummitProjector.placedOnDem(in.summits(), renderer.dem(), rendered.metadata());
                SummitProjector.warnings(placed, rendered.metadata()).forEach(w -> log.progress("warning: " + w));
                sightings = SummitProjector.withDem(SummitProjector.project(rendered, placed), renderer.dem());
            }
            List<CameraWriter.ExtraFile> orientationFiles = estimated == null ? List.of() : List.of(
                    new CameraWriter.ExtraFile("-orientation.png", pngBytes(estimated.overlay())),
                    new CameraWriter.ExtraFile("-orientation.json",
                            (estimated.json() + "\n").getBytes(StandardCharsets.UTF_8)));
            List<Path> files = CameraWriter.stage(set, rendered,
                    new CameraWriter.Extras(photo.pixels(), sightings, camera.provenance(), orientationFiles));
            set.commit();
            return new Result(camera, rendered, files);
        }

        /** The photo's metadata and pixels, or a camera from the flags alone (no image). */
        private Photo readPhoto() {
            if (in.image() == null) {
                if (in.widthPx() == null || in.heightPx() == null || in.widthPx() < 1 || in.heightPx() < 1) {
                    throw new IllegalArgumentException("no photo: give IMAGE, or --width-px and --height-px (≥ 1) for a"
                            + " camera from flags alone");
                }
                return new Photo(new PhotoMetadata("camera from flags", in.widthPx(), in.heightPx(), 1, PhotoMetadata.Gps.NONE,
                        PhotoMetadata.Lens.NONE, PhotoMetadata.XmpAttitude.NONE, List.of()), null);
            }
            if (in.widthPx() != null || in.heightPx() != null) {
                throw new IllegalArgumentException("--width-px and --height-px are for a camera without a photo: the"
                        + " photo's own size is used");
            }
            PhotoMetadata meta;
            try {
                meta = PhotoMetadata.read(in.image());
            } catch (PhotoMetadataException e) {
                throw new IllegalArgumentException(e.getMessage(), e);
            }
            BufferedImage stored;
            try {
                stored = readPixels(in.image());
            } catch (TooLarge e) { // a sound photo, only too large
                throw new IllegalArgumentException(in.image() + ": " + e.getMessage(), e);
            } catch (IOException | RuntimeException e) {
                throw new IllegalArgumentException(in.image() + ": corrupt photograph, its pixels cannot be decoded ("
                        + e.getMessage() + ")", e);
            }
            if (stored == null) {
                log.progress(in.image() + ": its metadata is read, but this Java has no decoder for its pixels (convert"
                        + " it to JPEG or PNG): nothing is estimated from the photo and it is not overlaid");
                return new Photo(meta, null);
            }
            BufferedImage displayed = CameraWriter.displayed(stored, meta.orientation());
            return new Photo(meta.withDecodedSize(displayed.getWidth(), displayed.getHeight()), displayed);
        }

        /**
         * The values {@code open} leaves to the photo, estimated from its skyline: the camera with them, the
         * provenance saying where each came from, and the orientation files' contents.
         */
        private Estimated estimate(Photo photo, PhotoOverrides given, PhotoOrientation open, PhotoCamera camera,
                                   double gpsGround, PanoramaRequest settings) {
            PhotoMetadata meta = photo.meta();
            if (!open.hfov()) {
                // A known field of view too wide to render fails now, not after seconds of estimating (level, as placed).
                try {
                    dempano.panorama.ViewLayout.checkCoverable(CameraRequest.of(camera).view(), settings.supersampling());
                } catch (IllegalArgumentException e) {
                    throw tooWideSaysWhy(e, camera);
                }
            }
            // The range is a prior only around a heading that was given (override or metadata).
            double headingRangeDeg = PhotoOrientation.headingGiven(meta, given) ? in.headingRangeDeg() : Double.NaN;
            double priorHeadingDeg = camera.pose().orientation().headingDeg();
            if (!Double.isNaN(in.headingRangeDeg()) && Double.isNaN(headingRangeDeg)) {
                log.progress("--heading-range-deg " + PhotoMetadata.num(in.headingRangeDeg()) + " not used: no heading"
                        + " (flag or EXIF compass) to search around; every heading is searched");
            }
            PhotoOrientation.Result est;
            try {
                est = open.estimate(renderer, settings.withOffsetMetres(camera.pose().offsetMetres())
                                .withAltitudeMetres(camera.pose().altitudeMetres())
                                .withEyeHeightMetres(camera.pose().cameraHeightMetres()),
                        photo.pixels(), camera, in.ranges().withHeadingRangeDeg(headingRangeDeg));
            } catch (dempano.InsufficientMemoryException e) {
                // The panorama matched against has a fixed grid: --ppd and --elevation-range are not the photo's to lower.
                throw new dempano.InsufficientMemoryException(e.estimate().matchPanoramaMessage(Runtime.getRuntime().maxMemory(),
                        String.join(", ", open.names()), String.join(", ", PhotoOverrides.HEADING, PhotoOverrides.PITCH,
                                PhotoOverrides.ROLL, PhotoOverrides.HFOV)), e.estimate());
            } catch (dempano.geo.EyeBelowGroundException e) {
                throw e; // the altitude is wrong, not the values the estimate looks for
            } catch (IllegalArgumentException e) {
                IllegalArgumentException tooWide = tooWideSaysWhy(e, camera);
                if (tooWide != e) {
                    throw tooWide;
                }
                List<String> missing = meta.missing(given);
                throw new IllegalArgumentException("could not estimate the " + String.join(", ", open.names())
                        + " from the photo: " + e.getMessage() + (missing.isEmpty() ? "" : "; give them instead:\n  - "
                        + String.join("\n  - ", missing)), e);
            }
            String line = est.provenance(open);
            log.result(line);
            OrientationEstimate e = est.estimate();
            checkMatched(e, open, meta.missing(given));
            if (e.marginScore() < 0 && e.second() != null) {
                // A heading pinned (or a prior) that the skyline contradicts: say where it fits, and how to search.
                log.result(String.format(java.util.Locale.ROOT, "the skyline fits better at heading %.1f° than at %.1f°"
                        + " (the heading given%s): %s", e.secondHeadingDeg(), e.headingDeg(), Double.isNaN(headingRangeDeg)
                        ? "" : " ± " + PhotoMetadata.num(headingRangeDeg) + "°", open.heading()
                        ? "widen --heading-range-deg, or check the position" : "give --heading-range-deg (e.g. 20) to search"
                        + " around it, as for a compass"));
            }
            PhotoCamera estimated = resolve(meta, open.apply(given, e, camera.pose()), gpsGround,
                    open.estimatedFlags(given, e));
            List<String> prov = new ArrayList<>(estimated.provenance());
            if (!Double.isNaN(headingRangeDeg)) {
                prov.add(String.format(java.util.Locale.ROOT, "heading searched within ± %s° of %s° (%s)",
                        PhotoMetadata.num(headingRangeDeg), PhotoMetadata.num(priorHeadingDeg), Double.isNaN(given.headingDeg())
                                ? "the photo's metadata" : PhotoOverrides.HEADING));
            }
            if (open.hfov() && in.ranges().hasFovRange()) {
                prov.add("field of view searched within " + in.ranges().describeFov(estimated.intrinsics().widthPx(),
                        estimated.intrinsics().heightPx()));
            }
            prov.add(line);
            com.google.gson.Gson gson = dempano.io.Json.writer();
            com.google.gson.JsonObject json = gson.toJsonTree(e).getAsJsonObject();
            json.addProperty("matchedWidthPx", est.matchedWidthPx()); // the image matched in (MatchImage)
            json.addProperty("matchedHeightPx", est.matchedHeightPx());
            return new Estimated(new PhotoCamera(estimated.intrinsics(), estimated.pose(), prov), est.overlay(),
                    gson.toJson(json));
        }

        /** The camera view, its errors as this photo's: its own size, its field of view's source. */
        private CameraImage render(PhotoCamera camera, PanoramaRequest settings, boolean hasPhoto) {
            try {
                return renderer.render(CameraRequest.of(camera).withSettings(settings), log::progress);
            } catch (dempano.InsufficientMemoryException e) {
                // A photo's size is its own: the camera-from-flags advice (--width-px/--height-px) is refused with a photo.
                throw !hasPhoto ? e : new dempano.InsufficientMemoryException(
                        e.estimate().photoMessage(Runtime.getRuntime().maxMemory()), e.estimate());
            } catch (IllegalArgumentException e) {
                throw tooWideSaysWhy(e, camera);
            }
        }
    }

    /**
     * Refuses an estimate that not one skyline sample fits (a photo upside down, of another place): there is no pose
     * to render, only an arbitrary one (an unsure estimate that fits somewhere is written, flagged).
     *
     * @param missing what the metadata and flags leave missing, each with its flag, for the way out
     * @throws IllegalArgumentException saying so
     */
    static void checkMatched(OrientationEstimate e, PhotoOrientation open, List<String> missing) {
        if (!(e.inlierShare() > 0)) {
            throw new IllegalArgumentException("could not estimate the " + String.join(", ", open.names())
                    + " from the photo: its skyline fits the panorama at 0 % of its samples, in no pose (is the photo"
                    + " upright, and the position right?)" + (missing.isEmpty() ? "" : "; give them instead:\n  - "
                    + String.join("\n  - ", missing)));
        }
    }

    /** The file a summit list was read from, as far as its source names one; null for none. */
    private static Path sourceFile(SummitList summits) {
        try {
            return summits == null ? null : Path.of(summits.source());
        } catch (java.nio.file.InvalidPathException e) {
            return null;
        }
    }

    /**
     * The photo's pixels as ImageIO decodes them; null for a format it has no reader for. A file that ends before its
     * pixels do (a truncated download or copy) is an error: the JPEG reader only warns and fills the missing rows
     * with grey, which would be matched as landscape.
     *
     * @throws IOException naming the problem: unreadable, or ending early
     */
    static BufferedImage readPixels(Path image) throws IOException {
        try (javax.imageio.stream.ImageInputStream stream = ImageIO.createImageInputStream(image.toFile())) {
            if (stream == null) {
                throw new IOException("cannot be opened");
            }
            java.util.Iterator<javax.imageio.ImageReader> readers = ImageIO.getImageReaders(stream);
            if (!readers.hasNext()) {
                return null;
            }
            javax.imageio.ImageReader reader = readers.next();
            List<String> warnings = new ArrayList<>();
            try {
                reader.setInput(stream, true, true);
                // The size from the header, before the pixels are decoded (a small file may declare gigapixels).
                int w = reader.getWidth(0), h = reader.getHeight(0);
                if (w > dempano.panorama.ViewLayout.MAX_VIEW_PX || h > dempano.panorama.ViewLayout.MAX_VIEW_PX) {
                    throw new TooLarge(w + "×" + h + " pixels: at most " + dempano.panorama.ViewLayout.MAX_VIEW_PX
                            + " on a side (the render of its view could not be made); scale it down");
                }
                reader.addIIOReadWarningListener((source, warning) -> warnings.add(warning));
                java.util.Iterator<javax.imageio.ImageTypeSpecifier> types = reader.getImageTypes(0);
                javax.imageio.ImageTypeSpecifier raw = types.hasNext() ? types.next() : null; // (getRawImageType: null for CMYK)
                boolean cmyk = raw != null && raw.getNumBands() == 4
                        && raw.getColorModel().getColorSpace().getType() == java.awt.color.ColorSpace.TYPE_CMYK;
                // A CMYK JPEG's samples as stored (read() hands them over inverted, in a colour space that washes them out).
                java.awt.image.Raster cmykSamples = cmyk ? reader.readRaster(0, null) : null;
                BufferedImage img = cmyk ? null : reader.read(0, reader.getDefaultReadParam());
                for (String warning : warnings) {
                    if (warning.toLowerCase(java.util.Locale.ROOT).contains("premature end")) {
                        throw new IOException("the file ends before the image does: " + warning);
                    }
                }
                if (cmyk) {
                    return cmykToRgb(cmykSamples, adobeMarker(reader));
                }
                return eightBit(img);
            } finally {
                reader.dispose();
            }
        }
    }

    /**
     * Floating-point pixels (a 32-bit float TIFF) as 8-bit RGB: Java's colour model takes them as 0…1 and fails on
     * larger values (0…255 floats threw deep in the overlay). Scaled by their largest value: 0…1 stays 0…1, anything
     * larger is taken as 0…max. Other images are returned as they are.
     */
    static BufferedImage eightBit(BufferedImage img) {
        int type = img.getRaster().getDataBuffer().getDataType();
        if (type != java.awt.image.DataBuffer.TYPE_FLOAT && type != java.awt.image.DataBuffer.TYPE_DOUBLE) {
            return img;
        }
        java.awt.image.Raster raster = img.getRaster();
        int w = img.getWidth(), h = img.getHeight(), bands = raster.getNumBands();
        int colourBands = bands >= 3 ? 3 : 1;
        double max = 0;
        double[] row = new double[w * bands];
        for (int y = 0; y < h; y++) {
            raster.getPixels(0, y, w, 1, row);
            for (int x = 0; x < w; x++) {
                for (int b = 0; b < colourBands; b++) {
                    double v = row[x * bands + b];
                    if (v > max) { // (NaN is not)
                        max = v;
                    }
                }
            }
        }
        double scale = 255 / (max <= 1 ? 1 : max);
        BufferedImage out = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        int[] c = new int[3];
        for (int y = 0; y < h; y++) {
            raster.getPixels(0, y, w, 1, row);
            for (int x = 0; x < w; x++) {
                for (int b = 0; b < 3; b++) {
                    double v = row[x * bands + (colourBands == 3 ? b : 0)] * scale;
                    c[b] = v >= 0 ? (int) Math.min(255, Math.round(v)) : 0; // NaN and negatives black
                }
                out.setRGB(x, y, c[0] << 16 | c[1] << 8 | c[2]);
            }
        }
        return out;
    }

    /**
     * A CMYK JPEG's pixels as RGB. The JDK decodes them with a colour space that washes them out (red 200,40,40 came
     * out 229,110,110), its samples inverted. Naive conversion, R = (1 − C)(1 − K) and so on, as without a colour profile: the skyline
     * needs the sky's hue and brightness, not print colours. A file with an Adobe APP14 marker (Photoshop's, and most
     * CMYK JPEGs) stores the inks inverted, as libjpeg and the other readers take them.
     *
     * @param raster        the 4 bands as stored in the file (8 bits; the reader's readRaster)
     * @param adobeInverted  whether the file has an Adobe APP14 marker
     */
    static BufferedImage cmykToRgb(java.awt.image.Raster raster, boolean adobeInverted) {
        int w = raster.getWidth(), h = raster.getHeight();
        int[] row = new int[w * 4];
        BufferedImage out = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < h; y++) {
            raster.getPixels(0, y, w, 1, row);
            for (int x = 0; x < w; x++) {
                int rgb = 0;
                int k = adobeInverted ? row[4 * x + 3] : 255 - row[4 * x + 3]; // 255 − K: the light left after black
                for (int b = 0; b < 3; b++) {
                    int ink = adobeInverted ? row[4 * x + b] : 255 - row[4 * x + b];
                    rgb = rgb << 8 | (ink * k + 127) / 255;
                }
                out.setRGB(x, y, rgb);
            }
        }
        return out;
    }

    /** Whether the image's JPEG metadata has an Adobe APP14 marker; false where it cannot be read. */
    private static boolean adobeMarker(javax.imageio.ImageReader reader) {
        try {
            javax.imageio.metadata.IIOMetadata m = reader.getImageMetadata(0);
            if (m == null || !java.util.Arrays.asList(m.getMetadataFormatNames()).contains("javax_imageio_jpeg_image_1.0")) {
                return false;
            }
            org.w3c.dom.Node tree = m.getAsTree("javax_imageio_jpeg_image_1.0");
            return tree instanceof org.w3c.dom.Element e && e.getElementsByTagName("app14Adobe").getLength() > 0;
        } catch (IOException | RuntimeException e) {
            return false;
        }
    }

    private static PhotoCamera resolve(PhotoMetadata meta, PhotoOverrides o) {
        return resolve(meta, o, Double.NaN, java.util.Set.of());
    }

    /** {@link PhotoMetadata#resolve(PhotoOverrides, double, java.util.Set)}, its errors as bad arguments. */
    private static PhotoCamera resolve(PhotoMetadata meta, PhotoOverrides o, double demGroundMetres,
                                       java.util.Set<String> estimatedFlags) {
        try {
            return meta.resolve(o, demGroundMetres, estimatedFlags);
        } catch (PhotoMetadataException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
    }

    /**
     * The DEM's surface at the camera's position where its altitude would be the EXIF GPSAltitude (no altitude or
     * offset flag), so that a GPS altitude below it is not used ({@link PhotoMetadata#resolve(PhotoOverrides, double)};
     * the tiles read are the ones the render loads); NaN elsewhere (nothing read).
     */
    private static double gpsGround(PanoramaRenderer renderer, PanoramaRequest settings, PhotoMetadata meta,
                                    PhotoOverrides o, PhotoCamera camera) {
        boolean gpsAltitude = Double.isNaN(o.altitudeMetres()) && Double.isNaN(o.offsetMetres())
                && !Double.isNaN(meta.gpsAltitudeMetres());
        return gpsAltitude ? renderer.groundElevationMetres(atCamera(settings, camera.pose().latDeg(), camera.pose().lonDeg()))
                : Double.NaN;
    }

    /**
     * The render settings at the camera's position: the viewpoint and everything that places the eye (offset,
     * altitude, eye height, summit snap, clear view) are a fresh request's, since the camera's pose places it.
     */
    static PanoramaRequest atCamera(PanoramaRequest d, double latDeg, double lonDeg) {
        return d.withStandpoint(PanoramaRequest.Standpoint.at(latDeg, lonDeg));
    }

    private static byte[] pngBytes(BufferedImage image) throws IOException {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        dempano.io.Png.write(image, b);
        return b.toByteArray();
    }

    /**
     * A field of view too wide (or too narrow) to render, with where it came from (the intrinsics' line of the provenance: an EXIF
     * FocalLengthIn35mmFilm of 1 or 2 mm is a broken tag or a fisheye) and the flag that sets it instead; any other
     * error as it is.
     */
    static IllegalArgumentException tooWideSaysWhy(IllegalArgumentException e, PhotoCamera camera) {
        boolean narrow = e.getMessage() != null && e.getMessage().startsWith(dempano.panorama.ViewLayout.TOO_NARROW);
        if (e.getMessage() == null || !(narrow || e.getMessage().startsWith(dempano.panorama.ViewLayout.TOO_WIDE))) {
            return e;
        }
        String source = camera.provenance().stream().filter(l -> l.startsWith("focal length ")).findFirst()
                .map(l -> l.replaceFirst(" \\(.*", "")).orElse(null);
        if (source != null && source.contains(PhotoOverrides.HFOV)) { // the flag itself: asking for it again says nothing
            return new IllegalArgumentException(e.getMessage() + "; the " + source + ": give a " + (narrow ? "wider " : "narrower ")
                    + PhotoOverrides.HFOV, e);
        }
        return new IllegalArgumentException(e.getMessage() + (source == null ? "" : "; the " + source) + ": give "
                + PhotoOverrides.HFOV + " (a pinhole camera's horizontal field of view) or a calibration", e);
    }
}
