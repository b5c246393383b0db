package dempano.camera;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import javax.imageio.ImageIO;

/**
 * Writes small JPEGs with EXIF (and optionally XMP) built byte by byte, for tests: the image from ImageIO,
 * an APP1 "Exif" segment holding a big-endian TIFF structure (IFD0 → Exif IFD and GPS IFD) as in the EXIF 2.32
 * standard, and an APP1 XMP packet, both inserted right after the SOI marker.
 */
public final class ExifJpeg {
    static final int BYTE = 1, ASCII = 2, SHORT = 3, LONG = 4, RATIONAL = 5;
    static final int TAG_EXIF_IFD = 0x8769, TAG_GPS_IFD = 0x8825;

    record Entry(int tag, int type, int count, byte[] value) {
    }

    final List<Entry> ifd0 = new ArrayList<>();
    final List<Entry> exif = new ArrayList<>();
    final List<Entry> gps = new ArrayList<>();
    String xmp;

    static Entry ascii(int tag, String s) {
        byte[] b = (s + "\0").getBytes(StandardCharsets.US_ASCII);
        return new Entry(tag, ASCII, b.length, b);
    }

    static Entry shortValue(int tag, int v) {
        return new Entry(tag, SHORT, 1, new byte[] {(byte) (v >> 8), (byte) v});
    }

    static Entry longValue(int tag, long v) {
        return new Entry(tag, LONG, 1, be32(v));
    }

    static Entry byteValue(int tag, int v) {
        return new Entry(tag, BYTE, 1, new byte[] {(byte) v});
    }

