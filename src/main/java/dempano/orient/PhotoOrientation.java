package dempano.orient;

import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
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
 */
public record PhotoOrientation(boolean heading, boolean pitch, boolean roll, boolean hfov) {
    /** Resolution of the panorama matched against, pixels per degree. */
    public static final double PANORAMA_PPD = 10;

    /**
     * What is open: a value is open when supplying it shortens the metadata's list of missing values; the heading
     * also when {@code headingPrior} asks to search around a known heading.
     */
    public static PhotoOrientation open(PhotoMetadata meta, PhotoOverrides o, boolean headingPrior) {
        int missing = meta.missing(o).size();
        return new PhotoOrientation(headingPrior || meta.missing(o.withHeadingDeg(0)).size() < missing,
                meta.missing(o.withPitchDeg(0)).size() < missing, meta.missing(o.withRollDeg(0)).size() < missing,
                meta.missing(o.withHorizontalFovDeg(50)).size() < missing);
    }

    public boolean any() {
        return heading || pitch || roll || hfov;
    }

    /** The open values filled with placeholders, so that the rest of the camera resolves. */
    public PhotoOverrides placeholders(PhotoOverrides o) {
        PhotoOverrides p = o;
        p = heading && Double.isNaN(o.headingDeg()) ? p.withHeadingDeg(0) : p;
        p = pitch ? p.withPitchDeg(0) : p;
        p = roll ? p.withRollDeg(0) : p;
        return hfov ? p.withHorizontalFovDeg(50) : p;
    }

    /** The overrides with the estimate in the open values. */
    public PhotoOverrides apply(PhotoOverrides o, OrientationEstimate e) {
        PhotoOverrides p = o;
        p = heading ? p.withHeadingDeg(e.headingDeg()) : p;
        p = pitch ? p.withPitchDeg(e.pitchDeg()) : p;
        p = roll ? p.withRollDeg(e.rollDeg()) : p;
        return hfov ? p.withHorizontalFovDeg(e.hfovDeg()) : p;
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
     * @param known the camera's resolved values for what is not open: heading (centre of the prior when
     *              {@code headingRangeDeg} is given), pitch, roll, horizontal FOV, degrees
     */
    public Result estimate(PanoramaRenderer renderer, PanoramaRequest settings, BufferedImage photo, double[] known,
                           double headingRangeDeg) {
        dempano.panorama.Panorama pano = renderer.render(settings.withPixelsPerDegree(PANORAMA_PPD)
                .withElevationRange(new ElevationRange(-30, 45, false)).withColour(false).withExactDistances(false));
        OrientationPriors priors = OrientationPriors.NONE;
        if (!heading) {
            priors = priors.withHeading(known[0], 0);
        } else if (!Double.isNaN(headingRangeDeg)) {
            priors = priors.withHeading(known[0], headingRangeDeg);
        }
        priors = pitch ? priors : priors.withPitchDeg(known[1]);
        priors = roll ? priors : priors.withRollDeg(known[2]);
        priors = hfov ? priors : priors.withHfovRangeDeg(known[3], known[3]);
        return match(photo, HorizonProfile.of(pano), SilhouetteField.of(pano), priors);
    }

    /**
     * Finds the photo's skyline and inner edges and matches them against a panorama's skyline profile and depth
     * edges, in the photo {@linkplain MatchImage scaled down} to about the benchmark's size. No GL.
     *
     * @param field the panorama's depth edges; null to match the skyline only
     * @return the estimate, its residual in the photo's own pixels, and the overlay drawn on the matched image
     */
    public static Result match(BufferedImage photo, HorizonProfile profile, SilhouetteField field, OrientationPriors priors) {
        MatchImage m = MatchImage.of(photo);
        Skyline sky = SkylineExtractor.extract(m.image());
        OrientationEstimate e = OrientationEstimator.estimate(sky, PhotoEdges.extract(m.image(), sky), profile, field,
                priors).withResidualScaled(m.scale());
        return new Result(e, OrientationOverlay.draw(m.image(), sky, profile, e), m.image().getWidth(),
                m.image().getHeight());
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
                    + " residual in photo pixels; margin = score of the best other heading minus the best score, below"
                    + " %.2f or fewer than %.0f %% of samples fitting is flagged UNSURE)", String.join(", ", open.names()),
                    e.summary(), matchedWidthPx, matchedHeightPx, OrientationEstimator.UNSURE_MARGIN,
                    100 * OrientationEstimator.UNSURE_INLIER_SHARE);
        }
    }
}
