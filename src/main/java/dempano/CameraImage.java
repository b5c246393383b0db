package dempano;

import dempano.camera.CameraPose;
import dempano.camera.CameraView;
import dempano.panorama.PanoramaMetadata;
import java.awt.image.BufferedImage;

/**
 * A camera's rendered view on the photo's own pixel grid (row 0 at the top, OpenCV pixel convention: pixel
 * (column i, row j) has its centre at (i, j)). Immutable: accessors of arrays return copies.
 */
public final class CameraImage {
    private final CameraView view;
    private final CameraPose pose;
    private final int[] argb;
    private final float[] distanceMetres;
    private final PanoramaMetadata metadata;
    private final java.util.Map<dempano.panorama.Layer, float[]> layers;

    /**
     * @param argb           colour per pixel, row-major; null when not rendered
     * @param distanceMetres straight-line distance from the eye per pixel, metres, +∞ for sky, NaN where the lens
     *                       model has no ray; null when not rendered
     * @param metadata       the eye as placed, tiles, timings and the renderer's settings (views are the camera's)
     */
    public CameraImage(CameraView view, CameraPose pose, int[] argb, float[] distanceMetres, PanoramaMetadata metadata) {
        this(view, pose, new Pixels(argb, distanceMetres, java.util.Map.of()), metadata);
    }

    /**
     * @param pixels   colour, distance and layers on the photo's pixel grid
     * @param metadata the eye as placed, tiles, timings and the renderer's settings (views are the camera's)
     */
    public CameraImage(CameraView view, CameraPose pose, Pixels pixels, PanoramaMetadata metadata) {
        this.view = view;
        this.pose = pose;
        this.argb = pixels.argb();
        this.distanceMetres = pixels.distanceMetres();
        this.metadata = metadata;
        java.util.Map<dempano.panorama.Layer, float[]> l = new java.util.EnumMap<>(dempano.panorama.Layer.class);
        l.putAll(pixels.layers());
        this.layers = java.util.Collections.unmodifiableMap(l);
    }

    /**
     * What a render puts on the photo's pixel grid (row-major).
     *
     * @param argb           colour per pixel; null when not rendered
     * @param distanceMetres distance per pixel, metres, +∞ sky, NaN without a ray; null when not rendered
     * @param layers         requested layers ({@link dempano.panorama.Layer}), NaN for sky and pixels without a ray
     */
    public record Pixels(int[] argb, float[] distanceMetres, java.util.Map<dempano.panorama.Layer, float[]> layers) {
    }

    /** The layers rendered, in {@link dempano.panorama.Layer} order. */
    public java.util.Set<dempano.panorama.Layer> layers() {
        return layers.keySet();
    }

    /** A copy of a layer, row-major. */
    public float[] layerArray(dempano.panorama.Layer layer) {
        float[] a = layers.get(layer);
        if (a == null) {
            throw new IllegalArgumentException("layer " + layer.fileName() + " was not rendered");
        }
        return a.clone();
    }

    /** A layer as a read-only buffer (for writers), no copy. */
    public java.nio.FloatBuffer layerBuffer(dempano.panorama.Layer layer) {
        float[] a = layers.get(layer);
        if (a == null) {
            throw new IllegalArgumentException("layer " + layer.fileName() + " was not rendered");
        }
        return java.nio.FloatBuffer.wrap(a).asReadOnlyBuffer();
    }

    public CameraView view() {
        return view;
    }

    public CameraPose pose() {
        return pose;
    }

    public PanoramaMetadata metadata() {
        return metadata;
    }

    public int widthPx() {
        return view.widthPx();
    }

    public int heightPx() {
        return view.heightPx();
    }

    public boolean hasColour() {
        return argb != null;
    }

    public boolean hasDistance() {
        return distanceMetres != null;
    }

    /**
     * Distance at a pixel, metres (+∞ sky).
     *
     * @throws IndexOutOfBoundsException when the column or row lies outside the image
     * @throws IllegalStateException     when the image was rendered without distances
     */
    public float distanceMetres(int column, int row) {
        if (distanceMetres == null) {
            throw new IllegalStateException("rendered without distances");
        }
        if (column < 0 || column >= widthPx()) {
            throw new IndexOutOfBoundsException("column " + column + " outside the image's columns 0…" + (widthPx() - 1));
        }
        if (row < 0 || row >= heightPx()) {
            throw new IndexOutOfBoundsException("row " + row + " outside the image's rows 0…" + (heightPx() - 1));
        }
        return distanceMetres[row * widthPx() + column];
    }

    /** A copy of the distance map, row-major, metres. */
    public float[] distanceArray() {
        if (distanceMetres == null) {
            throw new IllegalStateException("rendered without distances");
        }
        return distanceMetres.clone();
    }

    /** A copy of the colour, row-major ARGB. */
    public int[] argbArray() {
        if (argb == null) {
            throw new IllegalStateException("rendered without colour");
        }
        return argb.clone();
    }

    /** The distance map as a read-only buffer (for writers), no copy. */
    public java.nio.FloatBuffer distanceBuffer() {
        if (distanceMetres == null) {
            throw new IllegalStateException("rendered without distances");
        }
        return java.nio.FloatBuffer.wrap(distanceMetres).asReadOnlyBuffer();
    }

    /** The colour as an image. */
    public BufferedImage image() {
        BufferedImage img = new BufferedImage(widthPx(), heightPx(), BufferedImage.TYPE_INT_RGB);
        img.setRGB(0, 0, widthPx(), heightPx(), argbArray(), 0, widthPx());
        return img;
    }
}
