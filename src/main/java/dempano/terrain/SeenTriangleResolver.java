package dempano.terrain;

import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.VertexBuffer;
import com.jme3.scene.mesh.IndexBuffer;
import dempano.panorama.SeenTriangles;
import dempano.panorama.ViewCapture;
import java.nio.FloatBuffer;
import java.util.Arrays;
import java.util.List;
import java.util.stream.IntStream;

/**
 * Turns the views' per-sample surface identities (the scene's triangle numbers; see
 * {@link ViewCapture#triangleIds()} and {@link TerrainBuilder#triangleBases}) into
 * {@link SeenTriangles}: each distinct triangle seen, its
 * vertices read from the geometry's own buffers (ECEF double-single, exact to micrometres) and
 * placed as the shader places them, in double precision ({@link EyePlacement#place}). Must run while
 * the geometries' buffers are alive (before they are released).
 */
public final class SeenTriangleResolver {
    private SeenTriangleResolver() {
    }

    /**
     * @param drawn       the scene's geometries, in the order of their {@link TerrainBuilder#TRIANGLE_BASE}
     * @param captures    views read with surfaces
     * @param placement   the eye the scene was drawn for
     * @param rangeMetres the shader's range cut
     * @throws IllegalArgumentException when a capture carries no surface identities
     */
    public static SeenTriangles resolve(List<Geometry> drawn, ViewCapture[] captures, EyePlacement placement,
                                        double rangeMetres) {
        int[] bases = TerrainBuilder.triangleBases(drawn);
        int total = bases[drawn.size()];
        int[][] compactOf = new int[drawn.size()][]; // per geometry: primitive → compact index, −1 unseen
        int[][] triangleOfSample = new int[captures.length][];
        int[] seenGeometry = new int[1024], seenPrimitive = new int[1024];
        int seen = 0;
        for (int k = 0; k < captures.length; k++) {
            ViewCapture c = captures[k];
            if (c.triangleIds() == null) {
                throw new IllegalArgumentException("view " + k + " was read without surface identities");
            }
            int[] ids = c.triangleIds();
            int[] out = new int[ids.length];
            int g = 0; // the geometry of the previous sample: neighbours mostly share one
            for (int i = 0; i < ids.length; i++) {
                int id = ids[i];
                // An id outside the scene (never expected) is treated as unknown, not trusted.
                if (id < 0 || id >= total) {
                    out[i] = -1;
                    continue;
                }
                if (id < bases[g] || id >= bases[g + 1]) {
                    g = geometryOf(bases, id);
                }
                int p = id - bases[g];
                int[] map = compactOf[g];
                if (map == null) {
                    map = compactOf[g] = new int[bases[g + 1] - bases[g]];
                    Arrays.fill(map, -1);
                }
                int t = map[p];
                if (t < 0) {
                    if (seen == seenGeometry.length) {
                        seenGeometry = Arrays.copyOf(seenGeometry, seen * 2);
                        seenPrimitive = Arrays.copyOf(seenPrimitive, seen * 2);
                    }
                    seenGeometry[seen] = g;
                    seenPrimitive[seen] = p;
                    t = map[p] = seen++;
                }
                out[i] = t;
            }
            triangleOfSample[k] = out;
        }
        double[] corners = new double[seen * 9];
        boolean[] skirt = new boolean[seen], simplified = new boolean[seen];
        boolean[] fullResolution = new boolean[drawn.size()];
        for (int g = 0; g < drawn.size(); g++) {
            fullResolution[g] = Boolean.TRUE.equals(drawn.get(g).getUserData(TerrainBuilder.FULL_RESOLUTION));
        }
        int[] sg = seenGeometry, sp = seenPrimitive;
        Buffers[] buffers = new Buffers[drawn.size()];
        for (int g = 0; g < drawn.size(); g++) {
            if (compactOf[g] != null) {
                buffers[g] = new Buffers(drawn.get(g).getMesh());
            }
        }
        IntStream.range(0, seen).parallel().forEach(t -> {
            double[] ecef = new double[3], up = new double[3], v = new double[9];
            Buffers b = buffers[sg[t]];
            int p = sp[t];
            int[] vertices = new int[3];
            for (int corner = 0; corner < 3; corner++) {
                int vertex = vertices[corner] = b.index.get(3 * p + corner);
                for (int a = 0; a < 3; a++) {
                    ecef[a] = (double) b.high.get(3 * vertex + a) + b.low.get(3 * vertex + a);
                    up[a] = b.up.get(4 * vertex + a);
                }
                placement.place(ecef, up, b.up.get(4 * vertex + 3), v, 3 * corner);
            }
            simplified[t] = !fullResolution[sg[t]];
            skirt[t] = b.sameFoot(vertices[0], vertices[1]) || b.sameFoot(vertices[1], vertices[2]) || b.sameFoot(vertices[0], vertices[2]);
            int o = 9 * t;
            corners[o] = v[0];
            corners[o + 1] = v[1];
            corners[o + 2] = v[2];
            for (int a = 0; a < 3; a++) {
                corners[o + 3 + a] = v[3 + a] - v[a];
                corners[o + 6 + a] = v[6 + a] - v[a];
            }
        });
        return new SeenTriangles(corners, skirt, simplified, triangleOfSample, rangeMetres);
    }

    /** The geometry g with bases[g] ≤ id < bases[g + 1] (0 ≤ id < the total; empty geometries skipped). */
    static int geometryOf(int[] bases, int id) {
        int lo = 0, hi = bases.length - 2; // the answer lies in [lo, hi]
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (bases[mid] <= id) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        return lo;
    }

    /** A mesh's buffers in the layout {@link TerrainBuilder} writes (read with absolute gets: thread-safe). */
    private static final class Buffers {
        final FloatBuffer high, low, up;
        final IndexBuffer index;

        Buffers(Mesh mesh) {
            high = (FloatBuffer) mesh.getBuffer(VertexBuffer.Type.Position).getData();
            low = (FloatBuffer) mesh.getBuffer(VertexBuffer.Type.TexCoord2).getData();
            up = (FloatBuffer) mesh.getBuffer(VertexBuffer.Type.TexCoord3).getData();
            index = mesh.getIndexBuffer();
        }

        /**
         * Whether two vertices stand on one foot at different heights: a skirt's edge, which
         * {@link TerrainBuilder} hangs along the ellipsoid normal below a patch edge (distinct
         * samples have distinct normals, in float too: 90 m turn the normal by 1.4e-5).
         */
        boolean sameFoot(int a, int b) {
            return up.get(4 * a) == up.get(4 * b) && up.get(4 * a + 1) == up.get(4 * b + 1)
                    && up.get(4 * a + 2) == up.get(4 * b + 2) && up.get(4 * a + 3) != up.get(4 * b + 3);
        }
    }
}
