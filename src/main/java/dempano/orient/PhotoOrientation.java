package dempano.orient;

import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.camera.CameraIntrinsics;
import dempano.camera.PhotoMetadata;
import dempano.camera.PhotoOverrides;
import dempano.panorama.ElevationRange;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The photo command's use of the estimator: which of heading, pitch, roll and field of view the flags and the
 * metadata leave open, the 360° panorama to match against, and the overrides that carry the estimate.
 *
 * @param heading whether the heading is estimated
 * @param pitch   whether the pitch is estimated
 * @param roll    whether the roll is estimated
 * @param hfov    whether the horizontal field of view is estimated
 * @param altitude whether the eye's altitude may be refined too (neither an absolute altitude nor an offset was given
 *                by flag): where the skyline's distances constrain it ({@link OrientationEstimate#altitudeOffsetMetres})
 */
public record PhotoOrientation(boolean heading, boolean pitch, boolean roll, boolean hfov, boolean altitude) {
    /** Resolution of the panorama matched against, pixels per degree. */
    public static final double PANORAMA_PPD = 10;

    /**
     * What is open: a value is open when supplying it shortens the metadata's list of missing values; the heading
     * also when {@code headingPrior} asks to search around a known heading; the altitude unless a flag gave it.
     */
    public static PhotoOrientation open(PhotoMetadata meta, PhotoOverrides o, boolean headingPrior) {
        int missing = meta.missing(o).size();
        return new PhotoOrientation(headingPrior || !headingGiven(meta, o),
                meta.missing(o.withPitchDeg(0)).size() < missing, meta.missing(o.withRollDeg(0)).size() < missing,
                meta.missing(o.withHorizontalFovDeg(50)).size() < missing,
                Double.isNaN(o.altitudeMetres()) && Double.isNaN(o.offsetMetres()));
    }

    /** Whether the overrides or the metadata give a heading (a flag, an EXIF compass, an XMP yaw). */
    public static boolean headingGiven(PhotoMetadata meta, PhotoOverrides o) {
        return meta.missing(o.withHeadingDeg(0)).size() == meta.missing(o).size();
    }

    /** Whether anything is estimated: one of the angles (the altitude is refined only with them). */
    public boolean any() {
        return heading || pitch || roll || hfov;
    }

    /**
     * The open values filled with placeholders, so that the rest of the camera resolves. A heading that the flags or
     * the metadata give is kept: with a heading prior it is the centre searched around.
     */
    public PhotoOverrides placeholders(PhotoMetadata meta, PhotoOverrides o) {
        PhotoOverrides p = o;
        p = heading && !headingGiven(meta, o) ? p.withHeadingDeg(0) : p;
        p = pitch ? p.withPitchDeg(0) : p;
        p = roll ? p.withRollDeg(0) : p;
        return hfov ? p.withHorizontalFovDeg(50) : p;
    }

    /**
     * The overrides with the estimate in the open values; an estimated altitude offset moves {@code pose}'s
     * absolute altitude where it has one (EXIF GPS: the camera's own altitude, so the camera height stays that of
     * {@code pose}), else its offset from the DEM.
     */
    public PhotoOverrides apply(PhotoOverrides o, OrientationEstimate e, dempano.camera.CameraPose pose) {
        PhotoOverrides p = o;
        p = heading ? p.withHeadingDeg(e.headingDeg()) : p;
        p = pitch ? p.withPitchDeg(e.pitchDeg()) : p;
        p = roll ? p.withRollDeg(e.rollDeg()) : p;
        if (altitudeEstimated(e)) {
            if (Double.isNaN(pose.altitudeMetres())) {
                p = p.withOffsetMetres(pose.offsetMetres() + e.altitudeOffsetMetres());
            } else {
                p = p.withAltitudeMetres(pose.altitudeMetres() + e.altitudeOffsetMetres());
                p = Double.isNaN(o.cameraHeightMetres()) ? p.withCameraHeightMetres(pose.cameraHeightMetres()) : p;
            }
        }
        return hfov ? p.withHorizontalFovDeg(e.hfovDeg()) : p;
    }

    private boolean altitudeEstimated(OrientationEstimate e) {
        return altitude && e != null && Double.isFinite(e.altitudeOffsetMetres());
    }