    /** Rationals given as numerator, denominator pairs. */
    static Entry rationals(int tag, long... numDen) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (long v : numDen) {
            out.writeBytes(be32(v));
        }
        return new Entry(tag, RATIONAL, numDen.length / 2, out.toByteArray());
    }

    static byte[] be32(long v) {
        return new byte[] {(byte) (v >> 24), (byte) (v >> 16), (byte) (v >> 8), (byte) v};
    }

    /** GPS latitude/longitude as degrees, minutes, seconds·10000 rationals. */
    static Entry dms(int tag, double deg) {
        double a = Math.abs(deg);
        long d = (long) a;
        long m = (long) ((a - d) * 60);
        long s = Math.round(((a - d) * 60 - m) * 60 * 10000);
        return rationals(tag, d, 1, m, 1, s, 10000);
    }

    public ExifJpeg orientation(int o) {
        ifd0.add(shortValue(0x0112, o));
        return this;
    }

    public ExifJpeg position(double lat, double lon) {
        gps.add(ascii(0x0001, lat >= 0 ? "N" : "S"));
        gps.add(dms(0x0002, lat));
        gps.add(ascii(0x0003, lon >= 0 ? "E" : "W"));
        gps.add(dms(0x0004, lon));
        return this;
    }

    /** GPSAltitudeRef 0 = above, 1 = below sea level; the altitude in centimetres. */
    public ExifJpeg altitude(int ref, long centimetres) {
        gps.add(byteValue(0x0005, ref));
        gps.add(rationals(0x0006, centimetres, 100));
        return this;
    }

    /** GPSAltitudeRef and GPSAltitude as the rational num/den as written (den 0: a broken writer's). */
    public ExifJpeg altitudeRational(int ref, long num, long den) {
        gps.add(byteValue(0x0005, ref));
        gps.add(rationals(0x0006, num, den));
        return this;
    }

    /** GPSImgDirectionRef and GPSImgDirection as the rational num/den as written. */
    public ExifJpeg directionRational(String ref, long num, long den) {
        gps.add(ascii(0x0010, ref));
        gps.add(rationals(0x0011, num, den));
        return this;
    }

    /** FocalLength as the rational num/den as written. */
    public ExifJpeg focalRational(long num, long den) {
        exif.add(rationals(0x920A, num, den));
        return this;
    }

    /** GPSImgDirectionRef (null = no ref tag) and GPSImgDirection in hundredths of a degree. */
    public ExifJpeg direction(String ref, long hundredths) {
        if (ref != null) {
            gps.add(ascii(0x0010, ref));
        }
        gps.add(rationals(0x0011, hundredths, 100));
        return this;
    }

    /** FocalLength in hundredths of a millimetre. */
    public ExifJpeg focal(long hundredthsMm) {
        exif.add(rationals(0x920A, hundredthsMm, 100));
        return this;
    }

    public ExifJpeg focal35(int mm) {
        exif.add(shortValue(0xA405, mm));
        return this;
    }

    /** FocalPlaneX/YResolution in pixels per unit, with FocalPlaneResolutionUnit (2 inch, 3 cm, 4 mm). */
    public ExifJpeg focalPlane(long xNum, long xDen, long yNum, long yDen, int unit) {
        exif.add(rationals(0xA20E, xNum, xDen));
        exif.add(rationals(0xA20F, yNum, yDen));
        exif.add(shortValue(0xA210, unit));
        return this;
    }

    public ExifJpeg xmp(String rdfDescriptionAttributes) {
        xmp = "<?xpacket begin=\"\ufeff\" id=\"W5M0MpCehiHzreSzNTczkc9d\"?>"
                + "<x:xmpmeta xmlns:x=\"adobe:ns:meta/\"><rdf:RDF xmlns:rdf=\"http://www.w3.org/1999/02/22-rdf-syntax-ns#\">"
                + "<rdf:Description rdf:about=\"\" xmlns:drone-dji=\"http://www.dji.com/drone-dji/1.0/\""
                + " xmlns:GPano=\"http://ns.google.com/photos/1.0/panorama/\" " + rdfDescriptionAttributes + "/>"
                + "</rdf:RDF></x:xmpmeta><?xpacket end=\"w\"?>";
        return this;
    }

    /** The TIFF structure: header, IFD0, Exif IFD, GPS IFD, each followed by its out-of-line values. */
    byte[] tiff() {
        List<Entry> zero = new ArrayList<>(ifd0);
        if (!exif.isEmpty()) {
            zero.add(longValue(TAG_EXIF_IFD, 0));
        }
        if (!gps.isEmpty()) {
            zero.add(longValue(TAG_GPS_IFD, 0));
        }
        int off0 = 8;
        int offExif = off0 + size(zero);
        int offGps = offExif + (exif.isEmpty() ? 0 : size(exif));
        zero.replaceAll(e -> e.tag() == TAG_EXIF_IFD ? longValue(TAG_EXIF_IFD, offExif)
                : e.tag() == TAG_GPS_IFD ? longValue(TAG_GPS_IFD, offGps) : e);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.writeBytes(new byte[] {'M', 'M', 0, 42, 0, 0, 0, 8});
        write(out, zero, off0);
        if (!exif.isEmpty()) {
            write(out, exif, offExif);
        }
        if (!gps.isEmpty()) {
            write(out, gps, offGps);
        }
        return out.toByteArray();
    }

    private static int size(List<Entry> ifd) {
        int n = 2 + 12 * ifd.size() + 4;
        for (Entry e : ifd) {
            if (e.value().length > 4) {
                n += (e.value().length + 1) & ~1;
            }
        }
        return n;
    }

    private static void write(ByteArrayOutputStream out, List<Entry> ifd, int offset) {
        List<Entry> sorted = new ArrayList<>(ifd);
        sorted.sort(Comparator.comparingInt(Entry::tag));
        out.writeBytes(new byte[] {(byte) (sorted.size() >> 8), (byte) sorted.size()});
        int data = offset + 2 + 12 * sorted.size() + 4;
        ByteArrayOutputStream extra = new ByteArrayOutputStream();
        for (Entry e : sorted) {
            out.writeBytes(new byte[] {(byte) (e.tag() >> 8), (byte) e.tag(), 0, (byte) e.type()});
            out.writeBytes(be32(e.count()));
            if (e.value().length <= 4) {
                byte[] v = new byte[4];
                System.arraycopy(e.value(), 0, v, 0, e.value().length);
                out.writeBytes(v);
            } else {
                out.writeBytes(be32(data + extra.size()));
                extra.writeBytes(e.value());
                if ((e.value().length & 1) == 1) {
                    extra.write(0);
                }
            }
        }
        out.writeBytes(be32(0)); // no next IFD
        out.writeBytes(extra.toByteArray());
    }

    /** A w × h JPEG (stored size) with this metadata. */
    public byte[] jpeg(int width, int height) {
        BufferedImage img = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        g.setColor(new Color(90, 140, 200));
        g.fillRect(0, 0, width, height);
        g.dispose();
        return jpeg(img);
    }

    /** A JPEG of this image (its RGB; stored as is) with this metadata. */
    public byte[] jpeg(BufferedImage image) {
        BufferedImage img = new BufferedImage(image.getWidth(), image.getHeight(), BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        g.drawImage(image, 0, 0, null);
        g.dispose();
        ByteArrayOutputStream plain = new ByteArrayOutputStream();
        try {
            ImageIO.write(img, "jpeg", plain);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        byte[] jpeg = plain.toByteArray();
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.write(0xFF);
        out.write(0xD8);
        if (!ifd0.isEmpty() || !exif.isEmpty() || !gps.isEmpty()) {
            ByteArrayOutputStream body = new ByteArrayOutputStream();
            body.writeBytes(new byte[] {'E', 'x', 'i', 'f', 0, 0});
            body.writeBytes(tiff());
            segment(out, body.toByteArray());
        }
        if (xmp != null) {
            ByteArrayOutputStream body = new ByteArrayOutputStream();
            body.writeBytes("http://ns.adobe.com/xap/1.0/\0".getBytes(StandardCharsets.US_ASCII));
            body.writeBytes(xmp.getBytes(StandardCharsets.UTF_8));
            segment(out, body.toByteArray());
        }
        out.write(jpeg, 2, jpeg.length - 2);
        return out.toByteArray();
    }

    private static void segment(ByteArrayOutputStream out, byte[] body) {
        int length = body.length + 2;
        out.writeBytes(new byte[] {(byte) 0xFF, (byte) 0xE1, (byte) (length >> 8), (byte) length});
        out.writeBytes(body);
    }

    public Path write(Path dir, String name, int width, int height) throws IOException {
        Path p = dir.resolve(name);
        Files.write(p, jpeg(width, height));
        return p;
    }

    /** Writes a JPEG of {@code image} (a rendered view, say) with this metadata. */
    public Path write(Path dir, String name, BufferedImage image) throws IOException {
        Path p = dir.resolve(name);
        Files.write(p, jpeg(image));
        return p;
    }
}
