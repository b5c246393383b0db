package dempano.camera;

/**
 * What the user says about a photograph, overriding its metadata (a CLI's flags): NaN (or null) = not given.
 * The flag names in the constants are the ones {@link PhotoMetadata#missing} tells the user to give.
 *
 * @param placement where the camera stands
 * @param attitude  where it points
 * @param optics    its lens
 */
public record PhotoOverrides(Placement placement, Attitude attitude, Optics optics) {
    /**
     * Where the camera stands.
     *
     * @param latDeg             camera latitude, degrees ({@value #LAT})
     * @param lonDeg             camera longitude, degrees ({@value #LON})
     * @param altitudeMetres     absolute standing altitude, metres above sea level ({@value #ALTITUDE})
     * @param offsetMetres       stand on the DEM corrected by this signed offset, metres ({@value #OFFSET}); wins over
     *                           the EXIF GPS altitude
     * @param cameraHeightMetres camera above the standing altitude, metres ({@value #CAMERA_HEIGHT})
     */
    public record Placement(double latDeg, double lonDeg, double altitudeMetres, double offsetMetres,
                            double cameraHeightMetres) {
        public static final Placement NONE = new Placement(N, N, N, N, N);
    }

    /**
     * Where the camera points.
     *
     * @param headingDeg     true heading of the optical axis, degrees clockwise from north ({@value #HEADING})
     * @param declinationDeg magnetic declination at the photo, degrees east positive ({@value #DECLINATION}): makes a
     *                       magnetic EXIF direction true (true = magnetic + declination)
     * @param pitchDeg       pitch of the optical axis, degrees, positive up ({@value #PITCH})
     * @param rollDeg        roll, degrees, positive clockwise as the photographer sees it ({@value #ROLL})
     */
    public record Attitude(double headingDeg, double declinationDeg, double pitchDeg, double rollDeg) {
        public static final Attitude NONE = new Attitude(N, N, N, N);
    }

    /**
     * The camera's lens.
     *
     * @param focalLengthMm    the lens's focal length, mm ({@value #FOCAL}); needs a sensor width
     * @param sensorWidthMm    the sensor's long side, mm ({@value #SENSOR_WIDTH})
     * @param focal35mmMm      35 mm-equivalent focal length (diagonal definition), mm ({@value #FOCAL35})
     * @param horizontalFovDeg horizontal field of view across the displayed image, degrees ({@value #HFOV})
     * @param distortion       lens distortion to apply to a camera made from the values above; null = none
     * @param calibration      a full OpenCV calibration for the displayed image; wins over every focal value; null =
     *                         none
     */
    public record Optics(double focalLengthMm, double sensorWidthMm, double focal35mmMm, double horizontalFovDeg,
                         LensDistortion distortion, CameraIntrinsics calibration) {
        public static final Optics NONE = new Optics(N, N, N, N, null, null);
    }

    public PhotoOverrides {
        placement = placement == null ? Placement.NONE : placement;
        attitude = attitude == null ? Attitude.NONE : attitude;
        optics = optics == null ? Optics.NONE : optics;
    }

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
    public static final PhotoOverrides NONE = new PhotoOverrides(Placement.NONE, Attitude.NONE, Optics.NONE);

    // The values, read directly.

    public double latDeg() {
        return placement.latDeg();
    }

    public double lonDeg() {
        return placement.lonDeg();
    }

    public double altitudeMetres() {
        return placement.altitudeMetres();
    }

    public double offsetMetres() {
        return placement.offsetMetres();
    }

    public double cameraHeightMetres() {
        return placement.cameraHeightMetres();
    }

    public double headingDeg() {
        return attitude.headingDeg();
    }

    public double declinationDeg() {
        return attitude.declinationDeg();
    }

    public double pitchDeg() {
        return attitude.pitchDeg();
    }

    public double rollDeg() {
        return attitude.rollDeg();
    }

    public double focalLengthMm() {
        return optics.focalLengthMm();
    }

    public double sensorWidthMm() {
        return optics.sensorWidthMm();
    }

    public double focal35mmMm() {
        return optics.focal35mmMm();
    }

    public double horizontalFovDeg() {
        return optics.horizontalFovDeg();
    }

    public LensDistortion distortion() {
        return optics.distortion();
    }

    public CameraIntrinsics calibration() {
        return optics.calibration();
    }

    /** The ways of giving the lens, in the order of precedence {@link PhotoMetadata#resolve} takes them. */
    public enum Lens { FIELD_OF_VIEW, FOCAL35, FOCAL_LENGTH_AND_SENSOR, CALIBRATION }