    /**
     * The flags whose values {@link #apply} (or, with a null estimate, {@link #placeholders}) passed in as overrides
     * though nobody gave them: for {@link PhotoMetadata#resolve(PhotoOverrides, double, java.util.Set)}, whose
     * provenance then says "heading 235.5° estimated from the skyline", not "… from --heading-deg".
     *
     * @param given    the overrides as the user gave them
     * @param estimate the estimate applied; null: the placeholders before the estimate (no altitude)
     */
    public java.util.Set<String> estimatedFlags(PhotoOverrides given, OrientationEstimate estimate) {
        java.util.Set<String> flags = new java.util.HashSet<>();
        if (heading) {
            flags.add(PhotoOverrides.HEADING);
        }
        if (pitch) {
            flags.add(PhotoOverrides.PITCH);
        }
        if (roll) {
            flags.add(PhotoOverrides.ROLL);
        }
        if (hfov) {
            flags.add(PhotoOverrides.HFOV);
        }
        if (altitudeEstimated(estimate)) {
            flags.add(PhotoOverrides.OFFSET);
            flags.add(PhotoOverrides.ALTITUDE);
            if (Double.isNaN(given.cameraHeightMetres())) { // set by apply() only with an absolute altitude
                flags.add(PhotoOverrides.CAMERA_HEIGHT);
            }
        }
        return java.util.Set.copyOf(flags);
    }

    /** Names of the open values, for messages. */
    public List<String> names() {
        List<String> n = new ArrayList<>();
        if (heading) {
            n.add("heading");
        }
        if (pitch) {
            n.add("pitch");
        }
        if (roll) {
            n.add("roll");
        }
        if (hfov) {
            n.add("field of view");
        }
        return n;
    }

    /**
     * The estimate: renders the 360° panorama at the settings' position (distances only, {@link #PANORAMA_PPD}),
     * and {@linkplain #match matches} the photo against it.
     *
     * @param camera the camera as resolved so far: what is not open is taken from it (its heading is the centre of
     *               the prior when a heading range is given), and its lens (principal point, pixel aspect,
     *               distortion) is matched with; its field of view counts as that of the undistorted image,
     *               (w / 2) / tan(hfov / 2) = fx, as {@code --hfov-deg} does
     * @param ranges the heading range around the camera's heading (NaN: the heading searched all round where open),
     *               and the field-of-view range searched where the field of view is open (none: 15°–100°)
     */
    public Result estimate(PanoramaRenderer renderer, PanoramaRequest settings, BufferedImage photo,
                           dempano.camera.PhotoCamera camera, SearchRanges ranges) {
        PanoramaRequest base = settings.withPixelsPerDegree(PANORAMA_PPD)
                .withElevationRange(new ElevationRange(-30, 45, false)).withColour(false).withExactDistances(false);
        dempano.camera.CameraPose pose = camera.pose();
        OrientationEstimator.RaisedReference raised = altitude ? metres -> reference(renderer.render(
                Double.isNaN(pose.altitudeMetres()) ? base.withOffsetMetres(pose.offsetMetres() + metres)
                        : base.withAltitudeMetres(pose.altitudeMetres() + metres))) : null;
        dempano.camera.CameraOrientation k = pose.orientation();
        CameraIntrinsics lens = camera.intrinsics();
        OrientationPriors priors = OrientationPriors.NONE.withLens(isCentredPinhole(lens) ? null : lens)
                .withAltitudeFree(altitude);
        if (!heading) {
            priors = priors.withHeading(k.headingDeg(), 0);
        } else if (!Double.isNaN(ranges.headingRangeDeg())) {
            priors = priors.withHeading(k.headingDeg(), ranges.headingRangeDeg());
        }
        priors = pitch ? priors : priors.withPitchDeg(k.pitchDeg());
        priors = roll ? priors : priors.withRollDeg(k.rollDeg());
        if (!hfov) {
            double fov = Math.toDegrees(2 * Math.atan(lens.widthPx() / 2.0 / lens.fxPx()));
            priors = priors.withHfovRangeDeg(fov, fov);
        } else if (ranges.hasFovRange()) {
            double[] fov = ranges.hfovRangeDeg(lens.widthPx(), lens.heightPx());
            priors = priors.withHfovRangeDeg(fov[0], fov[1]);
        }
        return match(photo, reference(renderer.render(base)), raised, priors);
    }

    /** What a photo is matched against in a panorama: its skyline (with distances) and depth edges. */
    public static OrientationEstimator.Reference reference(dempano.panorama.Panorama pano) {
        return new OrientationEstimator.Reference(HorizonProfile.of(pano), SilhouetteField.of(pano));
    }

    /** Whether a camera is the estimator's default: no distortion, square pixels, the principal point at the centre. */
    static boolean isCentredPinhole(CameraIntrinsics k) {
        return k.distortion().isNone() && k.fxPx() == k.fyPx() && k.cxPx() == CameraIntrinsics.centre(k.widthPx())
                && k.cyPx() == CameraIntrinsics.centre(k.heightPx());
    }

    /**
     * Finds the photo's skyline and inner edges and matches them against a panorama's skyline profile and depth
     * edges, in the photo {@linkplain MatchImage scaled down} to about the benchmark's size (its lens, if the priors
     * have one at the photo's size, scaled with it). No GL.
     *
     * @param field the panorama's depth edges; null to match the skyline only
     * @return the estimate, its residual in the photo's own pixels, and the overlay drawn on the matched image
     */
    public static Result match(BufferedImage photo, HorizonProfile profile, SilhouetteField field, OrientationPriors priors) {
        return match(photo, new OrientationEstimator.Reference(profile, field), null, priors);
    }

