package dempano.panorama;

import java.util.stream.IntStream;

/**
 * Dark lines along silhouettes, so that a person reads which ridge stands in front of which (the
 * thesis's figures draw them the same way). A pixel is on a silhouette when the pixel above it sees
 * something farther away across a break: sky (the skyline), or terrain whose inverse distance jumps
 * by much more than it changes just below (an occluding edge). On one continuous surface, even at
 * grazing incidence where distances grow fast from row to row, inverse distance changes smoothly,
 * so no line is drawn there. Pure arithmetic on the distance map; colour only is changed.
 */
public final class Silhouettes {
    /** A jump in inverse distance this many times the change just below marks an edge. */
    static final double JUMP_RATIO = 4;
    /** Ignore jumps smaller than this in distance (5 %): texture, not an edge. */
    static final double MIN_DISTANCE_RATIO = 1.05;
    /** Brightness kept on a silhouette pixel. */
    static final double DARKEN = 0.45;

    private Silhouettes() {
    }

    /** Whether pixel (col, row) lies on a silhouette; row 0 at the top. */
    public static boolean isEdge(float[] distance, int width, int height, int col, int row) {
        if (row == 0) {
            return false;
        }
        double d = distance[row * width + col], above = distance[(row - 1) * width + col];
        if (!Double.isFinite(d)) {
            return false; // sky itself
        }
        if (!Double.isFinite(above)) {
            return true; // the skyline
        }
        if (!(above > d * MIN_DISTANCE_RATIO)) {
            return false;
        }
        double jump = 1 / d - 1 / above;
        double below = row + 1 < height && Double.isFinite(distance[(row + 1) * width + col])
                ? Math.abs(1 / distance[(row + 1) * width + col] - 1 / d) : 0;
        return jump > JUMP_RATIO * below;
    }

    /** Darkens the silhouette pixels of a colour image in place (the test reads distances only). */
    public static void draw(int[] argb, float[] distance, int width, int height) {
        IntStream.range(0, height).parallel().forEach(row -> {
            for (int col = 0, i = row * width; col < width; col++, i++) {
                if (isEdge(distance, width, height, col, row)) {
                    int c = argb[i];
                    int r = (int) (((c >> 16) & 0xff) * DARKEN), g = (int) (((c >> 8) & 0xff) * DARKEN), b = (int) ((c & 0xff) * DARKEN);
                    argb[i] = (c & 0xff000000) | (r << 16) | (g << 8) | b;
                }
            }
        });
    }
}
