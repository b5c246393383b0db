package dempano.orient;

import dempano.camera.CameraIntrinsics;
import dempano.camera.CameraOrientation;
import dempano.camera.CameraView;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Path2D;
import java.awt.image.BufferedImage;

/**
 * The match drawn on the photo: the rendered skyline projected with the estimate (red) over the skyline found in
 * the photo (yellow dots), and the estimate as text; when the estimate is unsure, the best other heading's skyline
 * too (cyan, dashed) and its heading, FOV and margin on the top line.
 */
public final class OrientationOverlay {
    private OrientationOverlay() {
    }

    /** The rendered skyline projected into the photo with a pose, over the azimuths the photo spans. */
    static Path2D.Double skylinePath(HorizonProfile profile, OrientationEstimate.Pose pose, int w, int h,
                                     CameraIntrinsics lens) {
        CameraView view = new CameraView(OrientationEstimator.intrinsics(w, h, pose.hfovDeg(), lens),
                new CameraOrientation(pose.headingDeg(), Math.max(-90, Math.min(90, pose.pitchDeg())), pose.rollDeg()));
        // Walk the rendered skyline over the azimuths the photo spans (with a margin for roll).
        double half = pose.hfovDeg() / 2 + 10;
        Path2D.Double path = new Path2D.Double();
        boolean open = false;
        double[] px = new double[2];
        double step = 0.25 / profile.pixelsPerDegree();
        for (double az = pose.headingDeg() - half; az <= pose.headingDeg() + half; az += step) {
            double el = profile.elevationDeg(az);
            double a = Math.toRadians(az), t = Math.toRadians(el);
            view.pixelOf(Math.sin(a) * Math.cos(t), Math.cos(a) * Math.cos(t), Math.sin(t), px);
            boolean in = Double.isFinite(px[0]) && px[0] >= -1 && px[0] <= w && px[1] >= -h && px[1] <= 2 * h;
            if (in && open) {
                path.lineTo(px[0], px[1]);
            } else if (in) {
                path.moveTo(px[0], px[1]);
            }
            open = in;
        }
        return path;
    }

    public static BufferedImage draw(BufferedImage photo, Skyline sky, HorizonProfile profile, OrientationEstimate e) {
        return draw(photo, sky, profile, e, null);
    }

    /** As {@link #draw(BufferedImage, Skyline, HorizonProfile, OrientationEstimate)} for a camera of this shape ({@link OrientationPriors#lens()}). */
    public static BufferedImage draw(BufferedImage photo, Skyline sky, HorizonProfile profile, OrientationEstimate e,
                                     CameraIntrinsics lens) {
        int w = photo.getWidth(), h = photo.getHeight();
        BufferedImage out = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = out.createGraphics();
        g.drawImage(photo, 0, 0, null);
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(Color.YELLOW);
        for (int x = 0; x < w; x += 2) {
            if (!Double.isNaN(sky.row(x))) {
                g.fillRect(x, (int) Math.round(sky.row(x)), 1, 1);
            }
        }
        if (e.unsure() && e.second() != null) {
            // An ambiguous match: the best other heading's skyline too (cyan, dashed), to see what it is confused with.
            g.setColor(new Color(0, 220, 255));
            g.setStroke(new BasicStroke(1.2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND, 1, new float[] {5, 4}, 0));
            g.draw(skylinePath(profile, e.second(), w, h, lens));
        }
        g.setColor(new Color(255, 40, 40));
        g.setStroke(new BasicStroke(1.5f));
        g.draw(skylinePath(profile, e.pose(), w, h, lens));
        g.setColor(new Color(0, 0, 0, 150));
        g.fillRect(0, h - 18, w, 18);
        g.setColor(e.unsure() ? Color.ORANGE : Color.WHITE);
        g.setFont(g.getFont().deriveFont(11f));
        g.drawString(String.format(java.util.Locale.ROOT, "hdg %.2f° pitch %.2f° roll %.2f° hfov %.1f°  res %.1f px  fit %.0f%%%s",
                e.headingDeg(), e.pitchDeg(), e.rollDeg(), e.hfovDeg(), e.residualPx(), 100 * e.inlierShare(),
                e.unsure() ? "  UNSURE" : ""), 4, h - 5);
        if (e.unsure() && e.second() != null) {
            g.setColor(new Color(0, 0, 0, 150));
            g.fillRect(0, 0, w, 16);
            g.setColor(new Color(0, 220, 255));
            g.drawString(String.format(java.util.Locale.ROOT, "2nd: hdg %.2f° hfov %.1f°  margin %.3f",
                    e.second().headingDeg(), e.second().hfovDeg(), e.marginScore()), 4, 12);
        }
        g.dispose();
        return out;
    }
}