    /**
     * As {@link #match(BufferedImage, HorizonProfile, SilhouetteField, OrientationPriors)}, then, where the priors
     * leave the altitude free and {@code raised} can render the reference from another eye, the estimate refined
     * with the altitude ({@link OrientationEstimator#withAltitude}).
     *
     * @param raised renders the reference from an eye raised by some metres; null: the altitude is not refined
     */
    public static Result match(BufferedImage photo, OrientationEstimator.Reference at0,
                               OrientationEstimator.RaisedReference raised, OrientationPriors priors) {
        MatchImage m = MatchImage.of(photo);
        CameraIntrinsics lens = priors.lens() == null ? null : scaled(priors.lens(), m.image().getWidth(),
                m.image().getHeight());
        OrientationPriors p = priors.withLens(lens);
        Skyline sky = SkylineExtractor.extract(m.image());
        PhotoEdges edges = PhotoEdges.extract(m.image(), sky);
        OrientationEstimate e = OrientationEstimator.estimate(sky, edges, at0.profile(), at0.field(), p);
        HorizonProfile profile = at0.profile();
        if (raised != null && priors.altitudeFree()) {
            java.util.Map<Double, OrientationEstimator.Reference> renders = new java.util.HashMap<>();
            OrientationEstimator.RaisedReference once = metres -> renders.computeIfAbsent(metres, raised::at);
            e = OrientationEstimator.withAltitude(e, sky, edges, at0, once, p);
            if (Double.isFinite(e.altitudeOffsetMetres())) {
                profile = once.at(e.altitudeOffsetMetres()).profile();
            }
        }
        e = e.withResidualScaled(m.scale());
        return new Result(e, OrientationOverlay.draw(m.image(), sky, profile, e, lens), m.image().getWidth(),
                m.image().getHeight());
    }

    /** A camera's intrinsics for the same image resampled to {@code w × h} (OpenCV convention: pixel centres at integers). */
    static CameraIntrinsics scaled(CameraIntrinsics k, int w, int h) {
        if (w == k.widthPx() && h == k.heightPx()) {
            return k;
        }
        double sx = (double) k.widthPx() / w, sy = (double) k.heightPx() / h;
        return new CameraIntrinsics(w, h, k.fxPx() / sx, k.fyPx() / sy, (k.cxPx() + 0.5) / sx - 0.5,
                (k.cyPx() + 0.5) / sy - 0.5, k.distortion());
    }

    /**
     * The fine stage's camera renders: distances only (no colour, no exact distances) with the settings' position,
     * range and refraction, each turned into a skyline profile at the render's own resolution.
     */
    public static CameraSkyline cameraSkyline(PanoramaRenderer renderer, PanoramaRequest settings) {
        PanoramaRequest s = settings.withColour(false).withDistance(true).withExactDistances(false)
                .withLayers(java.util.Set.of());
        return (k, o) -> {
            dempano.camera.CameraPose pose = new dempano.camera.CameraPose(s.latDeg(), s.lonDeg(), s.offsetMetres(),
                    s.altitudeMetres(), s.eyeHeightMetres(), o);
            dempano.CameraImage img = renderer.render(new dempano.CameraRequest(k, pose, s));
            return HorizonProfile.ofCamera(img.distanceArray(), img.view(), OrientationEstimator.finePixelsPerDegree(k));
        };
    }

    /**
     * An estimate and its overlay (rendered skyline in red over the photo's skyline in yellow).
     *
     * @param estimate       the estimate; its residual in the photo's own pixels
     * @param overlay        drawn on the image matched in (the photo, or the photo scaled down to it)
     * @param matchedWidthPx width of the image matched in, pixels
     * @param matchedHeightPx its height, pixels
     */
    public record Result(OrientationEstimate estimate, BufferedImage overlay, int matchedWidthPx, int matchedHeightPx) {
        /** The provenance line of the estimate. */
        public String provenance(PhotoOrientation open) {
            OrientationEstimate e = estimate;
            return String.format(Locale.ROOT, "%s estimated from the skyline: %s (matched in %d × %d px; confidence:"
                    + " residual in photo pixels; margin = score of the best other heading minus the best score;"
                    + " UNSURE when the margin is below %.2f or below %.1f × the best score, fewer than %.0f %% of the"
                    + " samples fit, or a free field of view ends on its search bound)", String.join(", ", open.names())
                            + (Double.isFinite(e.altitudeOffsetMetres()) ? ", eye altitude" : ""),
                    e.summary(), matchedWidthPx, matchedHeightPx, OrientationEstimator.UNSURE_MARGIN,
                    OrientationEstimator.UNSURE_MARGIN_PER_SCORE, 100 * OrientationEstimator.UNSURE_INLIER_SHARE);
        }
    }
}
