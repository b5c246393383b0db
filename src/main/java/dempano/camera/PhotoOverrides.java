package dempano.camera;

/**
 * What the user says about a photograph, overriding its metadata (a CLI's flags): NaN (or null) = not given.
 * The flag names in the constants are the ones {@link PhotoMetadata#missing} tells the user to give.
 *
 * @param latDeg             camera latitude, degrees ({@value #LAT})
 * @param lonDeg             camera longitude, degrees ({@value #LON})
 * @param altitudeMetres     absolute standing altitude, metres above sea level ({@value #ALTITUDE})
 * @param offsetMetres       stand on the DEM corrected by this signed offset, metres ({@value #OFFSET}); wins over
 *                           the EXIF GPS altitude
 * @param cameraHeightMetres camera above the standing altitude, metres ({@value #CAMERA_HEIGHT})
 * @param headingDeg         true heading of the optical axis, degrees clockwise from north ({@value #HEADING})
 * @param declinationDeg     magnetic declination at the photo, degrees east positive ({@value #DECLINATION}): makes
 *                           a magnetic EXIF direction true (true = magnetic + declination)
 * @param pitchDeg           pitch of the optical axis, degrees, positive up ({@value #PITCH})
 * @param rollDeg            roll, degrees, positive clockwise as the photographer sees it ({@value #ROLL})
 * @param focalLengthMm      the lens's focal length, mm ({@value #FOCAL}); needs a sensor width
 * @param sensorWidthMm      the sensor's long side, mm ({@value #SENSOR_WIDTH})
 * @param focal35mmMm        35 mm-equivalent focal length (diagonal definition), mm ({@value #FOCAL35})
 * @param horizontalFovDeg   horizontal field of view across the displayed image, degrees ({@value #HFOV})
 * @param distortion         lens distortion to apply to a camera made from the values above; null = none
 * @param calibration        a full OpenCV calibration for the displayed image; wins over every focal value; null =
 *                           none
 */
