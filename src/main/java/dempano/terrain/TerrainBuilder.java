package dempano.terrain;

import com.jme3.bounding.BoundingBox;
import com.jme3.material.Material;
import com.jme3.math.Vector3f;
import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import com.jme3.scene.VertexBuffer;
import com.jme3.terrain.geomipmap.TerrainPatch;
import com.jme3.terrain.geomipmap.TerrainQuad;
import com.jme3.util.BufferUtils;
import dempano.dem.Mosaic;
import dempano.geo.Ellipsoid;
import dempano.geo.LocalFrame;
import dempano.geo.Refraction;
import dempano.geo.Viewpoint;
import java.nio.FloatBuffer;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Map;
import java.util.List;

/**
 * Builds the terrain the GPU draws: the mosaic cut into blocks of {@link #BLOCK_INTERVALS}² cells,
 * each a jME {@link TerrainQuad}, whose vertices are then moved to where the WGS84 ellipsoid puts
 * them relative to the eye (east-north-up in double precision, stored as float relative to the eye,
 * so float rounding is relative: 3 cm at 300 km). jME axes: x = east, y = up, z = south.
 * Refraction lifts each vertex by k·d²/2R. Blocks and patches wholly beyond the range are left out.
 *
 * <p>Each vertex also carries, in its first texture coordinate, the terrain elevation in metres
 * (for colouring).
 */
public final class TerrainBuilder {
    /** Cells per TerrainQuad block side (a power of two). */
    public static final int BLOCK_INTERVALS = 512;
    /** Cells per TerrainPatch side. */
    public static final int PATCH_INTERVALS = 64;

    private TerrainBuilder() {
    }

    /** What was built. */
    public record Terrain(Node root, long vertices, long triangles, int blocks, int patches, int[] patchesPerLevel) {
    }

    /**
     * @param rangeMetres terrain whose ground distance exceeds this is left out (whole patches here;
     *                    the exact cut is made per fragment by the shader)
     */
    public static Terrain build(Mosaic mosaic, Viewpoint eye, Refraction refraction, double rangeMetres, Material material) {
        return build(mosaic, eye, refraction, rangeMetres, material, 1, 0);
    }

