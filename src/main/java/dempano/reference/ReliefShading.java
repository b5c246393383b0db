package dempano.reference;

/**
 * The colour the reference renderer gives a terrain point: the same hypsometric tint, sun from the
 * north-west 40° high, and aerial haze as the GPU's terrain shader, so both renderers' images read
 * alike. Colour only; distances never depend on it.
 */
final class ReliefShading {
    /** The sky, as the GPU clears it. */
    static final int SKY_ARGB = argb(0.60, 0.78, 0.97);
    private static final double[] SUN_ENU;

    static {
        double az = Math.toRadians(315), el = Math.toRadians(40);
        SUN_ENU = new double[] {Math.cos(el) * Math.sin(az), Math.cos(el) * Math.cos(az), Math.sin(el)};
    }

    private final double hazeMetres;

    ReliefShading(double rangeMetres) {
        this.hazeMetres = Math.max(20_000, rangeMetres * 0.6);
    }

    /** @param normalEnu unit upward normal; @param rangeMetres distance from the eye */
    int argb(double elevationMetres, double[] normalEnu, double rangeMetres) {
        double[] c = tint(elevationMetres);
        double dot = normalEnu[0] * SUN_ENU[0] + normalEnu[1] * SUN_ENU[1] + normalEnu[2] * SUN_ENU[2];
        double light = 0.30 + 0.70 * Math.max(dot, 0);
        double haze = 0.85 * (1 - Math.exp(-rangeMetres / hazeMetres));
        double[] far = {0.62, 0.68, 0.78};
        return argb(mix(c[0] * light, far[0], haze), mix(c[1] * light, far[1], haze), mix(c[2] * light, far[2], haze));
    }

    private static double[] tint(double h) {
        if (h < 0.5) {
            return new double[] {0.28, 0.42, 0.55};
        }
        double[][] stops = {{0.36, 0.52, 0.30}, {0.30, 0.42, 0.24}, {0.55, 0.55, 0.38}, {0.50, 0.46, 0.42}, {0.93, 0.94, 0.96}};
        double[] at = {0, 800, 1800, 2600, 3200};
        for (int i = 1; i < at.length; i++) {
            if (h < at[i]) {
                double t = (h - at[i - 1]) / (at[i] - at[i - 1]);
                double[] a = stops[i - 1], b = stops[i];
                return new double[] {mix(a[0], b[0], t), mix(a[1], b[1], t), mix(a[2], b[2], t)};
            }
        }
        return stops[4];
    }

    private static double mix(double a, double b, double t) {
        return a + (b - a) * t;
    }

    private static int argb(double r, double g, double b) {
        return 0xFF000000 | channel(r) << 16 | channel(g) << 8 | channel(b);
    }

    private static int channel(double v) {
        return (int) Math.round(Math.max(0, Math.min(1, v)) * 255);
    }
}
