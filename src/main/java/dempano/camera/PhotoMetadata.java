package dempano.camera;

import com.adobe.internal.xmp.XMPException;
import com.adobe.internal.xmp.XMPMeta;
import com.adobe.internal.xmp.properties.XMPProperty;
import com.drew.imaging.ImageMetadataReader;
import com.drew.imaging.ImageProcessingException;
import com.drew.lang.Rational;
import com.drew.metadata.Directory;
import com.drew.metadata.Metadata;
import com.drew.metadata.exif.ExifIFD0Directory;
import com.drew.metadata.exif.ExifSubIFDDirectory;
import com.drew.metadata.exif.GpsDirectory;
import com.drew.metadata.jpeg.JpegDirectory;
import com.drew.metadata.png.PngDirectory;
import com.drew.metadata.xmp.XmpDirectory;
import dempano.geo.Viewpoint;
import dempano.io.IoMessages;
import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * What a photograph's EXIF and XMP metadata say about its camera; NaN (or 0 for sizes and the orientation, null
 * for the XMP source) = not in the file.
 *
 * <p>Read with metadata-extractor: EXIF GPS (GPSLatitude/GPSLongitude with their N/S, E/W refs; GPSAltitude with
 * GPSAltitudeRef 1 = below sea level, made negative; GPSImgDirection with GPSImgDirectionRef), EXIF FocalLength,
 * FocalLengthIn35mmFilm (0 = unknown, as the EXIF standard says), FocalPlaneX/YResolution with its unit (for the
 * sensor size), Orientation; the image size from the JPEG frame header (or PNG header, else the EXIF pixel
 * dimensions); XMP {@code drone-dji:GimbalYawDegree/GimbalPitchDegree/GimbalRollDegree} (DJI; yaw from true north,
 * pitch positive up, roll positive right side down: this project's {@link CameraOrientation} convention) or else
 * {@code GPano:PoseHeadingDegrees/PosePitchDegrees/PoseRollDegrees}. The Pix4D {@code camera:Yaw/Pitch/Roll}
 * properties are not read: their zero and signs differ between the drones that write them.
 *
 * <p><b>Orientation.</b> Width and height are of the image as displayed: EXIF orientations 5–8 (a quarter turn,
 * possibly mirrored) swap the stored width and height. Every pixel coordinate of the camera model refers to the
 * displayed image, so pixels read with a library that ignores the tag (Java's ImageIO does) must be turned first.
 *
 * <p><b>GPS position 0°, 0°</b>, which cameras without a fix write, counts as absent.
 *
 * @param source      the file, for messages
 * @param widthPx     displayed width, pixels; 0 = unknown
 * @param heightPx    displayed height, pixels; 0 = unknown
 * @param orientation EXIF Orientation 1–8 as written; 0 = no tag (displayed as stored)
 * @param gps         the EXIF GPS tags: position, altitude, image direction ({@link Gps#NONE} when there are none)
 * @param lens        the EXIF lens tags ({@link Lens#NONE} when there are none)
 * @param xmp         the XMP attitude ({@link XmpAttitude#NONE} when there is none)
 * @param problems    what the reader could not make sense of (corrupt directories, unknown units), for messages;
 *                    empty when all went well
 */
public record PhotoMetadata(String source, int widthPx, int heightPx, int orientation, Gps gps, Lens lens,
                            XmpAttitude xmp, List<String> problems) {
    /**
     * The EXIF GPS tags.
     *
     * @param latDeg                  GPS latitude, degrees, north positive
     * @param lonDeg                  GPS longitude, degrees, east positive
     * @param altitudeMetres          GPS altitude, metres above sea level (negative below)
     * @param imageDirectionDeg       GPSImgDirection: the direction the camera pointed, degrees clockwise from
     *                                {@code imageDirectionReference}'s north
     * @param imageDirectionReference north of {@code imageDirectionDeg}
     */
    public record Gps(double latDeg, double lonDeg, double altitudeMetres, double imageDirectionDeg,
                      DirectionReference imageDirectionReference) {
        public Gps {
            if (imageDirectionReference == null) {
                imageDirectionReference = DirectionReference.NOT_GIVEN;
            }
        }

        public static final Gps NONE = new Gps(Double.NaN, Double.NaN, Double.NaN, Double.NaN, DirectionReference.NOT_GIVEN);
    }

    /**
     * The EXIF lens tags.
     *
     * @param focalLengthMm the lens's focal length, mm
     * @param focal35mmMm   35 mm-equivalent focal length, mm (whole millimetres in EXIF)
     * @param sensorWidthMm the sensor's long side, mm, from the focal-plane resolution (pixels per unit of the sensor
     *                      at the EXIF pixel size)
     */
    public record Lens(double focalLengthMm, double focal35mmMm, double sensorWidthMm) {
        public static final Lens NONE = new Lens(Double.NaN, Double.NaN, Double.NaN);
    }

    /**
     * The camera's attitude from XMP.
     *
     * @param yawDeg   yaw (heading), degrees clockwise from true north
     * @param pitchDeg pitch, degrees, positive up
     * @param rollDeg  roll, degrees, positive clockwise as the photographer sees it
     * @param source   which XMP properties gave it ("drone-dji:Gimbal…Degree" or "GPano:Pose…Degrees"); null = none
     */
    public record XmpAttitude(double yawDeg, double pitchDeg, double rollDeg, String source) {
        public static final XmpAttitude NONE = new XmpAttitude(Double.NaN, Double.NaN, Double.NaN, null);
    }

    public double latDeg() {
        return gps.latDeg();
    }

    public double lonDeg() {
        return gps.lonDeg();
    }

    public double gpsAltitudeMetres() {
        return gps.altitudeMetres();
    }

    public double imageDirectionDeg() {
        return gps.imageDirectionDeg();
    }

    public DirectionReference imageDirectionReference() {
        return gps.imageDirectionReference();
    }

    public double focalLengthMm() {
        return lens.focalLengthMm();
    }

    public double focal35mmMm() {
        return lens.focal35mmMm();
    }

    public double sensorWidthMm() {
        return lens.sensorWidthMm();
    }

    public double xmpYawDeg() {
        return xmp.yawDeg();
    }

    public double xmpPitchDeg() {
        return xmp.pitchDeg();
    }

    public double xmpRollDeg() {
        return xmp.rollDeg();
    }

    public String xmpAttitudeSource() {
        return xmp.source();
    }

    /** XMP namespace of DJI drones' {@code drone-dji:} properties. */
    public static final String DJI_NAMESPACE = "http://www.dji.com/drone-dji/1.0/";
    /** XMP namespace of Google's photo-sphere {@code GPano:} properties. */
    public static final String GPANO_NAMESPACE = "http://ns.google.com/photos/1.0/panorama/";

    public PhotoMetadata {
        gps = gps == null ? Gps.NONE : gps;
        lens = lens == null ? Lens.NONE : lens;
        xmp = xmp == null ? XmpAttitude.NONE : xmp;
        problems = problems == null ? List.of() : List.copyOf(problems);
    }

    /**
     * Reads a photograph's metadata.
     *
     * @throws PhotoMetadataException naming the file when it is missing, unreadable, not an image format
     *                                metadata-extractor knows, or too corrupt to give the image size
     */
    public static PhotoMetadata read(Path file) {
        String name = file.toString();
        if (Files.isDirectory(file)) {
            throw new PhotoMetadataException(name + ": is a folder, not a photograph");
        }
        if (Files.exists(file) && !Files.isRegularFile(file)) { // a named pipe would be waited on for ever
            throw new PhotoMetadataException(name + ": is not a regular file (a pipe or a device), not a photograph");
        }
        Metadata metadata;
        try (InputStream in = new BufferedInputStream(Files.newInputStream(file))) {
            metadata = ImageMetadataReader.readMetadata(in, Files.size(file));
        } catch (ImageProcessingException e) {
            throw new PhotoMetadataException(name + ": not a photograph whose metadata can be read ("
                    + plain(e.getMessage()) + ")", e);
        } catch (IOException e) {
            if (e instanceof java.io.EOFException || e instanceof com.drew.lang.BufferBoundsException
                    || String.valueOf(e.getMessage()).startsWith("Unable to skip")) { // the reader ran past the end
                throw new PhotoMetadataException(name + ": corrupt photograph (the file ends before its data do:"
                        + " truncated?)", e);
            }
            throw new PhotoMetadataException(name + ": cannot read the photograph: " + IoMessages.reason(e), e);
        } catch (RuntimeException e) {
            // metadata-extractor may fail on malformed input with unchecked exceptions.
            throw new PhotoMetadataException(name + ": corrupt photograph (" + plain(e.getMessage()) + ")", e);
        }
        PhotoMetadata m = of(metadata, name);
        if (m.widthPx() == 0) {
            throw new PhotoMetadataException(name + ": corrupt or unsupported photograph: no image size found"
                    + (m.problems().isEmpty() ? "" : " (" + String.join("; ", m.problems()) + ")"));
        }
        return m;
    }

    private static String plain(String message) {
        return message == null || message.isBlank() ? "unknown format" : message;
    }

    /** Longest plausible 35 mm-equivalent focal length, mm (bridge cameras reach 3000). */
    static final double MAX_FOCAL35_MM = 5000;
    /** A FocalLength beyond this, millimetres, is taken as garbage (the longest camera lenses are about 5 m). */
    static final double MAX_FOCAL_MM = 5000;
    /** A sensor's long side beyond this, millimetres, is taken as garbage (a 10 × 8 inch plate is 254 mm). */
    static final double MAX_SENSOR_MM = 300;
    /** A GPSAltitude beyond ±this, metres, is taken as garbage (4294967295 stands for "unknown" in some writers). */
    static final double MAX_GPS_ALTITUDE_METRES = 100_000;

    /** Where a format keeps an image's size: the directory and its width and height tags. */
    private record SizeTags(Class<? extends Directory> directory, int widthTag, int heightTag) {
    }

    /**
     * Where the stored size is read, first found first: the JPEG and PNG headers; other formats' headers (GIF, BMP,
     * WebP): the size their pixels will have, before the EXIF sub-IFD's (a resized file often keeps the camera's
     * there: a WebP was rendered at it); a TIFF's first image last (in a raw file that is often a small preview, the
     * EXIF sub-IFD the sensor's image).
     */
    private static final List<SizeTags> SIZE_TAGS = List.of(
            new SizeTags(JpegDirectory.class, JpegDirectory.TAG_IMAGE_WIDTH, JpegDirectory.TAG_IMAGE_HEIGHT),
            new SizeTags(PngDirectory.class, PngDirectory.TAG_IMAGE_WIDTH, PngDirectory.TAG_IMAGE_HEIGHT),
            new SizeTags(com.drew.metadata.gif.GifHeaderDirectory.class, com.drew.metadata.gif.GifHeaderDirectory.TAG_IMAGE_WIDTH,
                    com.drew.metadata.gif.GifHeaderDirectory.TAG_IMAGE_HEIGHT),
            new SizeTags(com.drew.metadata.bmp.BmpHeaderDirectory.class, com.drew.metadata.bmp.BmpHeaderDirectory.TAG_IMAGE_WIDTH,
                    com.drew.metadata.bmp.BmpHeaderDirectory.TAG_IMAGE_HEIGHT),
            new SizeTags(com.drew.metadata.webp.WebpDirectory.class, com.drew.metadata.webp.WebpDirectory.TAG_IMAGE_WIDTH,
                    com.drew.metadata.webp.WebpDirectory.TAG_IMAGE_HEIGHT),
            new SizeTags(ExifSubIFDDirectory.class, ExifSubIFDDirectory.TAG_EXIF_IMAGE_WIDTH,
                    ExifSubIFDDirectory.TAG_EXIF_IMAGE_HEIGHT),
            new SizeTags(ExifIFD0Directory.class, ExifIFD0Directory.TAG_IMAGE_WIDTH, ExifIFD0Directory.TAG_IMAGE_HEIGHT));

    /** The stored width and height of {@link #SIZE_TAGS}' first place that has both; {0, 0} if none. */
    private static int[] storedSize(Metadata metadata) {
        for (SizeTags t : SIZE_TAGS) {
            Directory d = metadata.getFirstDirectoryOfType(t.directory());
            if (d != null) {
                Integer width = d.getInteger(t.widthTag()), height = d.getInteger(t.heightTag());
                if (width != null && height != null) {
                    return new int[] {width, height};
                }
            }
        }
        return new int[] {0, 0};
    }

    /** The values in already-read metadata; {@code source} names the file in messages. */
    public static PhotoMetadata of(Metadata metadata, String source) {
        List<String> problems = new ArrayList<>();
        for (Directory d : metadata.getDirectories()) {
            for (String error : d.getErrors()) {
                problems.add(d.getName() + ": " + error);
            }
        }
        int[] size = storedSize(metadata);
        int storedWidth = size[0], storedHeight = size[1];
        ExifSubIFDDirectory exif = metadata.getFirstDirectoryOfType(ExifSubIFDDirectory.class);
        if (storedWidth < 0 || storedHeight < 0) {
            storedWidth = storedHeight = 0;
        }

        int orientation = 0;
        ExifIFD0Directory ifd0 = metadata.getFirstDirectoryOfType(ExifIFD0Directory.class);
        if (ifd0 != null && ifd0.getInteger(ExifIFD0Directory.TAG_ORIENTATION) != null) {
            orientation = ifd0.getInteger(ExifIFD0Directory.TAG_ORIENTATION);
            if (orientation < 1 || orientation > 8) {
                problems.add("EXIF Orientation " + orientation + " is not 1–8: taken as 1 (displayed as stored)");
                orientation = 0;
            }
        }
        boolean quarterTurn = orientation >= 5;
        int width = quarterTurn ? storedHeight : storedWidth;
        int height = quarterTurn ? storedWidth : storedHeight;

        double lat = Double.NaN, lon = Double.NaN, alt = Double.NaN, dir = Double.NaN;
        DirectionReference dirRef = DirectionReference.NOT_GIVEN;
        GpsDirectory gps = metadata.getFirstDirectoryOfType(GpsDirectory.class);
        if (gps != null) {
            // Read here, not by GpsDirectory.getGeoLocation: it takes 0/0 for 0 and 99 minutes for 1.65°.
            double la = degrees(gps.getRationalArray(GpsDirectory.TAG_LATITUDE), gps.getString(GpsDirectory.TAG_LATITUDE_REF),
                    "GPSLatitude", 'N', 'S', 90, problems);
            double lo = degrees(gps.getRationalArray(GpsDirectory.TAG_LONGITUDE), gps.getString(GpsDirectory.TAG_LONGITUDE_REF),
                    "GPSLongitude", 'E', 'W', 180, problems);
            if (Double.isFinite(la) && Double.isFinite(lo) && !(la == 0 && lo == 0)) { // 0, 0: a placeholder
                lat = la;
                lon = lo;
            }
            alt = value(gps.getRational(GpsDirectory.TAG_ALTITUDE), "GPSAltitude", problems);
            Integer altRef = gps.getInteger(GpsDirectory.TAG_ALTITUDE_REF);
            if (altRef != null && altRef == 1) {
                alt = -alt;
            } else if (altRef != null && altRef != 0) {
                problems.add("GPSAltitudeRef " + altRef + " is neither 0 (above sea level) nor 1 (below): taken as above");
            }
            if (Math.abs(alt) > MAX_GPS_ALTITUDE_METRES) { // 4294967295: "unknown" in some writers
                problems.add(String.format(Locale.ROOT, "GPSAltitude %.0f m is beyond %.0f km: not used", alt,
                        MAX_GPS_ALTITUDE_METRES / 1000));
                alt = Double.NaN;
            }
            dir = value(gps.getRational(GpsDirectory.TAG_IMG_DIRECTION), "GPSImgDirection", problems);
            if (!(dir >= 0 && dir <= 360) && !Double.isNaN(dir)) { // 0 ≤ d < 360 by the standard
                problems.add("GPSImgDirection " + shortest(dir) + "° is outside 0–360°: not used");
                dir = Double.NaN;
            }
            String ref = gps.getString(GpsDirectory.TAG_IMG_DIRECTION_REF);
            if (ref != null && ref.trim().equalsIgnoreCase("T")) {
                dirRef = DirectionReference.TRUE;
            } else if (ref != null && ref.trim().equalsIgnoreCase("M")) {
                dirRef = DirectionReference.MAGNETIC;
            } else if (ref != null) {
                problems.add("GPSImgDirectionRef \"" + ref.trim() + "\" is neither T nor M");
            }
        }

        double focal = Double.NaN, focal35 = Double.NaN, sensorWidth = Double.NaN;
        if (exif != null) {
            focal = value(exif.getRational(ExifSubIFDDirectory.TAG_FOCAL_LENGTH), "FocalLength", problems);
            if (focal <= 0) {
                problems.add("FocalLength " + shortest(focal) + " mm is not positive: not used");
                focal = Double.NaN;
            }
            if (focal > MAX_FOCAL_MM) {
                problems.add("FocalLength " + shortest(focal) + " mm is beyond any lens (" + shortest(MAX_FOCAL_MM) + " mm): not used");
                focal = Double.NaN;
            }
            Integer f35 = exif.getInteger(ExifSubIFDDirectory.TAG_35MM_FILM_EQUIV_FOCAL_LENGTH);
            focal35 = f35 == null ? Double.NaN : positive(f35);
            if (f35 != null && f35 <= 0) {
                problems.add("FocalLengthIn35mmFilm " + f35 + (f35 == 0 ? " (unknown, by the standard)" : " mm") + ": not used");
            }
            if (focal35 > MAX_FOCAL35_MM) { // 65535: "unknown" in some cameras' EXIF; a 0.03° view otherwise
                problems.add("FocalLengthIn35mmFilm " + f35 + " mm is beyond any lens (" + (int) MAX_FOCAL35_MM + " mm): not used");
                focal35 = Double.NaN;
            }
            sensorWidth = sensorLongSideMm(exif, storedWidth, storedHeight, problems);
        }

        double yaw = Double.NaN, pitch = Double.NaN, roll = Double.NaN;
        String attitudeSource = null;
        for (XmpDirectory xmp : metadata.getDirectoriesOfType(XmpDirectory.class)) {
            XMPMeta meta = xmp.getXMPMeta();
            if (meta == null || attitudeSource != null) {
                continue;
            }
            double y = xmpDouble(meta, DJI_NAMESPACE, "GimbalYawDegree", PhotoOverrides.HEADING_LIMIT_DEG, problems);
            double p = xmpDouble(meta, DJI_NAMESPACE, "GimbalPitchDegree", PhotoOverrides.PITCH_LIMIT_DEG, problems);
            double r = xmpDouble(meta, DJI_NAMESPACE, "GimbalRollDegree", PhotoOverrides.ROLL_LIMIT_DEG, problems);
            String src = "drone-dji:Gimbal{Yaw,Pitch,Roll}Degree";
            if (Double.isNaN(y) && Double.isNaN(p) && Double.isNaN(r)) {
                y = xmpDouble(meta, GPANO_NAMESPACE, "PoseHeadingDegrees", PhotoOverrides.HEADING_LIMIT_DEG, problems);
                p = xmpDouble(meta, GPANO_NAMESPACE, "PosePitchDegrees", PhotoOverrides.PITCH_LIMIT_DEG, problems);
                r = xmpDouble(meta, GPANO_NAMESPACE, "PoseRollDegrees", PhotoOverrides.ROLL_LIMIT_DEG, problems);
                src = "GPano:Pose{Heading,Pitch,Roll}Degrees";
            }
            if (!Double.isNaN(y) || !Double.isNaN(p) || !Double.isNaN(r)) {
                yaw = y;
                pitch = p;
                roll = r;
                attitudeSource = src;
            }
        }
        return new PhotoMetadata(source, width, height, orientation, new Gps(lat, lon, alt, dir, dirRef),
                new Lens(focal, focal35, sensorWidth), new XmpAttitude(yaw, pitch, roll, attitudeSource), problems);
    }

    /**
     * An EXIF GPS latitude or longitude from its three rationals (degrees, minutes, seconds) and its reference;
     * NaN, with a problem said, where it is absent in part, has a zero denominator, minutes or seconds outside
     * [0, 60), or exceeds {@code maxDeg}; NaN silently where the tag is absent.
     */
    static double degrees(Rational[] dms, String ref, String tag, char positive, char negative, double maxDeg,
                          List<String> problems) {
        if (dms == null && ref == null) {
            return Double.NaN;
        }
        if (dms == null || dms.length != 3) {
            problems.add(tag + " is not three numbers (degrees, minutes, seconds): not used");
            return Double.NaN;
        }
        double[] v = new double[3];
        for (int i = 0; i < 3; i++) {
            if (dms[i] == null || dms[i].getDenominator() == 0) {
                problems.add(tag + " " + java.util.Arrays.toString(dms) + " has a zero denominator: not used");
                return Double.NaN;
            }
            v[i] = dms[i].doubleValue();
        }
        if (!(v[0] >= 0 && v[1] >= 0 && v[1] < 60 && v[2] >= 0 && v[2] < 60)) {
            problems.add(tag + " " + java.util.Arrays.toString(dms) + " is not degrees, minutes < 60 and seconds < 60:"
                    + " not used");
            return Double.NaN;
        }
        double deg = v[0] + v[1] / 60 + v[2] / 3600;
        String r = ref == null ? "" : ref.trim().toUpperCase(Locale.ROOT);
        if (!(r.equals(String.valueOf(positive)) || r.equals(String.valueOf(negative)))) {
            problems.add(tag + "Ref \"" + (ref == null ? "" : ref.trim()) + "\" is neither " + positive + " nor " + negative
                    + ": the position is not used");
            return Double.NaN;
        }
        if (!(deg <= maxDeg)) {
            problems.add(tag + " " + deg + "° is beyond " + (int) maxDeg + "°: not used");
            return Double.NaN;
        }
        return r.equals(String.valueOf(negative)) ? -deg : deg;
    }

    private static double value(Rational r) {
        if (r == null || r.getDenominator() == 0) {
            return Double.NaN;
        }
        double v = r.doubleValue();
        return Double.isFinite(v) ? v : Double.NaN;
    }

    /** A rational tag's value; NaN where absent, and where its denominator is 0 also a problem naming the tag. */
    private static double value(Rational r, String tag, List<String> problems) {
        if (r != null && r.getDenominator() == 0) {
            problems.add(tag + " " + r.getNumerator() + "/0 has a zero denominator: not used");
        }
        return value(r);
    }

    private static double positive(double v) {
        return v > 0 ? v : Double.NaN;
    }

    /** The sensor's long side from FocalPlaneX/YResolution (pixels per unit at the EXIF pixel size), mm; NaN if absent. */
    private static double sensorLongSideMm(ExifSubIFDDirectory exif, int storedWidth, int storedHeight,
                                           List<String> problems) {
        double xRes = positive(value(exif.getRational(ExifSubIFDDirectory.TAG_FOCAL_PLANE_X_RESOLUTION)));
        double yRes = positive(value(exif.getRational(ExifSubIFDDirectory.TAG_FOCAL_PLANE_Y_RESOLUTION)));
        if (Double.isNaN(xRes) || Double.isNaN(yRes)) {
            return Double.NaN;
        }
        Integer unit = exif.getInteger(ExifSubIFDDirectory.TAG_FOCAL_PLANE_RESOLUTION_UNIT);
        double unitMm;
        int u = unit == null ? 2 : unit; // EXIF default: inches
        switch (u) {
            case 2 -> unitMm = 25.4;
            case 3 -> unitMm = 10;
            case 4 -> unitMm = 1;
            case 5 -> unitMm = 0.001;
            default -> {
                problems.add("FocalPlaneResolutionUnit " + u + " is not inch, cm, mm or µm: sensor size not used");
                return Double.NaN;
            }
        }
        Integer w = exif.getInteger(ExifSubIFDDirectory.TAG_EXIF_IMAGE_WIDTH);
        Integer h = exif.getInteger(ExifSubIFDDirectory.TAG_EXIF_IMAGE_HEIGHT);
        int pw = w != null && w > 0 ? w : storedWidth, ph = h != null && h > 0 ? h : storedHeight;
        if (pw <= 0 || ph <= 0) {
            return Double.NaN;
        }
        double mm = Math.max(pw / xRes, ph / yRes) * unitMm;
        if (mm > MAX_SENSOR_MM) {
            problems.add("FocalPlaneX/YResolution give a sensor " + shortest(mm) + " mm wide, beyond any camera's ("
                    + shortest(MAX_SENSOR_MM) + " mm): sensor size not used");
            return Double.NaN;
        }
        return mm;
    }

    /** A value for the problems' words (400, 42949672.95). */
    private static String shortest(double v) {
        return dempano.util.Decimals.shortest(v, 10);
    }

    /** An XMP angle, degrees: NaN where absent, or (with a problem said) not a plain decimal or beyond ±{@code limit}. */
    private static double xmpDouble(XMPMeta meta, String namespace, String property, double limit, List<String> problems) {
        try {
            XMPProperty p = meta.getProperty(namespace, property);
            if (p == null || p.getValue() == null) {
                return Double.NaN;
            }
            String text = p.getValue().trim();
            if (dempano.util.Decimals.isPlain(text)) {
                double v = Double.parseDouble(text);
                if (Math.abs(v) <= limit) {
                    return v;
                }
                problems.add("XMP " + property + " \"" + quoted(text) + "\" is beyond ±" + (int) limit + "°: not used");
                return Double.NaN;
            }
            problems.add("XMP " + property + " \"" + quoted(text) + "\" is not a number");
            return Double.NaN;
        } catch (XMPException e) {
            return Double.NaN; // the namespace is not in this file
        }
    }

    /**
     * A value from the file for a one-line message: control characters (line breaks) as '?', and at most 40
     * characters (a 50 KB value was echoed whole to stderr and P.json).
     */
    static String quoted(String text) {
        String clean = text.codePoints().map(c -> Character.isISOControl(c) ? '?' : c)
                .collect(StringBuilder::new, StringBuilder::appendCodePoint, StringBuilder::append).toString();
        return clean.length() <= 40 ? clean : clean.substring(0, 40) + "… (" + clean.length() + " characters)";
    }

    /**
     * This metadata with the displayed size of the pixels as decoded, where the file's tags said another (a resized
     * TIFF keeps the camera's ExifImageWidth/Height; which of a file's sizes its decoder takes is the decoder's):
     * the pixels are what is rendered and matched, and a problem says which size the tags gave.
     *
     * @param displayedWidthPx  the decoded image's width, turned by the EXIF orientation, pixels
     * @param displayedHeightPx the same for its height
     */
    public PhotoMetadata withDecodedSize(int displayedWidthPx, int displayedHeightPx) {
        if (displayedWidthPx == widthPx && displayedHeightPx == heightPx) {
            return this;
        }
        List<String> said = new ArrayList<>(problems);
        if (widthPx > 0 && heightPx > 0) {
            said.add("the file's tags give " + widthPx + " × " + heightPx + " px (as displayed) but its pixels are "
                    + displayedWidthPx + " × " + displayedHeightPx + ": the pixels' size is used");
        }
        return new PhotoMetadata(source, displayedWidthPx, displayedHeightPx, orientation, gps, lens, xmp, List.copyOf(said));
    }

    /** Whether the displayed image is the stored one turned a quarter (EXIF orientation 5–8). */
    public boolean quarterTurn() {
        return orientation >= 5;
    }

    /**
     * What is missing to make the photo's camera, each with the flag that supplies it; empty when
     * {@link #resolve} will succeed.
     */
    public List<String> missing(PhotoOverrides overrides) {
        List<String> missing = new ArrayList<>();
        build(overrides, java.util.Set.of(), missing, new ArrayList<>(), Double.NaN);
        return missing;
    }

    /**
     * The photo's camera: the overrides where given, else the metadata, else the documented defaults. Order of
     * precedence:
     * <ul>
     *   <li>position: {@value PhotoOverrides#LAT}/{@value PhotoOverrides#LON}, else EXIF GPS;</li>
     *   <li>altitude: {@value PhotoOverrides#ALTITUDE} (standing altitude, camera
     *       {@value PhotoOverrides#CAMERA_HEIGHT} above it, default {@link Viewpoint#DEFAULT_EYE_HEIGHT_METRES}),
     *       else {@value PhotoOverrides#OFFSET} (on the DEM), else EXIF GPSAltitude (the camera's own altitude:
     *       camera height default 0), else on the DEM with offset 0;</li>
     *   <li>heading: {@value PhotoOverrides#HEADING}, else GPSImgDirection (true north as written; magnetic or
     *       without a reference only with {@value PhotoOverrides#DECLINATION}: true = magnetic + declination;
     *       never silently read as true), else the XMP yaw;</li>
     *   <li>pitch and roll: the flags, else the XMP attitude; never assumed level;</li>
     *   <li>intrinsics: a calibration, else {@value PhotoOverrides#HFOV}, else {@value PhotoOverrides#FOCAL35}, else
     *       {@value PhotoOverrides#FOCAL}/{@value PhotoOverrides#SENSOR_WIDTH} (each flag completed by EXIF), else
     *       EXIF FocalLengthIn35mmFilm, else EXIF FocalLength with the sensor size from the focal-plane
     *       resolution; the overrides' distortion is applied to all but a calibration.</li>
     * </ul>
     *
     * @throws PhotoMetadataException naming the file and listing everything missing with its flag, or a value
     *                                out of range
     */
    public PhotoCamera resolve(PhotoOverrides overrides) {
        return resolve(overrides, Double.NaN);
    }

    /**
     * As {@link #resolve(PhotoOverrides)}, knowing the DEM's surface at the photo's position: an EXIF GPSAltitude that
     * puts the camera below it, or less than {@link Viewpoint#MIN_EYE_CLEARANCE_METRES} above it, is wrong (GPS altitudes are
     * often tens of metres off), so it is not used and the camera stands on the DEM (offset 0, the default camera
     * height), with a provenance line saying why. An altitude given by flag is the user's, and is not second-guessed
     * (a viewpoint below the surface is refused when rendered).
     *
     * @param demGroundMetres the DEM surface's height at the photo's position, metres; NaN: not known (no check)
     */
    public PhotoCamera resolve(PhotoOverrides overrides, double demGroundMetres) {
        return resolve(overrides, demGroundMetres, java.util.Set.of());
    }

    /** How a provenance line says that a value was estimated instead of given. */
    public static final String ESTIMATED = "estimated from the skyline";

    /**
     * As {@link #resolve(PhotoOverrides, double)}, where some of the overrides' values are not the user's but
     * estimates (the photo command's, from the skyline): their provenance lines say so ("heading 235.5° estimated
     * from the skyline", "standing on the DEM corrected by 12.5 m (estimated from the skyline)") instead of naming
     * flags nobody gave.
     *
     * @param estimatedFlags the flags ({@link PhotoOverrides#HEADING}, {@link PhotoOverrides#PITCH},
     *                       {@link PhotoOverrides#ROLL}, {@link PhotoOverrides#HFOV}, {@link PhotoOverrides#OFFSET},
     *                       {@link PhotoOverrides#ALTITUDE}: the EXIF GPS altitude corrected by an estimated offset,
     *                       {@link PhotoOverrides#CAMERA_HEIGHT}: the camera's own height that such an altitude keeps)
     *                       whose values in {@code overrides} are estimates; others are ignored
     */
    public PhotoCamera resolve(PhotoOverrides overrides, double demGroundMetres, java.util.Set<String> estimatedFlags) {
        List<String> missing = new ArrayList<>();
        List<String> provenance = new ArrayList<>();
        PhotoCamera camera = build(overrides, java.util.Set.copyOf(estimatedFlags), missing, provenance, demGroundMetres);
        if (!missing.isEmpty()) {
            throw new PhotoMetadataException(source + ": the photo's camera is not fully known:\n  - "
                    + String.join("\n  - ", missing));
        }
        return camera;
    }

    private static boolean given(double v) {
        return !Double.isNaN(v);
    }

    /** A number for messages: 9 significant digits, no trailing zeros. */
    public static String num(double v) {
        if (!Double.isFinite(v)) {
            return Double.toString(v);
        }
        java.math.BigDecimal d = new java.math.BigDecimal(String.format(Locale.ROOT, "%.9g", v)).stripTrailingZeros();
        // Plain digits where they are readable; 1.71887339E+304 rather than 305 digits.
        return Math.abs(v) < 1e12 && (v == 0 || Math.abs(v) >= 1e-6) ? d.toPlainString() : d.toString();
    }

    /** How far the camera at the GPS altitude (its own: height 0 unless a flag gives one) is below the ground; NaN: unknown. */
    private double gpsEyeBelowMetres(PhotoOverrides o, double demGroundMetres) {
        return demGroundMetres - gpsAltitudeMetres() - (given(o.cameraHeightMetres()) ? o.cameraHeightMetres() : 0);
    }

    /** Where a value given in the overrides came from: "from FLAG", or {@link #ESTIMATED}. */
    private static String from(String flag, java.util.Set<String> estimated) {
        return estimated.contains(flag) ? ESTIMATED : "from " + flag;
    }

    private PhotoCamera build(PhotoOverrides o, java.util.Set<String> estimated, List<String> missing,
                              List<String> provenance, double demGroundMetres) {
        for (String p : problems) {
            provenance.add("metadata problem: " + p);
        }
        // Position.
        double lat = given(o.latDeg()) ? o.latDeg() : latDeg();
        double lon = given(o.lonDeg()) ? o.lonDeg() : lonDeg();
        if (!given(lat) || !given(lon)) {
            String gpsProblem = problems.stream().filter(p -> p.startsWith("GPSLatitude") || p.startsWith("GPSLongitude"))
                    .findFirst().orElse(null);
            missing.add((gpsProblem == null ? "no GPS position in the EXIF" : "the EXIF GPS position is unusable ("
                    + gpsProblem + ")") + ": give " + PhotoOverrides.LAT + " and " + PhotoOverrides.LON);
        } else {
            provenance.add("position " + num(lat) + ", " + num(lon) + " from "
                    + (given(o.latDeg()) && given(o.lonDeg()) ? PhotoOverrides.LAT + "/" + PhotoOverrides.LON
                    : !given(o.latDeg()) && !given(o.lonDeg()) ? "EXIF GPSLatitude/GPSLongitude"
                    : "the flag given and the EXIF GPS position"));
        }
        // Altitude.
        double offset = 0, altitude = Double.NaN, defaultHeight = Viewpoint.DEFAULT_EYE_HEIGHT_METRES;
        if (given(o.altitudeMetres())) {
            altitude = o.altitudeMetres();
            provenance.add("standing altitude " + num(altitude) + " m " + (estimated.contains(PhotoOverrides.ALTITUDE)
                    ? "(the camera's altitude, the EXIF GPSAltitude corrected by the offset " + ESTIMATED + ")"
                    : "from " + PhotoOverrides.ALTITUDE));
        } else if (given(o.offsetMetres())) {
            offset = o.offsetMetres();
            provenance.add("standing on the DEM" + (offset == 0 ? "" : " corrected by " + num(offset) + " m")
                    + " (" + (estimated.contains(PhotoOverrides.OFFSET) ? ESTIMATED : PhotoOverrides.OFFSET) + ")");
        } else if (given(gpsAltitudeMetres()) && gpsEyeBelowMetres(o, demGroundMetres) > -Viewpoint.MIN_EYE_CLEARANCE_METRES) {
            double below = gpsEyeBelowMetres(o, demGroundMetres);
            provenance.add(String.format(Locale.ROOT, "camera altitude %s m from EXIF GPSAltitude not used: %s"
                    + " the DEM surface (%.1f m); standing on the DEM instead (%s 0; %s gives an altitude)",
                    num(gpsAltitudeMetres()), below > 0 ? String.format(Locale.ROOT, "%.1f m below", below)
                            : String.format(Locale.ROOT, "only %.2f m above", -below), demGroundMetres, PhotoOverrides.OFFSET,
                    PhotoOverrides.ALTITUDE));
        } else if (given(gpsAltitudeMetres())) {
            altitude = gpsAltitudeMetres();
            defaultHeight = 0;
            provenance.add("camera altitude " + num(altitude) + " m from EXIF GPSAltitude (GPS altitudes are often"
                    + " tens of metres off: " + PhotoOverrides.OFFSET + " 0 stands on the DEM instead)");
        } else {
            provenance.add("no altitude in the EXIF: standing on the DEM (" + PhotoOverrides.OFFSET + " 0)");
        }
        double cameraHeight = given(o.cameraHeightMetres()) ? o.cameraHeightMetres() : defaultHeight;
        provenance.add("camera " + num(cameraHeight) + " m above the standing altitude"
                + (!given(o.cameraHeightMetres()) ? " (default)" : estimated.contains(PhotoOverrides.CAMERA_HEIGHT)
                ? " (the altitude is the camera's)" : " (" + PhotoOverrides.CAMERA_HEIGHT + ")"));
        // Heading.
        double heading = Double.NaN;
        if (given(o.headingDeg())) {
            heading = o.headingDeg();
            provenance.add("heading " + num(heading) + "° " + from(PhotoOverrides.HEADING, estimated));
        } else if (given(imageDirectionDeg())) {
            String what = "the EXIF direction (GPSImgDirection " + num(imageDirectionDeg()) + "°)";
            switch (imageDirectionReference()) {
                case TRUE -> {
                    heading = imageDirectionDeg();
                    provenance.add("heading " + num(heading) + "° from EXIF GPSImgDirection (true north)"
                            + (given(o.declinationDeg()) ? "; " + PhotoOverrides.DECLINATION + " not used: the direction is true" : ""));
                }
                case MAGNETIC -> {
                    if (given(o.declinationDeg())) {
                        heading = imageDirectionDeg() + o.declinationDeg();
                        provenance.add("heading " + num(heading) + "° = EXIF GPSImgDirection " + num(imageDirectionDeg())
                                + "° magnetic + declination " + num(o.declinationDeg()) + "° (" + PhotoOverrides.DECLINATION + ")");
                    } else {
                        missing.add(what + " is magnetic (GPSImgDirectionRef M) and the declination is unknown: give "
                                + PhotoOverrides.DECLINATION + " (east positive; true = magnetic + declination) or "
                                + PhotoOverrides.HEADING);
                    }
                }
                case NOT_GIVEN -> {
                    if (given(o.declinationDeg())) {
                        heading = imageDirectionDeg() + o.declinationDeg();
                        provenance.add("heading " + num(heading) + "° = EXIF GPSImgDirection " + num(imageDirectionDeg())
                                + "° (no reference: read as magnetic) + declination " + num(o.declinationDeg()) + "°");
                    } else {
                        missing.add(what + " has no reference (GPSImgDirectionRef): give " + PhotoOverrides.DECLINATION
                                + " to read it as magnetic (0 reads it as true) or " + PhotoOverrides.HEADING);
                    }
                }
                default -> throw new IllegalStateException();
            }
        } else if (given(xmpYawDeg())) {
            heading = xmpYawDeg();
            provenance.add("heading " + num(heading) + "° from XMP " + xmpAttitudeSource() + " (true north)");
        } else {
            missing.add("no camera heading in the EXIF (GPSImgDirection) or XMP: give " + PhotoOverrides.HEADING
                    + " (degrees clockwise from true north)");
        }
        // Pitch and roll.
        double pitch = pick(o.pitchDeg(), xmpPitchDeg(), "pitch", PhotoOverrides.PITCH, "0 = level, positive up",
                estimated, missing, provenance);
        double roll = pick(o.rollDeg(), xmpRollDeg(), "roll", PhotoOverrides.ROLL,
                "0 = level horizon, positive = camera turned clockwise", estimated, missing, provenance);
        // Intrinsics.
        CameraIntrinsics intrinsics = intrinsics(o, estimated, missing, provenance);

        if (!missing.isEmpty()) {
            return null;
        }
        try {
            CameraOrientation orientation = new CameraOrientation(heading, pitch, roll);
            CameraPose pose = new CameraPose(lat, lon, offset, altitude, cameraHeight, orientation);
            return new PhotoCamera(intrinsics, pose, provenance);
        } catch (IllegalArgumentException e) {
            throw new PhotoMetadataException(source + ": " + e.getMessage(), e);
        }
    }

    private double pick(double flag, double xmp, String what, String flagName, String hint, java.util.Set<String> estimated,
                        List<String> missing, List<String> provenance) {
        if (given(flag)) {
            provenance.add(what + " " + num(flag) + "° " + from(flagName, estimated));
            return flag;
        }
        if (given(xmp)) {
            provenance.add(what + " " + num(xmp) + "° from XMP " + xmpAttitudeSource());
            return xmp;
        }
        missing.add("no camera " + what + " in the metadata: give " + flagName + " (" + hint + ")");
        return Double.NaN;
    }

    private CameraIntrinsics intrinsics(PhotoOverrides o, java.util.Set<String> estimated, List<String> missing,
                                        List<String> provenance) {
        String size = widthPx + " × " + heightPx + " px as displayed"
                + (quarterTurn() ? " (EXIF orientation " + orientation + ": the stored image turned a quarter)" : "");
        if (o.calibration() != null) {
            CameraIntrinsics c = o.calibration();
            if (c.widthPx() != widthPx || c.heightPx() != heightPx) {
                throw new PhotoMetadataException(source + ": the calibration is for " + c.widthPx() + " × "
                        + c.heightPx() + " px but the photo is " + size
                        + (quarterTurn() && c.widthPx() == heightPx && c.heightPx() == widthPx
                        ? ": a calibration of the stored frames must be turned (CameraIntrinsics.displayed("
                        + orientation + "))" : ""));
            }
            provenance.add("intrinsics from the given calibration" + (o.distortion() != null
                    ? " (its own distortion; the separate distortion is not used)" : ""));
            return c;
        }
        if (widthPx <= 0 || heightPx <= 0) {
            missing.add("the image size could not be read from the file");
            return null;
        }
        CameraIntrinsics c = null;
        double focal = given(o.focalLengthMm()) ? o.focalLengthMm() : focalLengthMm();
        double sensor = given(o.sensorWidthMm()) ? o.sensorWidthMm() : sensorWidthMm();
        boolean focalFlags = given(o.focalLengthMm()) || given(o.sensorWidthMm());
        try {
            if (given(o.horizontalFovDeg())) {
                c = CameraIntrinsics.fromHorizontalFov(widthPx, heightPx, o.horizontalFovDeg());
                provenance.add("focal length " + num(c.fxPx()) + " px from " + (estimated.contains(PhotoOverrides.HFOV)
                        ? "a horizontal field of view of " + num(o.horizontalFovDeg()) + "° " + ESTIMATED
                        : PhotoOverrides.HFOV + " " + num(o.horizontalFovDeg()) + "°"));
            } else if (given(o.focal35mmMm())) {
                c = CameraIntrinsics.fromFocal35mm(widthPx, heightPx, o.focal35mmMm());
                provenance.add("focal length " + num(c.fxPx()) + " px from " + PhotoOverrides.FOCAL35 + " "
                        + num(o.focal35mmMm()) + " mm (diagonal definition)");
            } else if (focalFlags && given(focal) && given(sensor)) {
                c = CameraIntrinsics.fromFocalLength(widthPx, heightPx, focal, sensor);
                provenance.add("focal length " + num(c.fxPx()) + " px from " + num(focal) + " mm ("
                        + (given(o.focalLengthMm()) ? PhotoOverrides.FOCAL : "EXIF FocalLength") + ") on a "
                        + num(sensor) + " mm sensor (" + (given(o.sensorWidthMm()) ? PhotoOverrides.SENSOR_WIDTH
                        : "EXIF FocalPlaneXResolution") + ")");
            } else if (focalFlags && given(focal)) {
                missing.add(PhotoOverrides.FOCAL + " needs " + PhotoOverrides.SENSOR_WIDTH
                        + " (the sensor's long side, mm), which the EXIF does not give; or give "
                        + PhotoOverrides.FOCAL35 + " or " + PhotoOverrides.HFOV);
            } else if (focalFlags) {
                missing.add(PhotoOverrides.SENSOR_WIDTH + " needs a focal length and the EXIF has none: give "
                        + PhotoOverrides.FOCAL);
            } else if (given(focal35mmMm())) {
                c = CameraIntrinsics.fromFocal35mm(widthPx, heightPx, focal35mmMm());
                provenance.add("focal length " + num(c.fxPx()) + " px from EXIF FocalLengthIn35mmFilm " + num(focal35mmMm())
                        + " mm (diagonal definition; whole millimetres, so uncertain by ±"
                        + String.format(Locale.ROOT, "%.1f", 50 / focal35mmMm()) + " %: " + PhotoOverrides.HFOV + " or a calibration is better)");
            } else if (given(focalLengthMm()) && given(sensorWidthMm())) {
                c = CameraIntrinsics.fromFocalLength(widthPx, heightPx, focalLengthMm(), sensorWidthMm());
                provenance.add("focal length " + num(c.fxPx()) + " px from EXIF FocalLength " + num(focalLengthMm())
                        + " mm on a " + num(sensorWidthMm()) + " mm sensor (EXIF FocalPlaneX/YResolution)");
            } else if (given(focalLengthMm())) {
                missing.add("the EXIF gives the focal length (" + num(focalLengthMm()) + " mm) but neither a 35 mm"
                        + " equivalent nor the sensor size: give " + PhotoOverrides.SENSOR_WIDTH
                        + " (the sensor's long side), " + PhotoOverrides.FOCAL35 + " or " + PhotoOverrides.HFOV);
            } else {
                missing.add("no focal length in the EXIF: give " + PhotoOverrides.FOCAL + " with "
                        + PhotoOverrides.SENSOR_WIDTH + ", " + PhotoOverrides.FOCAL35 + " or " + PhotoOverrides.HFOV);
            }
        } catch (IllegalArgumentException e) {
            throw new PhotoMetadataException(source + ": " + e.getMessage(), e);
        }
        if (c != null) {
            provenance.add("image " + size);
            if (o.distortion() != null) {
                c = c.withDistortion(o.distortion());
                provenance.add("lens distortion " + o.distortion());
            }
        }
        return c;
    }
}
