package dempano.summits;

/**
 * Where a summit falls in a panorama and whether it is seen.
 *
 * @param summit             the surveyed summit
 * @param azimuthDeg         direction from the eye, degrees clockwise from true north, [0, 360)
 * @param elevationAngleDeg  apparent angle above the eye's horizontal (curvature and refraction applied), degrees
 * @param pixelX             panorama column coordinate (pixel centres at c + 0.5); in a camera image, OpenCV's (pixel
 *                           i's centre at i), as the camera's P.json declares
 * @param pixelY             panorama row coordinate (row 0's top edge at 0); in a camera image, OpenCV's; may lie
 *                           outside the image
 * @param slantMetres        straight-line distance from the eye to the (refraction-lifted) summit, metres
 * @param groundMetres       geodesic distance on the WGS84 ellipsoid from the viewpoint, metres
 * @param mapDistanceMetres  distance-map value at the summit's pixel (+∞ sky; NaN outside the image)
 * @param seenDistanceMetres distance of the terrain seen at the summit: the first terrain pixel at or
 *                           below the summit's pixel, in the best-matching column of the tolerance
 *                           window (what a person clicking on the peak reads); NaN if none
 * @param visible            true when that terrain is the summit (within the documented tolerance)
 * @param demHeightMetres    the DEM's height at the summit's surveyed position (bilinear between the
 *                           four samples around it), metres; NaN when not looked up (no DEM given, or no
 *                           tile there). Compare with {@code summit().elevationMetres()}: SRTM3 comes out
 *                           some 40 m low on valid data (it averages 90 m cells), far more where it was void
 * @param inFilledVoid       true when one of those four samples was a void the DEM had no height for,
 *                           interpolated by the void fill: there the terrain, not the renderer, is what
 *                           is most likely wrong
 */
public record SummitSighting(Summit summit, double azimuthDeg, double elevationAngleDeg, double pixelX, double pixelY,
                             double slantMetres, double groundMetres, double mapDistanceMetres,
                             double seenDistanceMetres, boolean visible, double demHeightMetres,
                             boolean inFilledVoid) {
    /** A sighting whose DEM height was not looked up (NaN, not in a void). */
    public SummitSighting(Summit summit, double azimuthDeg, double elevationAngleDeg, double pixelX, double pixelY,
                          double slantMetres, double groundMetres, double mapDistanceMetres, double seenDistanceMetres,
                          boolean visible) {
        this(summit, azimuthDeg, elevationAngleDeg, pixelX, pixelY, slantMetres, groundMetres, mapDistanceMetres,
                seenDistanceMetres, visible, Double.NaN, false);
    }

    /** This sighting with the DEM's height at the summit and whether it lies in a filled void. */
    public SummitSighting withDem(double heightMetres, boolean filledVoid) {
        return new SummitSighting(summit, azimuthDeg, elevationAngleDeg, pixelX, pixelY, slantMetres, groundMetres,
                mapDistanceMetres, seenDistanceMetres, visible, heightMetres, filledVoid);
    }
}
