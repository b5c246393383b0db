package dempano.panorama;

import java.awt.image.BufferedImage;
import java.util.Collections;
import java.util.EnumMap;
import java.util.Map;
import java.util.Objects;

/**
 * A rendered 360° panorama: colour, distance per pixel and optional layers on an equirectangular
 * grid ({@link PanoramaGeometry}). Row-major arrays, row 0 at the top. Distances are straight-line
 * metres from the eye to the terrain point seen, +∞ for sky. Immutable; accessors return copies
 * only where noted.
 *
 * <p>Domains. Pixel accessors ({@link #distanceMetres(int, int)}, {@link #argb(int, int)}) take a
 * column in [0, {@link #widthPx()}) and a row in [0, {@link #heightPx()}) and throw
 * {@link IndexOutOfBoundsException} naming the value and the range otherwise. Direction lookups
 * ({@link #distanceAt(double, double)}) take any finite azimuth, wrapped modulo 360°, and return NaN
 * for a NaN or infinite argument or an elevation outside the rendered rows (bottom, top]. The angle conversions
 * {@link #azimuthOfColumn(int)} and {@link #elevationOfRow(int)} are plain arithmetic on the grid:
 * outside the image they extrapolate (no wrapping, no exception).
 */
public final class Panorama {
    private final PanoramaGeometry geometry;
    private final int[] argb;
    private final float[] distanceMetres;
    private final Map<Layer, float[]> layers;
    private final PanoramaMetadata metadata;

    /**
     * @param argb           colour, or null when only distances were rendered
     * @param distanceMetres distances, or null when only colour was rendered
     */
    public Panorama(PanoramaGeometry geometry, int[] argb, float[] distanceMetres, Map<Layer, float[]> layers,
                    PanoramaMetadata metadata) {
        this.geometry = Objects.requireNonNull(geometry);
        int n = geometry.widthPx() * geometry.heightPx();
        if (argb == null && distanceMetres == null) {
            throw new IllegalArgumentException("a panorama needs colour, distances or both");
        }
        if ((argb != null && argb.length != n) || (distanceMetres != null && distanceMetres.length != n)) {
            throw new IllegalArgumentException("arrays do not match " + geometry.widthPx() + "×" + geometry.heightPx());
        }
        this.argb = argb;
        this.distanceMetres = distanceMetres;
        EnumMap<Layer, float[]> copy = new EnumMap<>(Layer.class);
        copy.putAll(layers);
        this.layers = Collections.unmodifiableMap(copy);
        this.metadata = Objects.requireNonNull(metadata);
    }

    public PanoramaGeometry geometry() {
        return geometry;
    }

    public int widthPx() {
        return geometry.widthPx();
    }

    public int heightPx() {
        return geometry.heightPx();
    }

    public PanoramaMetadata metadata() {
        return metadata;
    }

    /**
     * Azimuth of a column's centre, degrees clockwise from true north: (column + 0.5)/ppd, in
     * [0, 360) for columns of the image; other columns extrapolate linearly (not wrapped).
     */
    public double azimuthOfColumn(int column) {
        return geometry.azimuthOfColumn(column);
    }

    /**
     * Elevation angle of a row's centre above the eye's horizontal, degrees: top − (row + 0.5)/ppd;
     * rows outside the image extrapolate linearly (−1 is the row that would lie above row 0).
     */
    public double elevationOfRow(int row) {
        return geometry.elevationOfRow(row);
    }

    /**
     * Distance in metres of the pixel at (column, row); +∞ for sky.
     *
     * @throws IndexOutOfBoundsException column not in [0, width) or row not in [0, height), naming the value
     * @throws IllegalStateException     distances were not rendered
     */
    public float distanceMetres(int column, int row) {
        return distances()[index(column, row)];
    }

    /** The array index of a pixel, after checking both coordinates. */
    private int index(int column, int row) {
        if (column < 0 || column >= widthPx()) {
            throw new IndexOutOfBoundsException("column " + column + " outside the panorama's columns 0…" + (widthPx() - 1));
        }
        if (row < 0 || row >= heightPx()) {
            throw new IndexOutOfBoundsException("row " + row + " outside the panorama's rows 0…" + (heightPx() - 1));
        }
        return row * widthPx() + column;
    }

    /** Whether the distance map was rendered (see {@code PanoramaRequest.withDistance}). */
    public boolean hasDistance() {
        return distanceMetres != null;
    }

