package dempano.panorama;

/**
 * What one rendered view gave back, in GL order (row 0 at the bottom).
 *
 * @param view         index of the view (0 = the one starting at north)
 * @param rgba         colour, 4 bytes a pixel; null when colour was not rendered
 * @param depth        per pixel: the depth-buffer value (STANDARD_24, REVERSED_32F) or the range in
 *                     metres written by the shader (SHADER_RANGE, ≤ 0 where nothing was drawn)
 * @param geometryIds  per pixel, which geometry was seen there (the terrain's numbering, see
 *                     {@code TerrainBuilder.Terrain#drawn()}), −1 for sky; null when not read
 * @param primitiveIds per pixel, which triangle of that geometry (its index in the geometry's index
 *                     buffer, in threes), −1 for sky; null when not read
 */
public record ViewCapture(int view, byte[] rgba, float[] depth, int[] geometryIds, int[] primitiveIds) {
    /** A capture without surface identities. */
    public ViewCapture(int view, byte[] rgba, float[] depth) {
        this(view, rgba, depth, null, null);
    }
}
