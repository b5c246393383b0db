package dempano.dem;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.zip.Deflater;

/**
 * Writes GeoTIFFs for tests from the TIFF 6.0 and GeoTIFF 1.1 specifications, independently of the
 * library dempano reads them with: int16/int32/float32 samples, no/LZW/Deflate compression,
 * horizontal (2) and floating-point (3) predictors, strips or tiles, either byte order, GeoKeys,
 * GDAL_NODATA and an optional overview image (as in a Cloud-Optimized GeoTIFF).
 */
final class GeoTiffTestFiles {
    enum SampleType {
        INT16(2, 2), INT32(4, 2), FLOAT32(4, 3);

        final int bytes, bits, sampleFormat;

        SampleType(int bytes, int sampleFormat) {
            this.bytes = bytes;
            this.bits = bytes * 8;
            this.sampleFormat = sampleFormat;
        }
    }

    /** TIFF compression codes. */
    static final int NONE = 1, LZW = 5, DEFLATE = 8;

    /**
     * What to write. Heights come from {@code value(row, col)}; NaN (float) or the nodata value make voids.
     *
     * @param tileSize 0 for strips (rowsPerStrip rows each), else square tiles of this size (multiple of 16)
     */
    record Spec(int width, int height, SampleType type, int compression, int predictor, int tileSize, int rowsPerStrip,
                ByteOrder order, double[] tiepointXY, double[] pixelScale, double[] transformation, int modelType,
                int rasterType, int epsg, int verticalCs, String nodata, boolean overview, int forcedCompressionCode) {
        Spec withCompression(int c, int p) {
            return new Spec(width, height, type, c, p, tileSize, rowsPerStrip, order, tiepointXY, pixelScale, transformation,
                    modelType, rasterType, epsg, verticalCs, nodata, overview, forcedCompressionCode);
        }

        Spec withLayout(int tiles, int rows, ByteOrder o) {
            return new Spec(width, height, type, compression, predictor, tiles, rows, o, tiepointXY, pixelScale, transformation,
                    modelType, rasterType, epsg, verticalCs, nodata, overview, forcedCompressionCode);
        }

        Spec withType(SampleType t) {
            return new Spec(width, height, t, compression, predictor, tileSize, rowsPerStrip, order, tiepointXY, pixelScale,
                    transformation, modelType, rasterType, epsg, verticalCs, nodata, overview, forcedCompressionCode);
        }

        Spec withCrs(int model, int code, int vertical) {
            return new Spec(width, height, type, compression, predictor, tileSize, rowsPerStrip, order, tiepointXY, pixelScale,
                    transformation, model, rasterType, code, vertical, nodata, overview, forcedCompressionCode);
        }

        Spec withNodata(String n) {
            return new Spec(width, height, type, compression, predictor, tileSize, rowsPerStrip, order, tiepointXY, pixelScale,
                    transformation, modelType, rasterType, epsg, verticalCs, n, overview, forcedCompressionCode);
        }

        Spec withOverview() {
            return new Spec(width, height, type, compression, predictor, tileSize, rowsPerStrip, order, tiepointXY, pixelScale,
                    transformation, modelType, rasterType, epsg, verticalCs, nodata, true, forcedCompressionCode);
        }

        Spec withTransformation() {
            double[] m = {pixelScale[0], 0, 0, tiepointXY[0], 0, -pixelScale[1], 0, tiepointXY[1], 0, 0, 0, 0, 0, 0, 0, 1};
            return new Spec(width, height, type, compression, predictor, tileSize, rowsPerStrip, order, null, null, m,
                    modelType, rasterType, epsg, verticalCs, nodata, overview, forcedCompressionCode);
        }

        Spec withCompressionCodeWritten(int code) {
            return new Spec(width, height, type, compression, predictor, tileSize, rowsPerStrip, order, tiepointXY, pixelScale,
                    transformation, modelType, rasterType, epsg, verticalCs, nodata, overview, code);
        }
    }

