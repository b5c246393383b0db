package dempano.camera;

/**
 * What a camera sees: its intrinsics and its orientation, as a {@link TargetImage} mapping the photo's pixels
 * (as displayed, OpenCV convention) to directions in the eye's east-north-up frame and back. Immutable.
 */
public final class CameraView implements TargetImage {
    private final CameraIntrinsics intrinsics;
    private final CameraOrientation orientation;
    private final double[] cameraToEnu;

    public CameraView(CameraIntrinsics intrinsics, CameraOrientation orientation) {
        if (intrinsics == null || orientation == null) {
            throw new IllegalArgumentException("a camera view needs intrinsics and an orientation");
        }
        this.intrinsics = intrinsics;
        this.orientation = orientation;
        this.cameraToEnu = orientation.cameraToEnu();
    }

    public CameraIntrinsics intrinsics() {
        return intrinsics;
    }

    public CameraOrientation orientation() {
        return orientation;
    }

    @Override
    public int widthPx() {
        return intrinsics.widthPx();
    }

    @Override
    public int heightPx() {
        return intrinsics.heightPx();
    }

    @Override
    public void rayOf(double px, double py, double[] out) {
        intrinsics.rayOf(px, py, out);
        CameraOrientation.cameraToEnu(cameraToEnu, out[0], out[1], out[2], out);
    }

    @Override
    public void pixelOf(double east, double north, double up, double[] out) {
        double[] m = cameraToEnu; // transpose: ENU → camera
        double x = m[0] * east + m[3] * north + m[6] * up;
        double y = m[1] * east + m[4] * north + m[7] * up;
        double z = m[2] * east + m[5] * north + m[8] * up;
        intrinsics.pixelOf(x, y, z, out);
    }

    @Override
    public String toString() {
        return "CameraView[" + intrinsics + ", " + orientation + "]";
    }
}
