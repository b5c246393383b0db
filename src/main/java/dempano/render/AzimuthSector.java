package dempano.render;

import com.jme3.bounding.BoundingBox;
import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;

/** The azimuths (degrees clockwise from north) under which a mesh's bounding box is seen from the origin. */
final class AzimuthSector {
    private AzimuthSector() {
    }

    /**
     * {fromDeg, spanDeg}, or null when the box surrounds the eye (seen in every direction). The
     * bound of a terrain geometry ({@link dempano.terrain.TerrainBuilder#EYE_BOUND}) is taken as set;
     * any other mesh's is computed from its vertices, eye-relative.
     */
    static double[] of(Geometry g) {
        Mesh mesh = g.getMesh();
        if (g.getUserData(dempano.terrain.TerrainBuilder.EYE_BOUND) == null) {
            mesh.updateBound();
        }
        BoundingBox b = (BoundingBox) mesh.getBound();
        double x0 = b.getCenter().x - b.getXExtent(), x1 = b.getCenter().x + b.getXExtent();
        double z0 = b.getCenter().z - b.getZExtent(), z1 = b.getCenter().z + b.getZExtent();
        if (x0 <= 0 && x1 >= 0 && z0 <= 0 && z1 >= 0) {
            return null;
        }
        double first = azimuth(x0, z0), lo = 0, hi = 0;
        for (double[] c : new double[][] {{x1, z0}, {x0, z1}, {x1, z1}}) {
            double d = dempano.geo.Angles.wrap180(azimuth(c[0], c[1]) - first);
            lo = Math.min(lo, d);
            hi = Math.max(hi, d);
        }
        return new double[] {first + lo, hi - lo};
    }

    /** True if a sector overlaps [viewFrom, viewFrom + viewSpan] (with a small margin). */
    static boolean overlaps(double[] sector, double viewFrom, double viewSpan) {
        if (sector == null) {
            return true;
        }
        double margin = 0.5;
        double start = dempano.geo.Angles.wrap360(sector[0] - viewFrom); // sector start relative to the view
        double end = start + sector[1];
        return start <= viewSpan + margin || end >= 360 - margin;
    }

    private static double azimuth(double x, double z) {
        return Math.toDegrees(Math.atan2(x, -z)); // x east, -z north
    }
}