    /**
     * As {@link #build(Mosaic, Viewpoint, Refraction, double, Material)}, with each patch simplified
     * as far as {@link LevelOfDetail} allows for a screen error of at most {@code maxErrorPx} pixels
     * at {@code pixelsPerDegree} (0 = full resolution everywhere). Where neighbouring patches differ,
     * vertical skirts as deep as both patches' errors together close the cracks between them.
     */
    public static Terrain build(Mosaic mosaic, Viewpoint eye, Refraction refraction, double rangeMetres, Material material,
                                double pixelsPerDegree, double maxErrorPx) {
        LocalFrame frame = eye.eyeFrame();
        // Foot of the eye on the ellipsoid, for ground distances (refraction).
        double[] eyeFoot = new double[3];
        Ellipsoid.toEcef(eye.latDeg(), eye.lonDeg(), 0, eyeFoot);
        double eyeRow = mosaic.rowOf(eye.latDeg()), eyeCol = mosaic.colOf(eye.lonDeg());
        // Cells of the mosaic that can lie within range (a generous box; exact cut later).
        double metresPerRow = 111_000.0 / mosaic.intervalsPerDegree();
        double metresPerCol = metresPerRow * Math.max(0.01, Math.cos(Math.toRadians(Math.abs(eye.latDeg()) + 1)));
        int r0 = Math.max(0, (int) Math.floor(eyeRow - rangeMetres / metresPerRow * 1.05 - 2));
        int r1 = Math.min(mosaic.rows() - 1, (int) Math.ceil(eyeRow + rangeMetres / metresPerRow * 1.05 + 2));
        int c0 = Math.max(0, (int) Math.floor(eyeCol - rangeMetres / metresPerCol * 1.05 - 2));
        int c1 = Math.min(mosaic.cols() - 1, (int) Math.ceil(eyeCol + rangeMetres / metresPerCol * 1.05 + 2));

        // Per-row and per-column trigonometry, computed once.
        int nr = r1 - r0 + 1, nc = c1 - c0 + 1;
        double[] sinLat = new double[nr], cosLat = new double[nr], sinLon = new double[nc], cosLon = new double[nc];
        for (int r = 0; r < nr; r++) {
            double phi = Math.toRadians(mosaic.latOfRow(r0 + r));
            sinLat[r] = Math.sin(phi);
            cosLat[r] = Math.cos(phi);
        }
        for (int c = 0; c < nc; c++) {
            double lam = Math.toRadians(mosaic.lonOfCol(c0 + c));
            sinLon[c] = Math.sin(lam);
            cosLon[c] = Math.cos(lam);
        }
        VertexPlacer placer = new VertexPlacer(mosaic, frame, eyeFoot, refraction, r0, c0, sinLat, cosLat, sinLon, cosLon);

        Node root = new Node("terrain");
        int b = BLOCK_INTERVALS;
        Map<Long, PatchWork> work = new HashMap<>();
        List<TerrainQuad> quads = new ArrayList<>();
        for (int br = r0; br < r1; br += b) {
            for (int bc = c0; bc < c1; bc += b) {
                // Skip blocks entirely beyond range (nearest block point to the eye, in cells).
                double dr = Math.max(0, Math.max(br - eyeRow, eyeRow - (br + b))) * metresPerRow;
                double dc = Math.max(0, Math.max(bc - eyeCol, eyeCol - (bc + b))) * metresPerCol;
                if (Math.hypot(dr, dc) > rangeMetres * 1.05 + 1000) {
                    continue;
                }
                float[] heights = new float[(b + 1) * (b + 1)];
                for (int i = 0; i <= b; i++) {
                    for (int j = 0; j <= b; j++) {
                        int r = Math.min(br + i, mosaic.rows() - 1), c = Math.min(bc + j, mosaic.cols() - 1);
                        float h = mosaic.sample(r, c);
                        heights[i * (b + 1) + j] = Float.isNaN(h) ? 0f : h; // NaN only beyond range
                    }
                }
                TerrainQuad quad = new TerrainQuad("block-" + br + "-" + bc, PATCH_INTERVALS + 1, b + 1, heights);
                // jME would recompute normals from its flat grid each frame; ours come from the exact positions.
                quad.removeControl(com.jme3.terrain.geomipmap.NormalRecalcControl.class);
                quad.updateGeometricState();
                List<TerrainPatch> ps = new ArrayList<>();
                collectPatches(quad, ps);
                // jME lays the grid out in world units of one cell; find the block's origin to map back.
                float minX = Float.MAX_VALUE, minZ = Float.MAX_VALUE;
                for (TerrainPatch p : ps) {
                    BoundingBox bb = (BoundingBox) p.getWorldBound();
                    minX = Math.min(minX, bb.getCenter().x - bb.getXExtent());
                    minZ = Math.min(minZ, bb.getCenter().z - bb.getZExtent());
                }
                for (TerrainPatch p : ps) {
                    PatchWork w = placer.place(p, br, bc, minX, minZ, heights, b + 1, rangeMetres);
                    if (w == null) {
                        p.removeFromParent();
                        continue;
                    }
                    w.level = LevelOfDetail.chooseLevel(w.deviations, w.nearestMetres, pixelsPerDegree, maxErrorPx);
                    work.put(key(w.row0, w.col0), w);
                }
                zeroTranslations(quad);
                quad.setMaterial(material);
                quads.add(quad);
            }
        }
        long vertices = 0, triangles = 0;
        int patches = 0;
        int[] patchesPerLevel = new int[Integer.numberOfTrailingZeros(PATCH_INTERVALS) + 1];
        for (PatchWork w : work.values()) {
            double neighbours = 0;
            int p = PATCH_INTERVALS;
            for (long k : new long[] {key(w.row0 - p, w.col0), key(w.row0 + p, w.col0), key(w.row0, w.col0 - p),
                    key(w.row0, w.col0 + p)}) {
                PatchWork n = work.get(k);
                if (n != null) {
                    neighbours = Math.max(neighbours, n.errorMetres());
                }
            }
            double skirt = w.errorMetres() + neighbours;
            placer.finish(w, skirt > 0 ? skirt + 0.5 : 0);
            vertices += w.patch.getMesh().getVertexCount();
            triangles += w.patch.getMesh().getTriangleCount();
            patches++;
            patchesPerLevel[w.level]++;
        }
        for (TerrainQuad quad : quads) {
            // Patches were moved: refresh bounds up the tree.
            quad.updateModelBound();
            quad.updateGeometricState();
            root.attachChild(quad);
        }
        int blocks = quads.size();
        root.updateGeometricState();
        return new Terrain(root, vertices, triangles, blocks, patches, patchesPerLevel);
    }