    /**
     * A geographic (EPSG:4326) grid whose pixel centres are at lon0 + col·dLon, lat0 − row·dLat, written
     * as PixelIsPoint (tiepoint on the centre of pixel 0,0) or PixelIsArea (tiepoint on its north-west corner).
     */
    static Spec geographic(int width, int height, double lon0Deg, double lat0Deg, double dLonDeg, double dLatDeg,
                           boolean pixelIsPoint) {
        double x = pixelIsPoint ? lon0Deg : lon0Deg - dLonDeg / 2, y = pixelIsPoint ? lat0Deg : lat0Deg + dLatDeg / 2;
        return new Spec(width, height, SampleType.INT16, NONE, 1, 0, 7, ByteOrder.LITTLE_ENDIAN, new double[] {x, y},
                new double[] {dLonDeg, dLatDeg}, null, 2, pixelIsPoint ? 2 : 1, 4326, 0, null, false, 0);
    }

    interface Values {
        double at(int row, int col);
    }

    static Path write(Path file, Spec s, Values v) throws IOException {
        Files.write(file, bytes(s, v));
        return file;
    }

    static byte[] bytes(Spec s, Values v) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteBuffer head = ByteBuffer.allocate(8).order(s.order());
        head.put((byte) (s.order() == ByteOrder.LITTLE_ENDIAN ? 'I' : 'M')).put((byte) (s.order() == ByteOrder.LITTLE_ENDIAN ? 'I' : 'M'));
        head.putShort((short) 42).putInt(0); // IFD offset patched below
        out.writeBytes(head.array());
        List<Map<Integer, Object>> ifds = new ArrayList<>();
        ifds.add(image(out, s, v, false));
        if (s.overview()) {
            // Half resolution, different heights: a reader must not take it for the image.
            Spec o = new Spec((s.width() + 1) / 2, (s.height() + 1) / 2, s.type(), s.compression(), s.predictor(), s.tileSize(),
                    s.rowsPerStrip(), s.order(), null, null, null, 0, 0, 0, 0, null, false, 0);
            ifds.add(image(out, o, (r, c) -> 4321, true));
        }
        // IFDs at the end, chained.
        byte[] body = out.toByteArray();
        ByteBuffer all = ByteBuffer.allocate(body.length + 100_000).order(s.order());
        all.put(body);
        int firstIfd = align(all);
        all.putInt(4, firstIfd);
        for (int k = 0; k < ifds.size(); k++) {
            writeIfd(all, ifds.get(k), k + 1 < ifds.size());
        }
        byte[] result = new byte[all.position()];
        all.flip();
        all.get(result);
        return result;
    }

    private static int align(ByteBuffer b) {
        if (b.position() % 2 == 1) {
            b.put((byte) 0);
        }
        return b.position();
    }

    /** Writes the image blocks to out; returns the IFD's tags (tag → int[], double[] or String). */
    private static Map<Integer, Object> image(ByteArrayOutputStream out, Spec s, Values v, boolean reduced) {
        boolean tiled = s.tileSize() > 0;
        int bw = tiled ? s.tileSize() : s.width(), bh = tiled ? s.tileSize() : s.rowsPerStrip();
        int across = tiled ? (s.width() + bw - 1) / bw : 1, down = (s.height() + bh - 1) / bh;
        List<Integer> offsets = new ArrayList<>(), counts = new ArrayList<>();
        for (int by = 0; by < down; by++) {
            for (int bx = 0; bx < across; bx++) {
                int rows = tiled ? bh : Math.min(bh, s.height() - by * bh);
                byte[] raw = block(s, v, bx * bw, by * bh, bw, rows);
                byte[] packed = switch (s.compression()) {
                    case NONE -> raw;
                    case DEFLATE -> deflate(raw);
                    case LZW -> lzw(raw);
                    default -> throw new IllegalArgumentException("compression " + s.compression());
                };
                if (out.size() % 2 == 1) {
                    out.write(0);
                }
                offsets.add(out.size());
                counts.add(packed.length);
                out.writeBytes(packed);
            }
        }
        Map<Integer, Object> t = new TreeMap<>();
        if (reduced) {
            t.put(254, new int[] {1}); // NewSubfileType: reduced-resolution image
        }
        t.put(256, new int[] {s.width()});
        t.put(257, new int[] {s.height()});
        t.put(258, new int[] {s.type().bits});
        t.put(259, new int[] {s.forcedCompressionCode() != 0 ? s.forcedCompressionCode() : s.compression()});
        t.put(262, new int[] {1}); // BlackIsZero
        t.put(277, new int[] {1});
        t.put(284, new int[] {1});
        t.put(317, new int[] {s.predictor()});
        t.put(339, new int[] {s.type().sampleFormat});
        int[] off = offsets.stream().mapToInt(Integer::intValue).toArray(), cnt = counts.stream().mapToInt(Integer::intValue).toArray();
        if (tiled) {
            t.put(322, new int[] {bw});
            t.put(323, new int[] {bh});
            t.put(324, off);
            t.put(325, cnt);
        } else {
            t.put(273, off);
            t.put(278, new int[] {bh});
            t.put(279, cnt);
        }
        if (s.tiepointXY() != null) {
            t.put(33550, new double[] {s.pixelScale()[0], s.pixelScale()[1], 0});
            t.put(33922, new double[] {0, 0, 0, s.tiepointXY()[0], s.tiepointXY()[1], 0});
        }
        if (s.transformation() != null) {
            t.put(34264, s.transformation());
        }
        if (s.modelType() != 0) {
            List<Integer> keys = new ArrayList<>(List.of(1, 1, 0, 0));
            keys.addAll(List.of(1024, 0, 1, s.modelType()));
            keys.addAll(List.of(1025, 0, 1, s.rasterType()));
            if (s.modelType() == 2) {
                keys.addAll(List.of(2048, 0, 1, s.epsg()));
                keys.addAll(List.of(2054, 0, 1, 9102));
            } else {
                keys.addAll(List.of(3072, 0, 1, s.epsg()));
            }
            if (s.verticalCs() != 0) {
                keys.addAll(List.of(4096, 0, 1, s.verticalCs()));
            }
            keys.set(3, (keys.size() - 4) / 4);
            t.put(34735, keys.stream().mapToInt(Integer::intValue).toArray());
        }
        if (s.nodata() != null) {
            t.put(42113, s.nodata());
        }
        return t;
    }

    /** One strip or tile, uncompressed, predictor applied, padded with zeros beyond the image. */
    private static byte[] block(Spec s, Values v, int x0, int y0, int w, int h) {
        int bytes = s.type().bytes;
        ByteBuffer b = ByteBuffer.allocate(w * h * bytes).order(s.order());
        for (int r = 0; r < h; r++) {
            long[] row = new long[w];
            float[] frow = new float[w];
            for (int c = 0; c < w; c++) {
                boolean inside = y0 + r < s.height() && x0 + c < s.width();
                double value = inside ? v.at(y0 + r, x0 + c) : 0;
                frow[c] = (float) value;
                row[c] = s.type() == SampleType.FLOAT32 ? 0 : (long) value;
            }
            if (s.predictor() == 2) {
                for (int c = w - 1; c > 0; c--) {
                    row[c] -= row[c - 1]; // wraps modulo the sample size when stored
                }
            }
            if (s.type() == SampleType.FLOAT32 && s.predictor() == 3) {
                // Floating-point predictor: the bytes of each sample, most significant first, split into
                // planes, then differenced byte by byte along the row.
                byte[] planes = new byte[4 * w];
                for (int c = 0; c < w; c++) {
                    int bits = Float.floatToRawIntBits(frow[c]);
                    for (int k = 0; k < 4; k++) {
                        planes[k * w + c] = (byte) (bits >>> (24 - 8 * k));
                    }
                }
                for (int j = 4 * w - 1; j > 0; j--) {
                    planes[j] -= planes[j - 1];
                }
                b.put(planes);
                continue;
            }
            for (int c = 0; c < w; c++) {
                switch (s.type()) {
                    case INT16 -> b.putShort((short) row[c]);
                    case INT32 -> b.putInt((int) row[c]);
                    case FLOAT32 -> b.putFloat(frow[c]);
                }
            }
        }
        return b.array();
    }

    private static byte[] deflate(byte[] raw) {
        Deflater d = new Deflater(); // zlib stream, as TIFF compression 8 holds
        d.setInput(raw);
        d.finish();
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        byte[] buf = new byte[65536];
        while (!d.finished()) {
            out.write(buf, 0, d.deflate(buf));
        }
        d.end();
        return out.toByteArray();
    }

    /** TIFF LZW (MSB-first codes, 9–12 bits, early change, Clear 256, EOI 257). */
    static byte[] lzw(byte[] raw) {
        BitWriter out = new BitWriter();
        Map<Long, Integer> dict = new java.util.HashMap<>();
        int next = 258, width = 9;
        out.write(256, width);
        int prefix = -1;
        for (byte x : raw) {
            int b = x & 0xff;
            if (prefix < 0) {
                prefix = b;
                continue;
            }
            Integer code = dict.get(((long) prefix << 8) | b);
            if (code != null) {
                prefix = code;
                continue;
            }
            out.write(prefix, width);
            dict.put(((long) prefix << 8) | b, next++);
            width = next >= 2048 ? 12 : next >= 1024 ? 11 : next >= 512 ? 10 : 9;
            if (next == 4094) {
                out.write(256, width);
                dict.clear();
                next = 258;
                width = 9;
            }
            prefix = b;
        }
        if (prefix >= 0) {
            out.write(prefix, width);
            next++;
            width = next >= 2048 ? 12 : next >= 1024 ? 11 : next >= 512 ? 10 : 9;
        }
        out.write(257, width);
        return out.bytes();
    }

    private static final class BitWriter {
        private final ByteArrayOutputStream out = new ByteArrayOutputStream();
        private long acc;
        private int bits;

        void write(int code, int width) {
            acc = (acc << width) | code;
            bits += width;
            while (bits >= 8) {
                out.write((int) (acc >>> (bits - 8)) & 0xff);
                bits -= 8;
            }
        }

        byte[] bytes() {
            if (bits > 0) {
                out.write((int) (acc << (8 - bits)) & 0xff);
                bits = 0;
            }
            return out.toByteArray();
        }
    }

    private static void writeIfd(ByteBuffer all, Map<Integer, Object> tags, boolean more) {
        int start = align(all);
        int n = tags.size();
        int extra = start + 2 + 12 * n + 4; // values that do not fit in 4 bytes go here
        ByteBuffer ext = ByteBuffer.allocate(200_000).order(all.order());
        all.putShort((short) n);
        for (Map.Entry<Integer, Object> e : tags.entrySet()) {
            int tag = e.getKey();
            Object val = e.getValue();
            all.putShort((short) tag);
            if (val instanceof String str) {
                byte[] a = (str + "\0").getBytes(java.nio.charset.StandardCharsets.US_ASCII);
                all.putShort((short) 2).putInt(a.length);
                putOrRef(all, ext, extra, a);
            } else if (val instanceof double[] d) {
                ByteBuffer bb = ByteBuffer.allocate(8 * d.length).order(all.order());
                for (double x : d) {
                    bb.putDouble(x);
                }
                all.putShort((short) 12).putInt(d.length);
                putOrRef(all, ext, extra, bb.array());
            } else {
                int[] a = (int[]) val;
                boolean asShort = tag != 273 && tag != 279 && tag != 324 && tag != 325 && tag != 254;
                ByteBuffer bb = ByteBuffer.allocate((asShort ? 2 : 4) * a.length).order(all.order());
                for (int x : a) {
                    if (asShort) {
                        bb.putShort((short) x);
                    } else {
                        bb.putInt(x);
                    }
                }
                all.putShort((short) (asShort ? 3 : 4)).putInt(a.length);
                putOrRef(all, ext, extra, bb.array());
            }
        }
        int nextIfdAt = all.position();
        all.putInt(0);
        byte[] e = new byte[ext.position()];
        ext.flip();
        ext.get(e);
        all.put(e);
        if (more) {
            int nextStart = all.position() + (all.position() % 2);
            all.putInt(nextIfdAt, nextStart);
        }
    }

    private static void putOrRef(ByteBuffer all, ByteBuffer ext, int extraStart, byte[] value) {
        if (value.length <= 4) {
            all.put(value);
            for (int i = value.length; i < 4; i++) {
                all.put((byte) 0);
            }
        } else {
            if (ext.position() % 2 == 1) {
                ext.put((byte) 0);
            }
            all.putInt(extraStart + ext.position());
            ext.put(value);
        }
    }
}
