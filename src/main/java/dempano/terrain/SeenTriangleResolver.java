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
 * Turns the views' per-sample surface names (see {@link ViewCapture#triangleIds()} and
 * {@link TerrainBuilder#VERTEX_BASE}: the provoking vertex's number in the scene and the facing)
 * into {@link SeenTriangles}: each distinct triangle seen, its
 * vertices read from the geometry's own buffers (ECEF double-single, exact to micrometres) and
 * placed as the shader places them, in double precision ({@link EyePlacement#place}). Must run while
 * the geometries' buffers are alive (before they are released).
 */
public final class SeenTriangleResolver {
    private SeenTriangleResolver() {
    }

    /**
     * @param drawn       the scene's geometries, in the order of their {@link TerrainBuilder#VERTEX_BASE}
     * @param captures    views read with surfaces
     * @param placement   the eye the scene was drawn for
     * @param rangeMetres the shader's range cut
     * @throws IllegalArgumentException when a capture carries no surface identities
     * @throws IllegalStateException    when a mesh breaks {@link TerrainBuilder#VERTEX_BASE}'s contract
     *                                  (a vertex last in three triangles or more)
     */
    public static SeenTriangles resolve(List<Geometry> drawn, ViewCapture[] captures, EyePlacement placement,
                                        double rangeMetres) {
        int[] bases = TerrainBuilder.vertexBases(drawn);
        int totalNames = 2 * bases[drawn.size()]; // below 2^31: vertexBases allows under 2^30 vertices
        for (int k = 0; k < captures.length; k++) {
            if (captures[k].triangleIds() == null) {
                throw new IllegalArgumentException("view " + k + " was read without surface identities");
            }
        }
        // 1. The names seen, per view in parallel (every writer writes 1: the races are benign, and the
        // stream's end makes the writes visible). A name outside the scene (never expected) is not trusted.
        int[] keyOfName = new int[totalNames];
        IntStream.range(0, captures.length).parallel().forEach(k -> {
            int previous = -1; // neighbouring samples mostly share a triangle
            for (int id : captures[k].triangleIds()) {
                if (id != previous && id >= 0 && id < totalNames) {
                    keyOfName[id] = 1;
                    previous = id;
                }
            }
        });
        // 2. Keys in the order of the names (so the numbering does not depend on the threads), with their geometries.
        int keys = 0;
        for (int name = 0; name < totalNames; name++) {
            if (keyOfName[name] != 0) {
                keyOfName[name] = ++keys; // key + 1, so that 0 stays "unseen"
            }
        }
        int[] keyName = new int[keys], keyGeometry = new int[keys];
        boolean[] geometrySeen = new boolean[drawn.size()];
        for (int name = 0, g = 0; name < totalNames; name++) {
            if (keyOfName[name] != 0) {
                while ((name >>> 1) >= bases[g + 1]) {
                    g++;
                }
                int key = keyOfName[name] - 1;
                keyGeometry[key] = g;
                keyName[key] = name - 2 * bases[g];
                geometrySeen[g] = true;
            }
        }
        Buffers[] buffers = new Buffers[drawn.size()];
        IntStream.range(0, drawn.size()).parallel().filter(g -> geometrySeen[g])
                .forEach(g -> buffers[g] = new Buffers(drawn.get(g).getMesh()));
        // 3. Each name to the triangle it names (−1 for none: never expected).
        int[] kg = keyGeometry, kn = keyName;
        int[] primitiveOfKey = new int[keys];
        double[] eye = placement.eyeEcef();
        IntStream.range(0, keys).parallel().forEach(key -> primitiveOfKey[key] = buffers[kg[key]].triangleNamed(kn[key], placement, eye));
        // 4. Distinct triangles, numbered compactly. A triangle is named only through its last vertex
        // (names 2v and 2v + 1), so its keys are adjacent: comparing with the key before finds repeats.
        int[] compactOfKey = new int[keys];
        int[] seenGeometry = new int[Math.max(1, keys)], seenPrimitive = new int[Math.max(1, keys)];
        int seen = 0;
        for (int key = 0; key < keys; key++) {
            int g = kg[key], p = primitiveOfKey[key];
            if (p < 0) {
                compactOfKey[key] = -1;
            } else if (seen > 0 && seenGeometry[seen - 1] == g && seenPrimitive[seen - 1] == p) {
                compactOfKey[key] = seen - 1;
            } else {
                seenGeometry[seen] = g;
                seenPrimitive[seen] = p;
                compactOfKey[key] = seen++;
            }
        }
        // 5. Each sample's triangle, per view in parallel.
        int[][] triangleOfSample = new int[captures.length][];
        IntStream.range(0, captures.length).parallel().forEach(k -> {
            int[] ids = captures[k].triangleIds();
            int[] out = new int[ids.length];
            int previousId = -1, previous = -1; // neighbouring samples mostly share a triangle: look up each run once
            for (int i = 0; i < ids.length; i++) {
                int id = ids[i];
                if (id != previousId) {
                    previousId = id;
                    previous = id >= 0 && id < totalNames ? compactOfKey[keyOfName[id] - 1] : -1;
                }
                out[i] = previous;
            }
            triangleOfSample[k] = out;
        });
        double[] corners = new double[seen * 9];
        boolean[] skirt = new boolean[seen], simplified = new boolean[seen];
        boolean[] fullResolution = new boolean[drawn.size()];
        for (int g = 0; g < drawn.size(); g++) {
            fullResolution[g] = Boolean.TRUE.equals(drawn.get(g).getUserData(TerrainBuilder.FULL_RESOLUTION));
        }
        int[] sg = seenGeometry, sp = seenPrimitive;
        IntStream.range(0, seen).parallel().forEach(t -> {
            double[] v = new double[9];
            Buffers b = buffers[sg[t]];
            int p = sp[t];
            b.place(p, placement, v);
            simplified[t] = !fullResolution[sg[t]];
            int i = b.index.get(3 * p), j = b.index.get(3 * p + 1), k = b.index.get(3 * p + 2);
            skirt[t] = b.sameFoot(i, j) || b.sameFoot(j, k) || b.sameFoot(i, k);
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

    /**
     * A mesh's buffers in the layout {@link TerrainBuilder} writes (read with absolute gets:
     * thread-safe once built), and which triangles end on each vertex.
     */
    private static final class Buffers {
        final FloatBuffer high, low, up;
        final IndexBuffer index;
        /** Per vertex, the (at most two) triangles it is the last vertex of, in index order; −1 for none. */
        private final int[] lastOf;

        Buffers(Mesh mesh) {
            high = (FloatBuffer) mesh.getBuffer(VertexBuffer.Type.Position).getData();
            low = (FloatBuffer) mesh.getBuffer(VertexBuffer.Type.TexCoord2).getData();
            up = (FloatBuffer) mesh.getBuffer(VertexBuffer.Type.TexCoord3).getData();
            index = mesh.getIndexBuffer();
            int triangles = index.size() / 3;
            lastOf = new int[2 * mesh.getVertexCount()];
            Arrays.fill(lastOf, -1);
            for (int p = 0; p < triangles; p++) {
                int v = index.get(3 * p + 2);
                if (lastOf[2 * v] < 0) {
                    lastOf[2 * v] = p;
                } else if (lastOf[2 * v + 1] < 0) {
                    lastOf[2 * v + 1] = p;
                } else {
                    throw new IllegalStateException("vertex " + v + " is the last vertex of three triangles or more ("
                            + lastOf[2 * v] + ", " + lastOf[2 * v + 1] + ", " + p + "): the shader's names are ambiguous");
                }
            }
        }

        /**
         * The triangle a name (twice the provoking vertex, plus 1 when seen from its back) names:
         * the vertex's only triangle, or of its two (wound oppositely) the one that shows the eye
         * the side it was seen from; where both or neither do (the eye above one's plane and below
         * the other's, or in one's plane), the one wound counter-clockwise seen from above when
         * seen from the front, the clockwise one when from the back (terrain is mostly seen from
         * above). −1 when the vertex ends no triangle.
         */
        int triangleNamed(int name, EyePlacement placement, double[] eye) {
            int v = name >>> 1;
            int first = lastOf[2 * v], second = lastOf[2 * v + 1];
            if (second < 0) {
                return first;
            }
            boolean back = (name & 1) != 0;
            // GL's rule: wound counter-clockwise on screen is the front.
            double f = facingTheEye(first, placement, eye), s = facingTheEye(second, placement, eye);
            boolean firstFits = back ? f < 0 : f > 0, secondFits = back ? s < 0 : s > 0;
            if (firstFits != secondFits) {
                return firstFits ? first : second;
            }
            double a = windingSeenFromAbove(first), b = windingSeenFromAbove(second);
            if (a > 0 && b < 0) {
                return back ? second : first;
            }
            if (a < 0 && b > 0) {
                return back ? first : second;
            }
            return first; // a degenerate cell (beyond the mosaic's edge), or walls edge-on: either serves
        }

        /**
         * The sign of {@link #facingTheEyePlaced}, from the vertices as stored (ECEF, no lift) where
         * that is beyond doubt: refraction lifts a vertex d metres away by k·d²/2R, which moves a
         * triangle's plane at the eye by less than 4·|k|·d²/2R (lift and tilt); only closer to the
         * plane than that (grazing incidence) are the vertices placed as the shader places them.
         *
         * @param eye the eye, ECEF metres
         */
        private double facingTheEye(int p, EyePlacement placement, double[] eye) {
            double[] q = ecefNormal(p);
            double nx = q[3], ny = q[4], nz = q[5];
            double tx = eye[0] - q[0], ty = eye[1] - q[1], tz = eye[2] - q[2];
            double facing = nx * tx + ny * ty + nz * tz;
            double squared = tx * tx + ty * ty + tz * tz;
            double doubt = (4 * Math.abs(placement.liftPerSquareMetre()) * squared + 1)
                    * Math.sqrt(nx * nx + ny * ny + nz * nz);
            return Math.abs(facing) > doubt ? facing : facingTheEyePlaced(p, placement);
        }

        /**
         * Positive when a triangle, placed for the eye, turns its front (the side from which it is
         * wound counter-clockwise) to the eye; negative for its back, 0 edge-on.
         */
        private double facingTheEyePlaced(int p, EyePlacement placement) {
            double[] v = new double[9];
            place(p, placement, v);
            double e1x = v[3] - v[0], e1y = v[4] - v[1], e1z = v[5] - v[2];
            double e2x = v[6] - v[0], e2y = v[7] - v[1], e2z = v[8] - v[2];
            double nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
            return -(nx * v[0] + ny * v[1] + nz * v[2]); // n · (eye − first vertex), the eye at the origin
        }

        /**
         * Positive for a triangle wound counter-clockwise seen from above (along its first vertex's
         * ellipsoid normal), negative for clockwise, 0 for none (degenerate). ECEF in double.
         */
        private double windingSeenFromAbove(int p) {
            double[] q = ecefNormal(p);
            int a = 4 * index.get(3 * p);
            return q[3] * up.get(a) + q[4] * up.get(a + 1) + q[5] * up.get(a + 2);
        }

        /** A triangle's first vertex and the cross product of its edges (drawn order), ECEF in double: 6 values. */
        private double[] ecefNormal(int p) {
            int a = index.get(3 * p), b = index.get(3 * p + 1), c = index.get(3 * p + 2);
            double ax = at(3 * a), ay = at(3 * a + 1), az = at(3 * a + 2);
            double e1x = at(3 * b) - ax, e1y = at(3 * b + 1) - ay, e1z = at(3 * b + 2) - az;
            double e2x = at(3 * c) - ax, e2y = at(3 * c + 1) - ay, e2z = at(3 * c + 2) - az;
            return new double[] {ax, ay, az, e1y * e2z - e1z * e2y, e1z * e2x - e1x * e2z, e1x * e2y - e1y * e2x};
        }

        /** A triangle's three vertices placed as the shader places them (eye frame, double) into {@code v[0..8]}. */
        void place(int p, EyePlacement placement, double[] v) {
            double[] ecef = new double[3], normal = new double[3];
            for (int corner = 0; corner < 3; corner++) {
                int vertex = index.get(3 * p + corner);
                for (int a = 0; a < 3; a++) {
                    ecef[a] = at(3 * vertex + a);
                    normal[a] = up.get(4 * vertex + a);
                }
                placement.place(ecef, normal, up.get(4 * vertex + 3), v, 3 * corner);
            }
        }

        /** Component i of the stored positions: the double a double-single pair holds. */
        private double at(int i) {
            return high.get(i) + (double) low.get(i);
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