    private static long key(int row, int col) {
        return ((long) row << 32) ^ (col & 0xffffffffL);
    }

    /** A patch between placing (all samples) and meshing (at its level). */
    private static final class PatchWork {
        TerrainPatch patch;
        int row0, col0, side;
        float[] positions, normals, elevations;
        double nearestMetres;
        double[] deviations;
        int level;

        double errorMetres() {
            return deviations[level];
        }
    }

    private static void collectPatches(Spatial s, List<TerrainPatch> out) {
        if (s instanceof TerrainPatch p) {
            out.add(p);
        } else if (s instanceof Node n) {
            for (Spatial c : n.getChildren()) {
                collectPatches(c, out);
            }
        }
    }

    private static void zeroTranslations(Spatial s) {
        s.setLocalTranslation(Vector3f.ZERO);
        s.setLocalScale(1);
        if (s instanceof Node n) {
            for (Spatial c : n.getChildren()) {
                zeroTranslations(c);
            }
        }
    }

    /** Frees the native memory of a built terrain's buffers (the GL side is freed by the renderer). */
    public static void destroyBuffers(Spatial s) {
        if (s instanceof Geometry g) {
            for (VertexBuffer vb : g.getMesh().getBufferList()) {
                if (vb.getData() != null && vb.getData().isDirect()) {
                    BufferUtils.destroyDirectBuffer(vb.getData());
                }
            }
        } else if (s instanceof Node n) {
            for (Spatial c : n.getChildren()) {
                destroyBuffers(c);
            }
        }
    }

    /** Computes exact eye-relative vertex positions and normals for patches. */
    private static final class VertexPlacer {
        private final Mosaic mosaic;
        private final LocalFrame frame;
        private final double[] eyeFoot;
        private final Refraction refraction;
        private final int r0, c0;
        private final double[] sinLat, cosLat, sinLon, cosLon;

        VertexPlacer(Mosaic mosaic, LocalFrame frame, double[] eyeFoot, Refraction refraction, int r0, int c0,
                     double[] sinLat, double[] cosLat, double[] sinLon, double[] cosLon) {
            this.mosaic = mosaic;
            this.frame = frame;
            this.eyeFoot = eyeFoot;
            this.refraction = refraction;
            this.r0 = r0;
            this.c0 = c0;
            this.sinLat = sinLat;
            this.cosLat = cosLat;
            this.sinLon = sinLon;
            this.cosLon = cosLon;
        }

        /** Eye-relative position (jME axes) of a mosaic sample lifted by refraction; returns its ground distance. */
        private double position(int r, int c, double elevationMetres, double dropMetres, double[] foot, double[] enu,
                                float[] out, int at) {
            int ri = Math.max(0, Math.min(sinLat.length - 1, r - r0)), ci = Math.max(0, Math.min(sinLon.length - 1, c - c0));
            Ellipsoid.toEcef(sinLat[ri], cosLat[ri], sinLon[ci], cosLon[ci], 0, foot);
            double ground = Refraction.groundDistanceBetweenFeetMetres(foot, eyeFoot);
            double h = elevationMetres + refraction.liftMetres(ground) - dropMetres;
            // ECEF(φ, λ, h) = ECEF(φ, λ, 0) + h·n̂ with n̂ the ellipsoid normal.
            double ex = foot[0] + h * cosLat[ri] * cosLon[ci];
            double ey = foot[1] + h * cosLat[ri] * sinLon[ci];
            double ez = foot[2] + h * sinLat[ri];
            frame.ecefToEnu(ex, ey, ez, enu);
            out[at] = (float) enu[0];
            out[at + 1] = (float) enu[2];
            out[at + 2] = (float) -enu[1];
            return ground;
        }

