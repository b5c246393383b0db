package dempano.camera;

import dempano.panorama.PanoramaGeometry;

/**
 * An equirectangular panorama as a {@link TargetImage}. {@link PanoramaGeometry} puts column c's centre at
 * azimuth (c + 0.5)/ppd and row r's centre at elevation top − (r + 0.5)/ppd; in the OpenCV pixel convention of
 * {@link TargetImage} (pixel centres at whole numbers) that is azimuth = (px + 0.5)/ppd degrees clockwise from
 * north and elevation = top − (py + 0.5)/ppd degrees above the horizontal. {@link #pixelOf} wraps the azimuth
 * so px lies in [−0.5, w − 0.5); elevations off the covered range give rows off the image. Straight up or down
 * has azimuth 0 (its column is arbitrary).
 *
 * @param geometry the panorama's layout
 */
public record PanoramaTarget(PanoramaGeometry geometry) implements TargetImage {
    public PanoramaTarget {
        if (geometry == null) {
            throw new IllegalArgumentException("a panorama target needs a geometry");
        }
    }

    @Override
    public int widthPx() {
        return geometry.widthPx();
    }

    @Override
    public int heightPx() {
        return geometry.heightPx();
    }

    @Override
    public void rayOf(double px, double py, double[] out) {
        double ppd = geometry.pixelsPerDegree();
        double az = Math.toRadians((px + 0.5) / ppd);
        double el = Math.toRadians(geometry.topElevationDeg() - (py + 0.5) / ppd);
        if (!Double.isFinite(az) || !Double.isFinite(el)) {
            out[0] = out[1] = out[2] = Double.NaN;
            return;
        }
        double ce = Math.cos(el);
        out[0] = Math.sin(az) * ce;
        out[1] = Math.cos(az) * ce;
        out[2] = Math.sin(el);
    }

    @Override
    public void pixelOf(double east, double north, double up, double[] out) {
        double horizontal = Math.hypot(east, north);
        if (!(horizontal > 0 || up != 0) || !Double.isFinite(horizontal) || !Double.isFinite(up)) {
            out[0] = out[1] = Double.NaN;
            return;
        }
        double ppd = geometry.pixelsPerDegree();
        double az = Math.toDegrees(Math.atan2(east, north));
        double px = dempano.geo.Angles.wrap360(az) * ppd - 0.5;
        int w = geometry.widthPx();
        if (px >= w - 0.5) {
            px -= w;
        }
        double el = Math.toDegrees(Math.atan2(up, horizontal));
        out[0] = px;
        out[1] = (geometry.topElevationDeg() - el) * ppd - 0.5;
    }
}
