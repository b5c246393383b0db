package dempano.panorama;

/** How a view's distances are obtained from the GPU. */
public enum DepthMode {
    /**
     * The thesis's method: standard OpenGL projection with near/far planes, a 24-bit depth buffer,
     * linearized by z_e = 2fn / (f + n − (2z_b − 1)(f − n)). Coarse far away (about 100 m at 50 km
     * with near 1 m, far 300 km); kept for comparison.
     */
    STANDARD_24("standard24"),
    /** Reversed-Z (clip control 0..1, infinite far plane) with a 32-bit float depth buffer: z_e = n / z_b. */
    REVERSED_32F("reversed32f"),
    /**
     * Default. Visibility by reversed-Z 32-bit float depth; the distance written per fragment by the
     * shader into a 32-bit float target, exact for the drawn triangle.
     */
    SHADER_RANGE("shader");

    private final String optionName;

    DepthMode(String optionName) {
        this.optionName = optionName;
    }

    /** The name used on the command line and in metadata. */
    public String optionName() {
        return optionName;
    }

    public boolean reversedZ() {
        return this != STANDARD_24;
    }

    public static DepthMode fromOptionName(String s) {
        for (DepthMode m : values()) {
            if (m.optionName.equalsIgnoreCase(s) || m.name().equalsIgnoreCase(s)) {
                return m;
            }
        }
        throw new IllegalArgumentException("unknown depth mode '" + s + "' (use standard24, reversed32f or shader)");
    }
}
