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
    public record Terrain(Node root, long vertices, long triangles, int blocks, int patches) {
    }

    /**
     * @param rangeMetres terrain whose ground distance exceeds this is left out (whole patches here;
     *                    the exact cut is made per fragment by the shader)
     */
    public static Terrain build(Mosaic mosaic, Viewpoint eye, Refraction refraction, double rangeMetres, Material material) {
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
        long vertices = 0, triangles = 0;
        int blocks = 0, patches = 0;
        int b = BLOCK_INTERVALS;
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
                    boolean keep = placer.place(p, br, bc, minX, minZ, heights, b + 1, rangeMetres);
                    if (!keep) {
                        p.removeFromParent();
                        continue;
                    }
                    vertices += p.getMesh().getVertexCount();
                    triangles += p.getMesh().getTriangleCount();
                    patches++;
                }
                zeroTranslations(quad);
                quad.setMaterial(material);
                // Patches were moved: refresh bounds up the tree.
                quad.updateModelBound();
                quad.updateGeometricState();
                root.attachChild(quad);
                blocks++;
            }
        }
        root.updateGeometricState();
        return new Terrain(root, vertices, triangles, blocks, patches);
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

        /**
         * Rewrites a patch's positions, normals and texture coordinates. Returns false if the whole
         * patch lies beyond range.
         */
        boolean place(TerrainPatch p, int blockRow, int blockCol, float minX, float minZ, float[] heights,
                      int blockSamples, double rangeMetres) {
            Mesh mesh = p.getMesh();
            FloatBuffer pos = (FloatBuffer) mesh.getBuffer(VertexBuffer.Type.Position).getData();
            int n = mesh.getVertexCount();
            Vector3f t = p.getWorldTranslation();
            float[] out = new float[n * 3];
            float[] elevation = new float[n * 2];
            int[] rowOf = new int[n], colOf = new int[n];
            double[] foot = new double[3], enu = new double[3];
            double nearest = Double.POSITIVE_INFINITY;
            for (int k = 0; k < n; k++) {
                float x = pos.get(3 * k) + t.x, y = pos.get(3 * k + 1), z = pos.get(3 * k + 2) + t.z;
                int i = Math.round(z - minZ), j = Math.round(x - minX);
                if (i < 0 || j < 0 || i >= blockSamples || j >= blockSamples || heights[i * blockSamples + j] != y) {
                    throw new IllegalStateException("jME terrain layout not as expected at vertex " + k);
                }
                int r = Math.min(blockRow + i, mosaic.rows() - 1), c = Math.min(blockCol + j, mosaic.cols() - 1);
                rowOf[k] = r;
                colOf[k] = c;
                int ri = r - r0, ci = c - c0;
                if (ri < 0 || ci < 0 || ri >= sinLat.length || ci >= sinLon.length) {
                    ri = Math.max(0, Math.min(sinLat.length - 1, ri));
                    ci = Math.max(0, Math.min(sinLon.length - 1, ci));
                }
                Ellipsoid.toEcef(sinLat[ri], cosLat[ri], sinLon[ci], cosLon[ci], 0, foot);
                double ground = Refraction.groundDistanceBetweenFeetMetres(foot, eyeFoot);
                nearest = Math.min(nearest, ground);
                double h = y + refraction.liftMetres(ground);
                // ECEF(φ, λ, h) = ECEF(φ, λ, 0) + h·n̂ with n̂ the ellipsoid normal.
                double ex = foot[0] + h * cosLat[ri] * cosLon[ci];
                double ey = foot[1] + h * cosLat[ri] * sinLon[ci];
                double ez = foot[2] + h * sinLat[ri];
                frame.ecefToEnu(ex, ey, ez, enu);
                out[3 * k] = (float) enu[0];
                out[3 * k + 1] = (float) enu[2];
                out[3 * k + 2] = (float) -enu[1];
                elevation[2 * k] = y;
            }
            if (nearest > rangeMetres + 2000) {
                return false;
            }
            // Block-relative row and column of the patch's first (north-west) vertex.
            int gridRow0 = Math.round(pos.get(2) + t.z - minZ), gridCol0 = Math.round(pos.get(0) + t.x - minX);
            // Normals from the exact positions: central differences over the patch grid.
            int side = (int) Math.round(Math.sqrt(n));
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
            // Our own triangle list (jME's strip splits cells relative to each patch): the split is fixed
            // to the mosaic grid, so the CPU reference can intersect exactly the same surface.
            short[] indices = new short[(side - 1) * (side - 1) * 6];
            int w = 0;
            for (int gi = 0; gi < side - 1; gi++) {
                for (int gj = 0; gj < side - 1; gj++) {
                    int nw = gi * side + gj, ne = nw + 1, sw = nw + side, se = sw + 1;
                    // Winding as jME's (counter-clockwise seen from above).
                    if (Triangulation.splitsNorthWestToSouthEast(blockRow + gridRow0 + gi, blockCol + gridCol0 + gj)) {
                        w = put(indices, w, se, ne, nw);
                        w = put(indices, w, nw, sw, se);
                    } else {
                        w = put(indices, w, sw, se, ne);
                        w = put(indices, w, sw, ne, nw);
                    }
                }
            }
            mesh.setMode(Mesh.Mode.Triangles);
            VertexBuffer oldIndex = mesh.getBuffer(VertexBuffer.Type.Index);
            if (oldIndex != null) {
                if (oldIndex.getData() != null && oldIndex.getData().isDirect()) {
                    BufferUtils.destroyDirectBuffer(oldIndex.getData());
                }
                mesh.clearBuffer(VertexBuffer.Type.Index);
            }
            mesh.setBuffer(VertexBuffer.Type.Index, 3, BufferUtils.createShortBuffer(indices));
            mesh.updateCounts();
            replace(mesh, VertexBuffer.Type.Position, 3, out);
            replace(mesh, VertexBuffer.Type.Normal, 3, normals);
            replace(mesh, VertexBuffer.Type.TexCoord, 2, elevation);
            // Buffers the shader does not use: free them now.
            for (VertexBuffer.Type unused : new VertexBuffer.Type[] {VertexBuffer.Type.Tangent, VertexBuffer.Type.Binormal,
                    VertexBuffer.Type.TexCoord2}) {
                if (mesh.getBuffer(unused) != null) {
                    mesh.clearBuffer(unused);
                }
            }
            mesh.updateBound();
            p.setModelBound(mesh.getBound().clone());
            return true;
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
