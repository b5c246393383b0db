package dempano.summits;

/**
 * Where a summit falls in a panorama and whether it is seen.
 *
 * @param summit             the surveyed summit
 * @param azimuthDeg         direction from the eye, degrees clockwise from true north, [0, 360)
 * @param elevationAngleDeg  apparent angle above the eye's horizontal (curvature and refraction applied), degrees
 * @param pixelX             panorama column coordinate (pixel centres at c + 0.5)
 * @param pixelY             panorama row coordinate (row 0's top edge at 0); may lie outside the image
 * @param slantMetres        straight-line distance from the eye to the (refraction-lifted) summit, metres
 * @param groundMetres       geodesic distance on the WGS84 ellipsoid from the viewpoint, metres
 * @param mapDistanceMetres  distance-map value at the summit's pixel (+∞ sky; NaN outside the image)
 * @param seenDistanceMetres distance of the terrain seen at the summit: the first terrain pixel at or
 *                           below the summit's pixel, in the best-matching column of the tolerance
 *                           window (what a person clicking on the peak reads); NaN if none
 * @param visible            true when that terrain is the summit (within the documented tolerance)
 */
public record SummitSighting(Summit summit, double azimuthDeg, double elevationAngleDeg, double pixelX, double pixelY,
                             double slantMetres, double groundMetres, double mapDistanceMetres,
                             double seenDistanceMetres, boolean visible) {
}
