package dempano;

import dempano.camera.CameraIntrinsics;
import dempano.camera.CameraPose;
import dempano.camera.CameraView;
import dempano.camera.PhotoCamera;

/**
 * What to render for a camera: its intrinsics (the photo's pixel grid, lens included), its pose, and the render
 * settings a panorama request carries. Of {@code settings}, these apply: range, refraction, depth mode, near
 * plane, supersampling (view pixels per photo pixel at the finest, linear), missing-tile policy, level-of-detail
 * bound (in view pixels, about photo pixels), colour, distance, exact distances and layers (on the photo's pixel
 * grid). The position (latitude, longitude, offset, altitude, eye height) comes from the pose; the panorama's
 * resolution, elevation range, views and viewpoint adjustments do not apply.
 *
 * @param intrinsics the camera model on the photo's pixels
 * @param pose       where the camera stands and which way it points
 * @param settings   render settings (see above)
 */
public record CameraRequest(CameraIntrinsics intrinsics, CameraPose pose, PanoramaRequest settings) {
    public CameraRequest {
        if (intrinsics == null || pose == null || settings == null) {
            throw new IllegalArgumentException("a camera request needs intrinsics, a pose and settings");
        }
        // The settings' position is the pose's, so that every value a render reads agrees with it.
        PanoramaRequest s = settings.latDeg() == pose.latDeg() && settings.lonDeg() == pose.lonDeg() ? settings
                : settings.movedTo(pose.latDeg(), pose.lonDeg());
        settings = s.withOffsetMetres(pose.offsetMetres()).withAltitudeMetres(pose.altitudeMetres())
                .withEyeHeightMetres(pose.cameraHeightMetres());
    }

    /** A camera with every default render setting. */
    public static CameraRequest of(CameraIntrinsics intrinsics, CameraPose pose) {
        return new CameraRequest(intrinsics, pose, PanoramaRequest.at(pose.latDeg(), pose.lonDeg()));
    }

    /** A photograph's resolved camera with every default render setting. */
    public static CameraRequest of(PhotoCamera camera) {
        return of(camera.intrinsics(), camera.pose());
    }

    public CameraRequest withSettings(PanoramaRequest v) {
        return new CameraRequest(intrinsics, pose, v);
    }

    /** The photo's pixels as directions in the eye's east-north-up frame. */
    public CameraView view() {
        return new CameraView(intrinsics, pose.orientation());
    }
}
