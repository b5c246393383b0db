package dempano.terrain;

import java.util.Arrays;

/**
 * Gives every triangle of an indexed mesh a provoking vertex of its own, so that a flat
 * per-vertex attribute names the triangle exactly: the terrain shader writes which triangle each
 * fragment belongs to from that attribute instead of {@code gl_PrimitiveID} (which makes Mesa's
 * llvmpipe assemble every primitive separately, 0.35–0.45 s of drawing per panorama).
 *
 * <p>OpenGL takes a flat attribute from a triangle's last vertex (the default provoking-vertex
 * convention). Where a triangle's last vertex already ends an earlier triangle, it ends with a copy
 * instead (a new vertex with the same attributes, so the same position to the bit). The triangles
 * keep their order and their corners' order, so they rasterize and interpolate exactly as before
 * (the order of a triangle's corners changes the rounding of its interpolated attributes), and a
 * triangle's number is its index in the index buffer, as {@code gl_PrimitiveID} counts. On the
 * terrain's grids (diamond split) the vertex count about doubles. Pure arithmetic, no GL.
 *
 * @param indices          the triangles, 3 vertex indices each, in the original order and corner
 *                         order, the last corner replaced by a copy where needed
 * @param source           per vertex of the new mesh, the original vertex it copies
 * @param provokedTriangle per vertex of the new mesh, the triangle it provokes (its index in
 *                         {@code indices} / 3), −1 for none; exact as a float (below 2^24)
 */
public record ProvokingVertices(int[] indices, int[] source, float[] provokedTriangle) {
    /** Most triangles one geometry may hold: their numbers travel as floats, exact below 2^24. */
    public static final int MAX_TRIANGLES = 1 << 24;

    /**
     * @param indices     triangles (3 vertex indices each) over vertices 0..vertexCount−1
     * @param vertexCount vertices of the mesh
     * @throws IllegalArgumentException when the mesh has more than {@link #MAX_TRIANGLES} triangles
     *                                  or an index out of range
     */
    public static ProvokingVertices assign(int[] indices, int vertexCount) {
        int triangles = indices.length / 3;
        if (triangles > MAX_TRIANGLES) {
            throw new IllegalArgumentException(triangles + " triangles: more than 2^24, not exact as floats");
        }
        int[] uses = new int[vertexCount];
        int[] out = new int[indices.length];
        int[] source = new int[vertexCount + triangles];
        float[] provoked = new float[vertexCount + triangles];
        for (int v = 0; v < vertexCount; v++) {
            source[v] = v;
        }
        Arrays.fill(provoked, -1);
        int n = vertexCount;
        for (int t = 0; t < triangles; t++) {
            int o = 3 * t;
            for (int c = 0; c < 3; c++) {
                int v = indices[o + c];
                if (v < 0 || v >= vertexCount) {
                    throw new IllegalArgumentException("index " + v + " outside 0.." + (vertexCount - 1));
                }
                out[o + c] = v;
            }
            int last = indices[o + 2], vertex = last;
            if (uses[last]++ > 0) {
                vertex = n; // the last vertex ends another triangle already: this one ends with a copy
                source[n++] = last;
                out[o + 2] = vertex;
            }
            provoked[vertex] = t;
        }
        return new ProvokingVertices(out, Arrays.copyOf(source, n), Arrays.copyOf(provoked, n));
    }

    /** Vertices of the new mesh. */
    public int vertexCount() {
        return source.length;
    }

    /** A per-vertex attribute of {@code width} floats, extended to the new vertices (copies). */
    public float[] copy(float[] attribute, int width) {
        float[] out = new float[source.length * width];
        for (int v = 0; v < source.length; v++) {
            System.arraycopy(attribute, source[v] * width, out, v * width, width);
        }
        return out;
    }
}
