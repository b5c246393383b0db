package dempano.panorama;

/**
 * The elevation angles a panorama covers, degrees above the eye's horizontal: fixed
 * ({@code bottom:top}) or {@code auto}, which renders {@link #AUTO_RENDER_BOTTOM_DEG} to
 * {@link #AUTO_RENDER_TOP_DEG} and crops to the terrain: from 1° above the highest terrain pixel
 * down to 10° below the lowest point of the skyline.
 */
public record ElevationRange(double bottomDeg, double topDeg, boolean auto) {
    public static final double AUTO_RENDER_BOTTOM_DEG = -40, AUTO_RENDER_TOP_DEG = 40;
    /** The default: 30° below to 30° above the horizon. */
    public static final ElevationRange DEFAULT = new ElevationRange(-30, 30, false);
    public static final ElevationRange AUTO = new ElevationRange(AUTO_RENDER_BOTTOM_DEG, AUTO_RENDER_TOP_DEG, true);

    public ElevationRange {
        if (!(bottomDeg >= -89 && topDeg <= 89 && topDeg > bottomDeg)) {
            throw new IllegalArgumentException("elevation range must satisfy -89 <= bottom < top <= 89 degrees, got "
                    + bottomDeg + ":" + topDeg);
        }
    }

    /** Parses {@code auto} or {@code bottom:top} in degrees, e.g. {@code -30:30}. */
    public static ElevationRange parse(String s) {
        if (s.trim().equalsIgnoreCase("auto")) {
            return AUTO;
        }
        String[] parts = s.split(":");
        if (parts.length != 2) {
            throw new IllegalArgumentException("elevation range must be 'auto' or 'bottom:top' in degrees, e.g. -30:30; got '" + s + "'");
        }
        try {
            return new ElevationRange(Double.parseDouble(parts[0].trim()), Double.parseDouble(parts[1].trim()), false);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("elevation range must be 'auto' or 'bottom:top' in degrees, got '" + s + "'");
        }
    }

    @Override
    public String toString() {
        return auto ? "auto" : bottomDeg + ":" + topDeg;
    }
}