        /**
         * Computes a patch's exact positions, normals and elevations at every sample, and the
         * deviations of its coarser levels. Returns null if the whole patch lies beyond range.
         */
        PatchWork place(TerrainPatch p, int blockRow, int blockCol, float minX, float minZ, float[] heights,
                        int blockSamples, double rangeMetres) {
            Mesh mesh = p.getMesh();
            FloatBuffer pos = (FloatBuffer) mesh.getBuffer(VertexBuffer.Type.Position).getData();
            int n = mesh.getVertexCount();
            int side = (int) Math.round(Math.sqrt(n));
            Vector3f t = p.getWorldTranslation();
            // Block-relative row and column of the patch's first (north-west) vertex.
            int gridRow0 = Math.round(pos.get(2) + t.z - minZ), gridCol0 = Math.round(pos.get(0) + t.x - minX);
            float[] out = new float[n * 3];
            float[] elevation = new float[n * 2];
            double[] foot = new double[3], enu = new double[3];
            double nearestGround = Double.POSITIVE_INFINITY, nearest = Double.POSITIVE_INFINITY;
            for (int k = 0; k < n; k++) {
                float x = pos.get(3 * k) + t.x, y = pos.get(3 * k + 1), z = pos.get(3 * k + 2) + t.z;
                int i = Math.round(z - minZ), j = Math.round(x - minX);
                if (side * side != n || i != gridRow0 + k / side || j != gridCol0 + k % side
                        || heights[i * blockSamples + j] != y) {
                    throw new IllegalStateException("jME terrain layout not as expected at vertex " + k);
                }
                int r = Math.min(blockRow + i, mosaic.rows() - 1), c = Math.min(blockCol + j, mosaic.cols() - 1);
                nearestGround = Math.min(nearestGround, position(r, c, y, 0, foot, enu, out, 3 * k));
                nearest = Math.min(nearest, Math.sqrt(enu[0] * enu[0] + enu[1] * enu[1] + enu[2] * enu[2]));
                elevation[2 * k] = y;
            }
            if (nearestGround > rangeMetres + 2000) {
                return null;
            }
            // Normals from the exact positions: central differences over the patch grid.
            float[] normals = new float[n * 3];
            for (int k = 0; k < n; k++) {
                int gi = k / side, gj = k % side;
                int up = (gi > 0 ? k - side : k), down = (gi < side - 1 ? k + side : k);
                int left = (gj > 0 ? k - 1 : k), right = (gj < side - 1 ? k + 1 : k);
                float ax = out[3 * right] - out[3 * left], ay = out[3 * right + 1] - out[3 * left + 1], az = out[3 * right + 2] - out[3 * left + 2];
                float bx = out[3 * down] - out[3 * up], by = out[3 * down + 1] - out[3 * up + 1], bz = out[3 * down + 2] - out[3 * up + 2];
                // (b × a) points up for a = east, b = south.
                float nx = by * az - bz * ay, ny = bz * ax - bx * az, nz = bx * ay - by * ax;
                float len = (float) Math.sqrt(nx * nx + ny * ny + nz * nz);
                if (len == 0) {
                    nx = 0;
                    ny = 1;
                    nz = 0;
                    len = 1;
                }
                normals[3 * k] = nx / len;
                normals[3 * k + 1] = ny / len;
                normals[3 * k + 2] = nz / len;
            }
            PatchWork w = new PatchWork();
            w.patch = p;
            w.row0 = blockRow + gridRow0;
            w.col0 = blockCol + gridCol0;
            w.side = side;
            w.positions = out;
            w.normals = normals;
            w.elevations = elevation;
            w.nearestMetres = nearest;
            w.deviations = LevelOfDetail.deviationsMetres(heights, blockSamples, gridRow0, gridCol0, side - 1);
            return w;
        }

