package dempano.camera;

/**
 * An image whose pixels are directions from the eye: what a renderer fills with colour and distance. An
 * equirectangular panorama ({@link PanoramaTarget}) and a photograph's camera ({@link CameraView}) are the two
 * kinds.
 *
 * <p>Conventions shared by every implementation:
 * <ul>
 *   <li>Directions are in the eye's local east-north-up frame ({@link dempano.geo.LocalFrame}), as unit vectors.</li>
 *   <li>Pixel coordinates follow OpenCV: the centre of pixel (column i, row j) is at (i, j); the image covers
 *       [−0.5, w − 0.5) × [−0.5, h − 0.5); row 0 is the top.</li>
 *   <li>NaN means "none": a pixel with no ray, a direction with no pixel (behind a camera, outside its lens
 *       model's domain). A direction that has a pixel coordinate off the image gets that coordinate;
 *       {@link #contains} tells whether it is on the image.</li>
 * </ul>
 * Implementations are immutable and thread-safe.
 */
public interface TargetImage {
    /** Image width, pixels. */
    int widthPx();

    /** Image height, pixels. */
    int heightPx();

    /**
     * The direction through a pixel coordinate.
     *
     * @param out receives {east, north, up} of a unit vector, or three NaN
     */
    void rayOf(double px, double py, double[] out);

    /**
     * The pixel coordinate of a direction (need not be a unit vector; the zero vector has none).
     *
     * @param out receives {px, py}, or two NaN
     */
    void pixelOf(double east, double north, double up, double[] out);

    /** {@link #rayOf(double, double, double[])} into a new array. */
    default double[] rayOf(double px, double py) {
        double[] out = new double[3];
        rayOf(px, py, out);
        return out;
    }

    /** {@link #pixelOf(double, double, double, double[])} into a new array. */
    default double[] pixelOf(double east, double north, double up) {
        double[] out = new double[2];
        pixelOf(east, north, up, out);
        return out;
    }

    /** Whether a pixel coordinate lies on the image, [−0.5, w − 0.5) × [−0.5, h − 0.5); false for NaN. */
    default boolean contains(double px, double py) {
        return px >= -0.5 && px < widthPx() - 0.5 && py >= -0.5 && py < heightPx() - 0.5;
    }
}
