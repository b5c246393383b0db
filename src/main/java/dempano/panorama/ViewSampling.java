package dempano.panorama;

import dempano.camera.PanoramaTarget;
import dempano.camera.TargetImage;

/**
 * Where each pixel of a target image samples the rendered views: which view, where in it, and the pixel's own
 * ray. The resampler ({@link Stitcher}) walks a target's pixels through this and nothing else, so a panorama and
 * a camera are resampled by the same code. Thread-safe (a row may be located on any thread).
 */
abstract class ViewSampling {
    /**
     * Locates one target pixel.
     *
     * @param p   receives {px, py, xTan, yTan}: the fractional view pixel (centres at integers, GL rows from the
     *            bottom) and the image-plane coordinates of the pixel's ray at unit depth
     * @param ray receives the pixel's ray in the eye's frame with jME axes (east, up, south), unit length
     * @return the view, or −1 when the pixel has no ray (outside its lens model's domain)
     */
    abstract int locate(int col, int row, double[] p, double[] ray);

    /**
     * The view {@link #locate} gives for every pixel of a column, where that holds for the whole column (an array
     * look-up), else −2: lets a stitch pass skip the columns of other passes' views without visiting their pixels.
     */
    int columnView(int col) {
        return -2;
    }

    /** For a target on a layout: the panorama's own fast walk when both are the ring's, else the general one. */
    static ViewSampling of(TargetImage target, ViewLayout layout) {
        if (target instanceof PanoramaTarget pt && layout.ring()) {
            return new Ring(pt.geometry(), layout);
        }
        return new General(target, layout);
    }

    /**
     * An equirectangular panorama on the horizon ring: per column its view, x in the view and the secant of its
     * angle off the view's axis; a row's y in a view is then tan(elevation)·secant (see {@link ViewLayout#project}).
     */
    private static final class Ring extends ViewSampling {
        private final ViewLayout layout;
        private final int[] viewOfCol;
        private final double[] pxOfCol, xTanOfCol, secOfCol, sinAz, cosAz, tanEl, sinEl, cosEl;
        private final double yScale;

        Ring(PanoramaGeometry g, ViewLayout layout) {
            this.layout = layout;
            int width = g.widthPx();
            viewOfCol = new int[width];
            pxOfCol = new double[width];
            xTanOfCol = new double[width];
            secOfCol = new double[width];
            sinAz = new double[width];
            cosAz = new double[width];
            for (int col = 0; col < width; col++) {
                double az = g.azimuthOfColumn(col);
                sinAz[col] = Math.sin(Math.toRadians(az));
                cosAz[col] = Math.cos(Math.toRadians(az));
                viewOfCol[col] = layout.viewOf(az);
                double[] q = layout.project(viewOfCol[col], az, 0);
                pxOfCol[col] = q[0];
                xTanOfCol[col] = q[2];
                secOfCol[col] = Math.sqrt(1 + q[2] * q[2]);
            }
            int h = g.heightPx();
            tanEl = new double[h];
            sinEl = new double[h];
            cosEl = new double[h];
            for (int row = 0; row < h; row++) {
                double elRad = Math.toRadians(g.elevationOfRow(row));
                tanEl[row] = Math.tan(elRad);
                sinEl[row] = Math.sin(elRad);
                cosEl[row] = Math.cos(elRad);
            }
            yScale = layout.heightPx() / (layout.topTan() - layout.bottomTan());
        }

        @Override
        int columnView(int col) {
            return viewOfCol[col];
        }

        @Override
        int locate(int col, int row, double[] p, double[] ray) {
            double yTan = tanEl[row] * secOfCol[col];
            p[0] = pxOfCol[col];
            p[1] = (yTan - layout.bottomTan()) * yScale - 0.5;
            p[2] = xTanOfCol[col];
            p[3] = yTan;
            ray[0] = cosEl[row] * sinAz[col];
            ray[1] = sinEl[row];
            ray[2] = -cosEl[row] * cosAz[col];
            return viewOfCol[col];
        }
    }

    /** Any target: the pixel's ray from {@link TargetImage#rayOf}, into the view whose axis is nearest it. */
    private static final class General extends ViewSampling {
        private final TargetImage target;
        private final ViewLayout layout;

        General(TargetImage target, ViewLayout layout) {
            this.target = target;
            this.layout = layout;
        }

        @Override
        int locate(int col, int row, double[] p, double[] ray) {
            target.rayOf(col, row, ray);
            double e = ray[0], n = ray[1], u = ray[2];
            if (Double.isNaN(e)) {
                return -1;
            }
            int view = layout.viewOfRay(e, n, u);
            layout.projectRay(view, e, n, u, p);
            if (Double.isNaN(p[0])) {
                return -1;
            }
            ray[0] = e;
            ray[1] = u;
            ray[2] = -n;
            return view;
        }
    }
}
