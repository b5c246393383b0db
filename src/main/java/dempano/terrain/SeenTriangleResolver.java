package dempano.terrain;

import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.VertexBuffer;
import com.jme3.scene.mesh.IndexBuffer;
import dempano.panorama.SeenTriangles;
import dempano.panorama.ViewCapture;
import java.nio.FloatBuffer;
import java.nio.ShortBuffer;
import java.util.Arrays;
import java.util.List;
import java.util.stream.IntStream;

/**
 * Turns the views' per-sample surface names (see {@link ViewCapture#triangleIds()} and
 * {@link TerrainBuilder#VERTEX_BASE}: the provoking vertex's number in the scene and the side of it)
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
     * @param captures    views read with surfaces; a null view is left out (its {@code triangleOfSample} null)
     * @param placement   the eye the scene was drawn for
     * @param rangeMetres the shader's range cut
     * @throws IllegalArgumentException when a capture carries no surface identities
     * @throws IllegalStateException    when a mesh breaks {@link TerrainBuilder#VERTEX_BASE}'s contract
     *                                  (a vertex last in three triangles or more)
     */
    public static SeenTriangles resolve(List<Geometry> drawn, ViewCapture[] captures, EyePlacement placement,
                                        double rangeMetres) {
        return new Scene(drawn, placement, rangeMetres).resolve(captures);
    }

    /** Names per block of {@link Scene}'s table that a resolve marks as touched (a power of two). */
    private static final int BLOCK_NAMES = 1024;

    /**
     * One drawn scene's resolver, for views resolved in several calls (the renderer's stitch passes): the table of
     * names and each geometry's {@link Buffers} are made once and kept from call to call, and a call reads and
     * clears only the blocks of the table its views' names fall in (the views of a pass see a small part of the
     * scene). One call at a time; the geometries' buffers must stay alive while it is used.
     */
    public static final class Scene {
        private final List<Geometry> drawn;
        private final EyePlacement placement;
        private final double rangeMetres;
        private final int[] bases;
        private final int totalNames;
        /** Per name: 0 unseen, else (during a call) 1 seen, then its key + 1. All 0 between calls. */
        private final int[] keyOfName;
        /** Per block of BLOCK_NAMES names: whether this call marked one in it. All false between calls. */
        private final boolean[] touched;
        private final Buffers[] buffers;
        private final boolean[] fullResolution;

        public Scene(List<Geometry> drawn, EyePlacement placement, double rangeMetres) {
            this.drawn = drawn;
            this.placement = placement;
            this.rangeMetres = rangeMetres;
            bases = TerrainBuilder.vertexBases(drawn);
            totalNames = 2 * bases[drawn.size()]; // below 2^31: vertexBases allows under 2^30 vertices
            keyOfName = new int[totalNames];
            touched = new boolean[(totalNames + BLOCK_NAMES - 1) / BLOCK_NAMES];
            buffers = new Buffers[drawn.size()];
            fullResolution = new boolean[drawn.size()];
            for (int g = 0; g < drawn.size(); g++) {
                fullResolution[g] = Boolean.TRUE.equals(drawn.get(g).getUserData(TerrainBuilder.FULL_RESOLUTION));
            }
        }

        /** The triangles these views saw (as {@link SeenTriangleResolver#resolve}); null views are left out. */
        public SeenTriangles resolve(ViewCapture[] captures) {
            for (int k = 0; k < captures.length; k++) {
                if (captures[k] != null && captures[k].triangleIds() == null) {
                    throw new IllegalArgumentException("view " + k + " was read without surface identities");
                }
            }
            try {
                return resolveMarked(captures);
            } finally {
                clearTouched();
            }
        }

        private SeenTriangles resolveMarked(ViewCapture[] captures) {
            int totalNames = this.totalNames;
            int[] keyOfName = this.keyOfName;
            boolean[] touched = this.touched;
            // 1. The names seen, per view in parallel (every writer writes 1 or true: the races are benign, and the
            // stream's end makes the writes visible). A name outside the scene (never expected) is not trusted.
            IntStream.range(0, captures.length).filter(k -> captures[k] != null).parallel().forEach(k -> {
                int previous = -1; // neighbouring samples mostly share a triangle
                for (int id : captures[k].triangleIds()) {
                    if (id != previous && id >= 0 && id < totalNames) {
                        keyOfName[id] = 1;
                        touched[id / BLOCK_NAMES] = true;
                        previous = id;
                    }
                }
            });
            // 2. Keys in the order of the names (so the numbering does not depend on the threads), with their
            // geometries. (The serial loops are methods of their own: the JIT then compiles them alone.)
            int[] names = numberKeys(keyOfName, touched);
            int keys = names.length;
            int[] keyName = new int[keys], keyGeometry = new int[keys];
            boolean[] geometrySeen = new boolean[drawn.size()];
            keysToGeometries(names, bases, keyName, keyGeometry, geometrySeen);
            Buffers[] buffers = this.buffers;
            IntStream.range(0, drawn.size()).parallel().filter(g -> geometrySeen[g] && buffers[g] == null)
                    .forEach(g -> buffers[g] = new Buffers(drawn.get(g).getMesh()));
            // 3. Each name to the triangle it names (−1 for none: never expected).
            int[] kg = keyGeometry, kn = keyName;
            int[] primitiveOfKey = new int[keys];
            IntStream.range(0, keys).parallel().forEach(key -> primitiveOfKey[key] = buffers[kg[key]].triangleNamed(kn[key]));
            // 4. Distinct triangles, numbered compactly.
            int[] compactOfKey = new int[keys];
            int[] seenGeometry = new int[Math.max(1, keys)], seenPrimitive = new int[Math.max(1, keys)];
            int seen = distinctTriangles(kg, primitiveOfKey, compactOfKey, seenGeometry, seenPrimitive);
            // 5. Each sample's triangle, per view in parallel.
            int[][] triangleOfSample = new int[captures.length][];
            IntStream.range(0, captures.length).filter(k -> captures[k] != null).parallel().forEach(k -> {
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

        /** Back to all 0 and false, block by touched block. */
        private void clearTouched() {
            for (int b = 0; b < touched.length; b++) {
                if (touched[b]) {
                    java.util.Arrays.fill(keyOfName, b * BLOCK_NAMES, Math.min(totalNames, (b + 1) * BLOCK_NAMES), 0);
                    touched[b] = false;
                }
            }
        }
    }

    /**
     * Numbers the names marked 1 in name order, in place (key + 1; 0 stays "unseen"), in touched blocks; returns
     * the names in key order (the one scan of the table: the geometries are then found from this list).
     */
    private static int[] numberKeys(int[] keyOfName, boolean[] touched) {
        int[] names = new int[1024];
        int keys = 0;
        for (int b = 0; b < touched.length; b++) {
            if (!touched[b]) {
                continue;
            }
            for (int name = b * BLOCK_NAMES, end = Math.min(keyOfName.length, name + BLOCK_NAMES); name < end; name++) {
                if (keyOfName[name] != 0) {
                    if (keys == names.length) {
                        names = Arrays.copyOf(names, 2 * keys);
                    }
                    names[keys] = name;
                    keyOfName[name] = ++keys;
                }
            }
        }
        return Arrays.copyOf(names, keys);
    }

    /** Each key's geometry and its name within it, and which geometries are seen at all ({@code names} ascending). */
    private static void keysToGeometries(int[] names, int[] bases, int[] keyName, int[] keyGeometry, boolean[] geometrySeen) {
        int g = 0;
        for (int key = 0; key < names.length; key++) {
            int name = names[key];
            while ((name >>> 1) >= bases[g + 1]) {
                g++;
            }
            keyGeometry[key] = g;
            keyName[key] = name - 2 * bases[g];
            geometrySeen[g] = true;
        }
    }

    /**
     * Distinct triangles, numbered compactly; returns how many. A triangle is named only through its last vertex
     * (names 2v and 2v + 1), so its keys are adjacent: comparing with the key before finds repeats.
     */
    private static int distinctTriangles(int[] keyGeometry, int[] primitiveOfKey, int[] compactOfKey, int[] seenGeometry,
                                         int[] seenPrimitive) {
        int seen = 0;
        for (int key = 0; key < compactOfKey.length; key++) {
            int g = keyGeometry[key], p = primitiveOfKey[key];
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
        return seen;
    }

    /**
     * A mesh's buffers in the layout {@link TerrainBuilder} writes (read with absolute gets:
     * thread-safe once built), and which triangles end on each vertex.
     */
    private static final class Buffers {
        final FloatBuffer high, low, up;
        /** Per vertex: elevation, flags, grid row, grid column (shorts, see TerrainBuilder.PatchMesh.merge). */
        final ShortBuffer texCoords;
        final IndexBuffer index;
        /** Per vertex, the (at most two) triangles it is the last vertex of, in index order; −1 for none. */
        private final int[] lastOf;

        Buffers(Mesh mesh) {
            high = (FloatBuffer) mesh.getBuffer(VertexBuffer.Type.Position).getData();
            low = (FloatBuffer) mesh.getBuffer(VertexBuffer.Type.TexCoord2).getData();
            up = (FloatBuffer) mesh.getBuffer(VertexBuffer.Type.TexCoord3).getData();
            texCoords = (ShortBuffer) mesh.getBuffer(VertexBuffer.Type.TexCoord).getData();
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
         * The triangle a name (twice the provoking vertex, plus the bit of {@link TerrainBuilder#VERTEX_BASE})
         * names: the vertex's only triangle, or of its two the one on the bit's side. −1 when the vertex ends no
         * triangle.
         */
        int triangleNamed(int name) {
            int v = name >>> 1;
            int first = lastOf[2 * v], second = lastOf[2 * v + 1];
            if (second < 0) {
                return first;
            }
            int bit = name & 1;
            return bitOf(first) == bit || bitOf(second) != bit ? first : second;
        }

        /**
         * The bit the shader writes for samples of a triangle ({@link TerrainBuilder#VERTEX_BASE}): 0 where the
         * naming rule's f, summed over its other two vertices, is positive.
         */
        int bitOf(int p) {
            int last = index.get(3 * p + 2);
            int rule = texCoords.get(4 * last + 1) & TerrainBuilder.NAMED_MASK;
            double row = texCoords.get(4 * last + 2), col = texCoords.get(4 * last + 3), f = 0;
            for (int corner = 0; corner < 2; corner++) {
                int v = index.get(3 * p + corner);
                f += TerrainBuilder.namingSide(rule, texCoords.get(4 * v + 2) - row, texCoords.get(4 * v + 3) - col);
            }
            return f > 0 ? 0 : 1;
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