public record PhotoOverrides(double latDeg, double lonDeg, double altitudeMetres, double offsetMetres,
                             double cameraHeightMetres, double headingDeg, double declinationDeg, double pitchDeg,
                             double rollDeg, double focalLengthMm, double sensorWidthMm, double focal35mmMm,
                             double horizontalFovDeg, LensDistortion distortion, CameraIntrinsics calibration) {
    public static final String LAT = "--lat";
    public static final String LON = "--lon";
    public static final String ALTITUDE = "--altitude-m";
    public static final String OFFSET = "--offset-m";
    public static final String CAMERA_HEIGHT = "--eye-height-m";
    public static final String HEADING = "--heading-deg";
    public static final String DECLINATION = "--declination-deg";
    public static final String PITCH = "--pitch-deg";
    public static final String ROLL = "--roll-deg";
    public static final String FOCAL = "--focal-mm";
    public static final String SENSOR_WIDTH = "--sensor-width-mm";
    public static final String FOCAL35 = "--focal35-mm";
    public static final String HFOV = "--hfov-deg";

    /**
     * Largest magnitude of the angles a user gives (flags, batch columns, XMP), degrees: a heading within a turn either
     * way, a declination and a roll within half a turn, a pitch within straight up and down. Beyond them a value is
     * a typo or garbage (a heading of 1e308), not a direction.
     */
    public static final double HEADING_LIMIT_DEG = 360, DECLINATION_LIMIT_DEG = 180, PITCH_LIMIT_DEG = 90,
            ROLL_LIMIT_DEG = 180;

    private static final double N = Double.NaN;

    /** Nothing overridden. */
    public static final PhotoOverrides NONE = new PhotoOverrides(N, N, N, N, N, N, N, N, N, N, N, N, N, null, null);

    public PhotoOverrides withPosition(double lat, double lon) {
        return new PhotoOverrides(lat, lon, altitudeMetres, offsetMetres, cameraHeightMetres, headingDeg,
                declinationDeg, pitchDeg, rollDeg, focalLengthMm, sensorWidthMm, focal35mmMm, horizontalFovDeg,
                distortion, calibration);
    }

    public PhotoOverrides withAltitudeMetres(double v) {
        return new PhotoOverrides(latDeg, lonDeg, v, offsetMetres, cameraHeightMetres, headingDeg, declinationDeg,
                pitchDeg, rollDeg, focalLengthMm, sensorWidthMm, focal35mmMm, horizontalFovDeg, distortion, calibration);
    }

    public PhotoOverrides withOffsetMetres(double v) {
        return new PhotoOverrides(latDeg, lonDeg, altitudeMetres, v, cameraHeightMetres, headingDeg, declinationDeg,
                pitchDeg, rollDeg, focalLengthMm, sensorWidthMm, focal35mmMm, horizontalFovDeg, distortion, calibration);
    }

    public PhotoOverrides withCameraHeightMetres(double v) {
        return new PhotoOverrides(latDeg, lonDeg, altitudeMetres, offsetMetres, v, headingDeg, declinationDeg,
                pitchDeg, rollDeg, focalLengthMm, sensorWidthMm, focal35mmMm, horizontalFovDeg, distortion, calibration);
    }

    public PhotoOverrides withHeadingDeg(double v) {
        return new PhotoOverrides(latDeg, lonDeg, altitudeMetres, offsetMetres, cameraHeightMetres, v, declinationDeg,
                pitchDeg, rollDeg, focalLengthMm, sensorWidthMm, focal35mmMm, horizontalFovDeg, distortion, calibration);
    }

    public PhotoOverrides withDeclinationDeg(double v) {
        return new PhotoOverrides(latDeg, lonDeg, altitudeMetres, offsetMetres, cameraHeightMetres, headingDeg, v,
                pitchDeg, rollDeg, focalLengthMm, sensorWidthMm, focal35mmMm, horizontalFovDeg, distortion, calibration);
    }

    public PhotoOverrides withPitchDeg(double v) {
        return new PhotoOverrides(latDeg, lonDeg, altitudeMetres, offsetMetres, cameraHeightMetres, headingDeg,
                declinationDeg, v, rollDeg, focalLengthMm, sensorWidthMm, focal35mmMm, horizontalFovDeg, distortion,
                calibration);
    }

    public PhotoOverrides withRollDeg(double v) {
        return new PhotoOverrides(latDeg, lonDeg, altitudeMetres, offsetMetres, cameraHeightMetres, headingDeg,
                declinationDeg, pitchDeg, v, focalLengthMm, sensorWidthMm, focal35mmMm, horizontalFovDeg, distortion,
                calibration);
    }

    public PhotoOverrides withFocalLengthMm(double v) {
        return new PhotoOverrides(latDeg, lonDeg, altitudeMetres, offsetMetres, cameraHeightMetres, headingDeg,
                declinationDeg, pitchDeg, rollDeg, v, sensorWidthMm, focal35mmMm, horizontalFovDeg, distortion,
                calibration);
    }

    public PhotoOverrides withSensorWidthMm(double v) {
        return new PhotoOverrides(latDeg, lonDeg, altitudeMetres, offsetMetres, cameraHeightMetres, headingDeg,
                declinationDeg, pitchDeg, rollDeg, focalLengthMm, v, focal35mmMm, horizontalFovDeg, distortion,
                calibration);
    }

    public PhotoOverrides withFocal35mmMm(double v) {
        return new PhotoOverrides(latDeg, lonDeg, altitudeMetres, offsetMetres, cameraHeightMetres, headingDeg,
                declinationDeg, pitchDeg, rollDeg, focalLengthMm, sensorWidthMm, v, horizontalFovDeg, distortion,
                calibration);
    }

    public PhotoOverrides withHorizontalFovDeg(double v) {
        return new PhotoOverrides(latDeg, lonDeg, altitudeMetres, offsetMetres, cameraHeightMetres, headingDeg,
                declinationDeg, pitchDeg, rollDeg, focalLengthMm, sensorWidthMm, focal35mmMm, v, distortion,
                calibration);
    }

    public PhotoOverrides withDistortion(LensDistortion v) {
        return new PhotoOverrides(latDeg, lonDeg, altitudeMetres, offsetMetres, cameraHeightMetres, headingDeg,
                declinationDeg, pitchDeg, rollDeg, focalLengthMm, sensorWidthMm, focal35mmMm, horizontalFovDeg, v,
                calibration);
    }

    public PhotoOverrides withCalibration(CameraIntrinsics v) {
        return new PhotoOverrides(latDeg, lonDeg, altitudeMetres, offsetMetres, cameraHeightMetres, headingDeg,
                declinationDeg, pitchDeg, rollDeg, focalLengthMm, sensorWidthMm, focal35mmMm, horizontalFovDeg,
                distortion, v);
    }
}