    /**
     * The lens values given ({@link #HFOV}, {@link #FOCAL35}, {@link #FOCAL}/{@link #SENSOR_WIDTH} either or both, a
     * calibration), in order of precedence. More than one leaves all but the first unused: callers refuse that,
     * naming the values as the user gave them (flags, or batch columns).
     */
    public java.util.List<Lens> lensesGiven() {
        java.util.List<Lens> given = new java.util.ArrayList<>();
        if (!Double.isNaN(horizontalFovDeg())) {
            given.add(Lens.FIELD_OF_VIEW);
        }
        if (!Double.isNaN(focal35mmMm())) {
            given.add(Lens.FOCAL35);
        }
        if (!Double.isNaN(focalLengthMm()) || !Double.isNaN(sensorWidthMm())) {
            given.add(Lens.FOCAL_LENGTH_AND_SENSOR);
        }
        if (calibration() != null) {
            given.add(Lens.CALIBRATION);
        }
        return given;
    }

    // Single values.

    public PhotoOverrides withPosition(double lat, double lon) {
        Placement p = placement;
        return new PhotoOverrides(new Placement(lat, lon, p.altitudeMetres(), p.offsetMetres(), p.cameraHeightMetres()),
                attitude, optics);
    }

    public PhotoOverrides withAltitudeMetres(double v) {
        Placement p = placement;
        return new PhotoOverrides(new Placement(p.latDeg(), p.lonDeg(), v, p.offsetMetres(), p.cameraHeightMetres()),
                attitude, optics);
    }

    public PhotoOverrides withOffsetMetres(double v) {
        Placement p = placement;
        return new PhotoOverrides(new Placement(p.latDeg(), p.lonDeg(), p.altitudeMetres(), v, p.cameraHeightMetres()),
                attitude, optics);
    }

    public PhotoOverrides withCameraHeightMetres(double v) {
        Placement p = placement;
        return new PhotoOverrides(new Placement(p.latDeg(), p.lonDeg(), p.altitudeMetres(), p.offsetMetres(), v),
                attitude, optics);
    }

    public PhotoOverrides withHeadingDeg(double v) {
        Attitude a = attitude;
        return new PhotoOverrides(placement, new Attitude(v, a.declinationDeg(), a.pitchDeg(), a.rollDeg()), optics);
    }

    public PhotoOverrides withDeclinationDeg(double v) {
        Attitude a = attitude;
        return new PhotoOverrides(placement, new Attitude(a.headingDeg(), v, a.pitchDeg(), a.rollDeg()), optics);
    }

    public PhotoOverrides withPitchDeg(double v) {
        Attitude a = attitude;
        return new PhotoOverrides(placement, new Attitude(a.headingDeg(), a.declinationDeg(), v, a.rollDeg()), optics);
    }

    public PhotoOverrides withRollDeg(double v) {
        Attitude a = attitude;
        return new PhotoOverrides(placement, new Attitude(a.headingDeg(), a.declinationDeg(), a.pitchDeg(), v), optics);
    }

    public PhotoOverrides withFocalLengthMm(double v) {
        Optics o = optics;
        return new PhotoOverrides(placement, attitude, new Optics(v, o.sensorWidthMm(), o.focal35mmMm(),
                o.horizontalFovDeg(), o.distortion(), o.calibration()));
    }

    public PhotoOverrides withSensorWidthMm(double v) {
        Optics o = optics;
        return new PhotoOverrides(placement, attitude, new Optics(o.focalLengthMm(), v, o.focal35mmMm(),
                o.horizontalFovDeg(), o.distortion(), o.calibration()));
    }

    public PhotoOverrides withFocal35mmMm(double v) {
        Optics o = optics;
        return new PhotoOverrides(placement, attitude, new Optics(o.focalLengthMm(), o.sensorWidthMm(), v,
                o.horizontalFovDeg(), o.distortion(), o.calibration()));
    }

    public PhotoOverrides withHorizontalFovDeg(double v) {
        Optics o = optics;
        return new PhotoOverrides(placement, attitude, new Optics(o.focalLengthMm(), o.sensorWidthMm(), o.focal35mmMm(),
                v, o.distortion(), o.calibration()));
    }

    public PhotoOverrides withDistortion(LensDistortion v) {
        Optics o = optics;
        return new PhotoOverrides(placement, attitude, new Optics(o.focalLengthMm(), o.sensorWidthMm(), o.focal35mmMm(),
                o.horizontalFovDeg(), v, o.calibration()));
    }

    public PhotoOverrides withCalibration(CameraIntrinsics v) {
        Optics o = optics;
        return new PhotoOverrides(placement, attitude, new Optics(o.focalLengthMm(), o.sensorWidthMm(), o.focal35mmMm(),
                o.horizontalFovDeg(), o.distortion(), v));
    }
}
