package dempano.camera;

/**
 * Which way a camera points: the rotation between its frame (OpenCV: x right, y down, z forward along the
 * optical axis) and the local east-north-up frame of {@link dempano.geo.LocalFrame}. The angles are the
 * aerospace yaw–pitch–roll (Tait–Bryan z-y′-x″) sequence, which is also DJI's gimbal convention:
 *
 * <table>
 *   <caption>Angles</caption>
 *   <tr><th>angle</th><th>zero</th><th>positive</th><th>range</th></tr>
 *   <tr><td>heading</td><td>optical axis toward true north</td><td>clockwise seen from above (90° = east)</td>
 *       <td>any; used modulo 360</td></tr>
 *   <tr><td>pitch</td><td>optical axis horizontal</td><td>optical axis up (90° = zenith, −90° = nadir)</td>
 *       <td>[−90, 90]</td></tr>
 *   <tr><td>roll</td><td>image rows horizontal (the image's x axis level)</td><td>camera turned clockwise about
 *       its optical axis as the photographer behind it sees it: the image's right side dips, so the horizon
 *       appears turned counter-clockwise in the photo (90° = portrait with the camera's top to the right: the
 *       image's top points along the level direction 90° clockwise of the heading)</td><td>any; used modulo
 *       360</td></tr>
 * </table>
 *
 * Composition: start from the camera level and facing north (x = east, y = down, z = north); turn it by the
 * heading about the vertical (clockwise from above), then tilt it by the pitch about its own (turned) x axis,
 * then roll it about its own (tilted) optical axis. This intrinsic heading → pitch → roll order equals the
 * extrinsic order roll about north → pitch about east (…the fixed axes of the starting pose) → heading about up;
 * the tests build it that way with axis-angle rotations. In closed form, with ψ heading, θ pitch, φ roll, the
 * camera's axes in ENU are
 *
 * <pre>
 *   forward z = (sin ψ·cos θ, cos ψ·cos θ, sin θ)
 *   r0 = (cos ψ, −sin ψ, 0)                      level right
 *   u0 = (−sin ψ·sin θ, −cos ψ·sin θ, cos θ)      image-up before roll
 *   right x = cos φ·r0 − sin φ·u0
 *   down  y = −(sin φ·r0 + cos φ·u0)
 * </pre>
 *
 * At pitch ±90° heading and roll turn about the same axis (gimbal lock): the rotation is still well defined.
 * The angles refer to the image as displayed (EXIF orientation applied): a portrait photo shown upright has
 * roll ≈ 0 whichever way the camera body was held.
 *
 * @param headingDeg azimuth of the optical axis, degrees clockwise from true north
 * @param pitchDeg   elevation of the optical axis above the local horizontal, degrees, [−90, 90]
 * @param rollDeg    rotation about the optical axis, degrees, positive clockwise as the photographer sees it
 */
public record CameraOrientation(double headingDeg, double pitchDeg, double rollDeg) {
    public CameraOrientation {
        if (!Double.isFinite(headingDeg) || !(pitchDeg >= -90 && pitchDeg <= 90) || !Double.isFinite(rollDeg)) {
            throw new IllegalArgumentException("camera orientation needs a finite heading and roll and a pitch in"
                    + " [-90°, 90°], got heading " + headingDeg + "°, pitch " + pitchDeg + "°, roll " + rollDeg + "°");
        }
    }

    /**
     * The rotation from the camera frame to ENU, row-major 3 × 3: column j holds camera axis j (x right, y down,
     * z forward) in east, north, up components, so enu = M · camera and camera = Mᵀ · enu.
     */
    public double[] cameraToEnu() {
        double psi = Math.toRadians(headingDeg), theta = Math.toRadians(pitchDeg), phi = Math.toRadians(rollDeg);
        double sp = Math.sin(psi), cp = Math.cos(psi), st = Math.sin(theta), ct = Math.cos(theta);
        double sf = Math.sin(phi), cf = Math.cos(phi);
        double[] f = {sp * ct, cp * ct, st};
        double[] r0 = {cp, -sp, 0};
        double[] u0 = {-sp * st, -cp * st, ct};
        double[] m = new double[9];
        for (int i = 0; i < 3; i++) {
            m[3 * i] = cf * r0[i] - sf * u0[i];
            m[3 * i + 1] = -(sf * r0[i] + cf * u0[i]);
            m[3 * i + 2] = f[i];
        }
        return m;
    }

    /** A camera-frame vector in ENU with a matrix from {@link #cameraToEnu()}. */
    public static void cameraToEnu(double[] m, double x, double y, double z, double[] out) {
        double e = m[0] * x + m[1] * y + m[2] * z;
        double n = m[3] * x + m[4] * y + m[5] * z;
        double u = m[6] * x + m[7] * y + m[8] * z;
        out[0] = e;
        out[1] = n;
        out[2] = u;
    }

    /** An ENU vector in the camera frame with a matrix from {@link #cameraToEnu()} (its transpose). */
    public static void enuToCamera(double[] m, double e, double n, double u, double[] out) {
        double x = m[0] * e + m[3] * n + m[6] * u;
        double y = m[1] * e + m[4] * n + m[7] * u;
        double z = m[2] * e + m[5] * n + m[8] * u;
        out[0] = x;
        out[1] = y;
        out[2] = z;
    }

    /**
     * The angles of a camera-to-ENU rotation (row-major, as {@link #cameraToEnu()}): heading in [0, 360), pitch in
     * [−90, 90], roll in (−180, 180]. At pitch ±90° (gimbal lock) the whole turn about the vertical is put in the
     * heading and roll is 0.
     */
    public static CameraOrientation fromCameraToEnu(double[] m) {
        double fe = m[2], fn = m[5], fu = m[8];
        double pitch = Math.toDegrees(Math.asin(Math.max(-1, Math.min(1, fu))));
        double horizontal = Math.hypot(fe, fn);
        if (horizontal < 1e-12) {
            // Looking straight up or down: the image's up (−y) fixes the heading; u0 = ∓(sin ψ, cos ψ, 0).
            double ue = -m[1], un = -m[4];
            double sign = fu > 0 ? -1 : 1;
            double heading = Math.toDegrees(Math.atan2(sign * ue, sign * un));
            return new CameraOrientation(dempano.geo.Angles.wrap360(heading), fu > 0 ? 90 : -90, 0);
        }
        double psi = Math.atan2(fe, fn);
        double heading = Math.toDegrees(psi);
        double theta = Math.toRadians(pitch);
        double sp = Math.sin(psi), cp = Math.cos(psi), st = Math.sin(theta), ct = Math.cos(theta);
        // right = cos φ·r0 − sin φ·u0.
        double re = m[0], rn = m[3], ru = m[6];
        double cosPhi = re * cp - rn * sp;
        double sinPhi = -(re * (-sp * st) + rn * (-cp * st) + ru * ct);
        double roll = Math.toDegrees(Math.atan2(sinPhi, cosPhi));
        return new CameraOrientation(dempano.geo.Angles.wrap360(heading), pitch, roll == -180 ? 180 : roll);
    }
}
