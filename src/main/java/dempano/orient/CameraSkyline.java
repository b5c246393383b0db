package dempano.orient;

import dempano.camera.CameraIntrinsics;
import dempano.camera.CameraOrientation;

/**
 * The fine stage's reference: the skyline of a camera view rendered at the photo's position, as a profile over
 * azimuth ({@link HorizonProfile#ofCamera}). {@link OrientationEstimator} asks for one around each pose it refines
 * finely; the caller renders it (OpenGL or CPU reference), so the estimator itself stays free of rendering.
 */
@FunctionalInterface
public interface CameraSkyline {
    /**
     * The skyline of the camera view with these intrinsics and this orientation.
     *
     * @return a profile whose azimuths outside the view are NaN
     */
    HorizonProfile render(CameraIntrinsics intrinsics, CameraOrientation orientation);
}
