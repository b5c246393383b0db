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

    /**
     * @param argb           colour per pixel, row-major; null when not rendered
     * @param distanceMetres straight-line distance from the eye per pixel, metres, +∞ for sky, NaN where the lens
     *                       model has no ray; null when not rendered
     * @param metadata       the eye as placed, tiles, timings and the renderer's settings (views are the camera's)
     */
    public CameraImage(CameraView view, CameraPose pose, int[] argb, float[] distanceMetres, PanoramaMetadata metadata) {
        this.view = view;
        this.pose = pose;
        this.argb = argb;
        this.distanceMetres = distanceMetres;
        this.metadata = metadata;
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

    /** Distance at a pixel, metres (+∞ sky). */
    public float distanceMetres(int column, int row) {
        if (distanceMetres == null) {
            throw new IllegalStateException("rendered without distances");
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
        return java.nio.FloatBuffer.wrap(distanceMetres).asReadOnlyBuffer();
    }

    /** The colour as an image. */
    public BufferedImage image() {
        BufferedImage img = new BufferedImage(widthPx(), heightPx(), BufferedImage.TYPE_INT_RGB);
        img.setRGB(0, 0, widthPx(), heightPx(), argbArray(), 0, widthPx());
        return img;
    }
}