    private float[] distances() {
        if (distanceMetres == null) {
            throw new IllegalStateException("this panorama was rendered without distances (colour only)");
        }
        return distanceMetres;
    }

    /**
     * Distance in metres seen in a direction: the value of the pixel containing it (column c covers
     * azimuths [c/ppd, (c+1)/ppd), row r elevations (top − (r+1)/ppd, top − r/ppd]).
     *
     * @param azimuthDeg   degrees clockwise from true north; any finite value, wrapped modulo 360
     *                     (−90 and 270 are the same direction)
     * @param elevationDeg degrees above the eye's horizontal
     * @return metres; +∞ for sky; NaN when either argument is NaN or infinite, or the elevation lies
     *         outside the rendered rows, which cover ({@link PanoramaGeometry#bottomElevationDeg() bottom},
     *         {@link PanoramaGeometry#topElevationDeg() top}] (the top edge belongs to row 0, the bottom
     *         edge to no row)
     * @throws IllegalStateException distances were not rendered
     */
    public double distanceAt(double azimuthDeg, double elevationDeg) {
        float[] d = distances();
        if (!Double.isFinite(azimuthDeg) || !Double.isFinite(elevationDeg)) {
            return Double.NaN;
        }
        double row = geometry.rowOf(elevationDeg);
        if (!(row >= 0 && row < heightPx())) {
            return Double.NaN;
        }
        // columnOf wraps into [0, 360); a value a rounding step below 0 can come back as 360·ppd itself.
        int col = Math.floorMod((int) Math.floor(geometry.columnOf(azimuthDeg)), widthPx());
        return d[(int) row * widthPx() + col];
    }

    /** Whether the colour image was rendered (see {@code PanoramaRequest.withColour}). */
    public boolean hasColour() {
        return argb != null;
    }

    /**
     * Colour of a pixel, 0xAARRGGBB.
     *
     * @throws IndexOutOfBoundsException column not in [0, width) or row not in [0, height), naming the value
     * @throws IllegalStateException     colour was not rendered
     */
    public int argb(int column, int row) {
        return colour()[index(column, row)];
    }

    private int[] colour() {
        if (argb == null) {
            throw new IllegalStateException("this panorama was rendered without colour (distances only)");
        }
        return argb;
    }

    /** A copy of the distance array (row-major, metres); throws if distances were not rendered. */
    public float[] distanceArray() {
        return distances().clone();
    }

    /** The layers rendered on request. */
    public java.util.Set<Layer> layers() {
        return layers.keySet();
    }

    /** A copy of a layer (row-major), or throws if it was not requested. */
    public float[] layer(Layer layer) {
        float[] l = layers.get(layer);
        if (l == null) {
            throw new IllegalArgumentException("layer " + layer.fileName() + " was not rendered; request it");
        }
        return l.clone();
    }

    /** The colour image; throws if colour was not rendered. */
    public BufferedImage image() {
        int[] colour = colour();
        BufferedImage img = new BufferedImage(widthPx(), heightPx(), BufferedImage.TYPE_INT_RGB);
        // Straight into the raster (setRGB converts pixel by pixel); INT_RGB ignores the alpha byte.
        int[] pixels = ((java.awt.image.DataBufferInt) img.getRaster().getDataBuffer()).getData();
        System.arraycopy(colour, 0, pixels, 0, colour.length);
        return img;
    }

    /** Read-only view of the distances for writers (no copy); throws if distances were not rendered. */
    public java.nio.FloatBuffer distanceBuffer() {
        return java.nio.FloatBuffer.wrap(distances()).asReadOnlyBuffer();
    }

    /** Read-only view of a layer for writers (no copy). */
    public java.nio.FloatBuffer layerBuffer(Layer layer) {
        float[] l = layers.get(layer);
        if (l == null) {
            throw new IllegalArgumentException("layer " + layer.fileName() + " was not rendered; request it");
        }
        return java.nio.FloatBuffer.wrap(l).asReadOnlyBuffer();
    }

    /**
     * The summits of a list within this panorama's range: where each falls (azimuth, elevation
     * angle, pixel), how far it is, and whether it is seen
     * ({@link dempano.summits.SummitProjector} documents the tolerance). Needs the distance map.
     */
    public java.util.List<dempano.summits.SummitSighting> summits(dempano.summits.SummitList list) {
        return dempano.summits.SummitProjector.project(this, list);
    }
}
