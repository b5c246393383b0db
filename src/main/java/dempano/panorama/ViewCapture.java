package dempano.panorama;

/**
 * What one rendered view gave back, in GL order (row 0 at the bottom).
 *
 * @param view         index of the view (0 = the one starting at north)
 * @param rgba         colour, 4 bytes a pixel; null when colour was not rendered
 * @param depth        per pixel: the depth-buffer value (STANDARD_24, REVERSED_32F) or the range in
 *                     metres written by the shader (SHADER_RANGE, ≤ 0 where nothing was drawn)
 * @param triangleIds  per pixel, which triangle was seen there: twice its provoking vertex's number
 *                     in the scene (see {@code TerrainBuilder.VERTEX_BASE}) plus 1 when seen from
 *                     its back, resolved by {@code SeenTriangleResolver}; −1 for sky; null when not read
 */
public record ViewCapture(int view, byte[] rgba, float[] depth, int[] triangleIds) {
    /** A capture without surface identities. */
    public ViewCapture(int view, byte[] rgba, float[] depth) {
        this(view, rgba, depth, null);
    }
}
