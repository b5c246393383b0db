package dempano.camera;

import java.util.List;

/**
 * A photograph's camera, resolved from its metadata and the user's overrides: what a renderer needs to render
 * the photo's own view.
 *
 * @param intrinsics the camera model for the photo's pixels as displayed
 * @param pose       where the camera stood and which way it pointed
 * @param provenance one line per value saying where it came from (flag, EXIF tag, XMP property, default) and
 *                   any caveat, for a log or a metadata file
 */
public record PhotoCamera(CameraIntrinsics intrinsics, CameraPose pose, List<String> provenance) {
    public PhotoCamera {
        if (intrinsics == null || pose == null) {
            throw new IllegalArgumentException("a photo camera needs intrinsics and a pose");
        }
        provenance = List.copyOf(provenance);
    }

    /** The photo's pixels as directions in the eye's east-north-up frame. */
    public CameraView view() {
        return new CameraView(intrinsics, pose.orientation());
    }
}