        /**
         * Writes a patch's mesh at its level: every step-th sample, triangles split as
         * {@link Triangulation} says (on the mosaic grid at full resolution, on the coarse grid
         * otherwise), and skirts {@code skirtMetres} deep along its four edges when that is positive.
         */
        void finish(PatchWork w, double skirtMetres) {
            int step = 1 << w.level, side = w.side, cs = (side - 1) / step + 1;
            int edge = 4 * (cs - 1), skirtVertices = skirtMetres > 0 ? edge + 1 : 0;
            int n = cs * cs + skirtVertices;
            float[] positions = new float[n * 3], normals = new float[n * 3], elevations = new float[n * 2];
            for (int gi = 0; gi < cs; gi++) {
                for (int gj = 0; gj < cs; gj++) {
                    int from = gi * step * side + gj * step, to = gi * cs + gj;
                    System.arraycopy(w.positions, 3 * from, positions, 3 * to, 3);
                    System.arraycopy(w.normals, 3 * from, normals, 3 * to, 3);
                    elevations[2 * to] = w.elevations[2 * from];
                }
            }
            int triangles = (cs - 1) * (cs - 1) * 2 + (skirtMetres > 0 ? 2 * edge : 0);
            short[] indices = new short[triangles * 3];
            int at = 0;
            for (int gi = 0; gi < cs - 1; gi++) {
                for (int gj = 0; gj < cs - 1; gj++) {
                    int nw = gi * cs + gj, ne = nw + 1, sw = nw + cs, se = sw + 1;
                    boolean nwToSe = step == 1 ? Triangulation.splitsNorthWestToSouthEast(w.row0 + gi, w.col0 + gj)
                            : Triangulation.splitsNorthWestToSouthEast(gi, gj);
                    // Winding as jME's (counter-clockwise seen from above).
                    if (nwToSe) {
                        at = put(indices, at, se, ne, nw);
                        at = put(indices, at, nw, sw, se);
                    } else {
                        at = put(indices, at, sw, se, ne);
                        at = put(indices, at, sw, ne, nw);
                    }
                }
            }
            if (skirtMetres > 0) {
                // The patch's border, clockwise from the north-west corner, closed; each border vertex
                // gets a twin skirtMetres lower along the ellipsoid normal.
                int[] ring = new int[edge + 1];
                int k = 0;
                for (int j = 0; j < cs - 1; j++) {
                    ring[k++] = j;
                }
                for (int i = 0; i < cs - 1; i++) {
                    ring[k++] = i * cs + cs - 1;
                }
                for (int j = cs - 1; j > 0; j--) {
                    ring[k++] = (cs - 1) * cs + j;
                }
                for (int i = cs - 1; i > 0; i--) {
                    ring[k++] = i * cs;
                }
                ring[k] = ring[0];
                double[] foot = new double[3], enu = new double[3];
                int base = cs * cs;
                for (int e = 0; e <= edge; e++) {
                    int v = ring[e], gi = v / cs, gj = v % cs, twin = base + e;
                    int r = Math.min(w.row0 + gi * step, mosaic.rows() - 1), c = Math.min(w.col0 + gj * step, mosaic.cols() - 1);
                    position(r, c, elevations[2 * v], skirtMetres, foot, enu, positions, 3 * twin);
                    System.arraycopy(normals, 3 * v, normals, 3 * twin, 3);
                    elevations[2 * twin] = elevations[2 * v];
                }
                for (int e = 0; e < edge; e++) {
                    int a = ring[e], b = ring[e + 1], a2 = base + e, b2 = base + e + 1;
                    // Faces are not culled (see OffscreenRenderer), so one winding serves both sides.
                    at = put(indices, at, a, b, b2);
                    at = put(indices, at, a, b2, a2);
                }
            }
            Mesh mesh = w.patch.getMesh();
            mesh.setMode(Mesh.Mode.Triangles);
            VertexBuffer oldIndex = mesh.getBuffer(VertexBuffer.Type.Index);
            if (oldIndex != null) {
                if (oldIndex.getData() != null && oldIndex.getData().isDirect()) {
                    BufferUtils.destroyDirectBuffer(oldIndex.getData());
                }
                mesh.clearBuffer(VertexBuffer.Type.Index);
            }
            mesh.setBuffer(VertexBuffer.Type.Index, 3, BufferUtils.createShortBuffer(indices));
            replace(mesh, VertexBuffer.Type.Position, 3, positions);
            replace(mesh, VertexBuffer.Type.Normal, 3, normals);
            replace(mesh, VertexBuffer.Type.TexCoord, 2, elevations);
            // Buffers the shader does not use: free them now.
            for (VertexBuffer.Type unused : new VertexBuffer.Type[] {VertexBuffer.Type.Tangent, VertexBuffer.Type.Binormal,
                    VertexBuffer.Type.TexCoord2}) {
                if (mesh.getBuffer(unused) != null) {
                    mesh.clearBuffer(unused);
                }
            }
            mesh.updateCounts();
            mesh.updateBound();
            w.patch.setModelBound(mesh.getBound().clone());
            // The full-resolution arrays are no longer needed.
            w.positions = null;
            w.normals = null;
            w.elevations = null;
        }

        private static int put(short[] a, int w, int i, int j, int k) {
            a[w] = (short) i;
            a[w + 1] = (short) j;
            a[w + 2] = (short) k;
            return w + 3;
        }

        private static void replace(Mesh mesh, VertexBuffer.Type type, int components, float[] data) {
            VertexBuffer old = mesh.getBuffer(type);
            if (old != null && old.getData() != null && old.getData().isDirect()) {
                BufferUtils.destroyDirectBuffer(old.getData());
            }
            if (old != null) {
                mesh.clearBuffer(type);
            }
            mesh.setBuffer(type, components, BufferUtils.createFloatBuffer(data));
        }
    }
}
