package dempano.render;

import static org.lwjgl.glfw.GLFW.GLFW_CONTEXT_CREATION_API;
import static org.lwjgl.glfw.GLFW.GLFW_EGL_CONTEXT_API;
import static org.lwjgl.glfw.GLFW.GLFW_PLATFORM;
import static org.lwjgl.glfw.GLFW.GLFW_PLATFORM_NULL;
import static org.lwjgl.glfw.GLFW.GLFW_PLATFORM_X11;
import static org.lwjgl.glfw.GLFW.glfwInitHint;
import static org.lwjgl.glfw.GLFW.glfwWindowHint;

import com.jme3.system.AppSettings;
import com.jme3.system.lwjgl.LwjglWindow;
import java.lang.reflect.Field;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * Chooses how GLFW gets an OpenGL context. {@code headless} (the default): GLFW's null platform with
 * an EGL context, which needs no X server (Mesa's llvmpipe on CPU machines, the GPU's EGL driver
 * elsewhere). {@code x11}: a normal GLX context on $DISPLAY (Xvfb works). Set with the environment
 * variable {@code DEMPANO_GL} or the system property {@code dempano.gl}.
 */
final class GlPlatform {
    /** The jME renderer name we ask for: OpenGL 4.5 core (clip control is core in 4.5). */
    static final String RENDERER = AppSettings.LWJGL_OPENGL45;
    private static boolean configured;
    /** Loggers whose level we set, kept reachable: java.util.logging holds loggers weakly and a collected one forgets its level. */
    private static final List<Logger> QUIETED = new ArrayList<>();

    private GlPlatform() {
    }

    static String choice() {
        String p = System.getProperty("dempano.gl", System.getenv("DEMPANO_GL"));
        return p == null ? "headless" : p.toLowerCase(Locale.ROOT);
    }

    /** Must run before jME initialises GLFW (each time: init hints apply to the next glfwInit). */
    static synchronized void configure() {
        String choice = choice();
        switch (choice) {
            case "headless", "egl", "null" -> {
                glfwInitHint(GLFW_PLATFORM, GLFW_PLATFORM_NULL);
                if (!configured) {
                    // jME resets window hints (glfwDefaultWindowHints) before applying its renderer's
                    // hints from a private table; wrap our renderer's entry to add the EGL hint there.
                    addWindowHint(() -> glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API));
                }
            }
            case "x11", "glx" -> glfwInitHint(GLFW_PLATFORM, GLFW_PLATFORM_X11);
            case "native", "default" -> {
                // Let GLFW pick (a desktop with a display).
            }
            default -> throw new GlUnavailableException("DEMPANO_GL=" + choice
                    + " is not known; use headless (EGL, no display), x11 (GLX on $DISPLAY) or native", null);
        }
        configured = true;
    }

    /**
     * jME's own log lines (start-up banner, warnings) are not for users: only SEVERE ones are kept, and
     * from its context class ({@code LwjglWindow}, which runs the offscreen buffer too) none: its failures
     * reach the caller through {@code handleError}, which words them ("Display initialization failed"
     * printed with a timestamp above our own message was noise). {@code DEMPANO_DEBUG} set in the
     * environment keeps them all.
     */
    static synchronized void quietJme() {
        if (System.getenv("DEMPANO_DEBUG") != null) {
            return;
        }
        Logger jme = Logger.getLogger("com.jme3");
        jme.setLevel(Level.SEVERE);
        QUIETED.add(jme);
        Logger w = Logger.getLogger(LwjglWindow.class.getName());
        w.setLevel(Level.OFF);
        QUIETED.add(w);
        // "SEVERE: Buffer cannot be destroyed" when a released mesh's native memory cannot be freed at once (seen
        // with a one-pixel GeoTIFF on a successful run): the garbage collector frees it instead; nothing is wrong.
        // (ReflectionAllocator logs through BufferUtils' logger; only that message is dropped.)
        Logger buffers = Logger.getLogger(com.jme3.util.BufferUtils.class.getName());
        buffers.setFilter(r -> r.getMessage() == null || !r.getMessage().startsWith("Buffer cannot be destroyed"));
        QUIETED.add(buffers);
    }

    /**
     * Why no window can be opened here, or null when one may be: on Linux and the BSDs a window needs
     * an X display ({@code $DISPLAY}) or, unless {@code DEMPANO_GL=x11}, a Wayland one
     * ({@code $WAYLAND_DISPLAY}, with {@code $XDG_RUNTIME_DIR} unless it is a path). Elsewhere (Windows, macOS) the desktop is assumed.
     *
     * @param choice the {@code DEMPANO_GL} choice ({@link #choice()})
     * @param env    the environment ({@code System.getenv()})
     * @param osName {@code os.name}
     */
    static String displayProblem(String choice, Map<String, String> env, String osName) {
        String os = osName.toLowerCase(Locale.ROOT);
        if (!(os.contains("linux") || os.contains("bsd") || os.contains("sunos"))) {
            return null;
        }
        boolean x11 = !blank(env.get("DISPLAY")), wayland = !blank(env.get("WAYLAND_DISPLAY"));
        if (choice.equals("x11") || choice.equals("glx")) {
            return x11 ? null : "$DISPLAY is not set (DEMPANO_GL=" + choice + " uses X only)";
        }
        if (!x11 && wayland && !env.get("WAYLAND_DISPLAY").startsWith("/") && blank(env.get("XDG_RUNTIME_DIR"))) {
            return "$WAYLAND_DISPLAY is set but $XDG_RUNTIME_DIR, where its socket lives, is not";
        }
        return x11 || wayland ? null : "no display is set ($DISPLAY and $WAYLAND_DISPLAY are empty)";
    }

    private static boolean blank(String s) {
        return s == null || s.isBlank();
    }

    /** How to fly without a screen, for messages. */
    static final String XVFB_WAY_OUT = "without a screen, run it under Xvfb: DEMPANO_GL=x11 xvfb-run -a dempano fly ..."
            + " (apt-get install xvfb xauth)";

    /**
     * For a visible window (the fly-through): X11 when {@code DEMPANO_GL=x11}, or when only
     * {@code $DISPLAY} is set (so GLFW does not probe Wayland, whose library prints to the terminal);
     * otherwise whatever GLFW finds (never the null platform, which has no screen). Check
     * {@link #displayProblem} first.
     */
    static synchronized void configureWindow() {
        String choice = choice();
        Map<String, String> env = System.getenv();
        boolean onlyX11 = !blank(env.get("DISPLAY")) && blank(env.get("WAYLAND_DISPLAY"))
                && !System.getProperty("os.name", "").toLowerCase(Locale.ROOT).contains("mac");
        glfwInitHint(GLFW_PLATFORM, choice.equals("x11") || choice.equals("glx") || onlyX11 ? GLFW_PLATFORM_X11
                : org.lwjgl.glfw.GLFW.GLFW_ANY_PLATFORM);
    }

    /** What to tell a user whose window failed to open although a display was set. */
    static String windowHint() {
        String display = System.getenv("DISPLAY"), wayland = System.getenv("WAYLAND_DISPLAY");
        return "check that the display (" + (blank(display) ? "" : "$DISPLAY " + display)
                + (blank(display) || blank(wayland) ? "" : ", ") + (blank(wayland) ? "" : "$WAYLAND_DISPLAY " + wayland)
                + ") is reachable and has OpenGL 4.5; " + XVFB_WAY_OUT;
    }

    @SuppressWarnings("unchecked")
    private static void addWindowHint(Runnable hint) {
        try {
            Field f = LwjglWindow.class.getDeclaredField("RENDER_CONFIGS");
            f.setAccessible(true);
            Map<String, Runnable> configs = (Map<String, Runnable>) f.get(null);
            Runnable original = configs.get(RENDERER);
            configs.put(RENDERER, () -> {
                original.run();
                hint.run();
            });
        } catch (ReflectiveOperationException | RuntimeException e) {
            throw new GlUnavailableException("this jME version does not expose the renderer hint table that "
                    + "headless EGL rendering relies on (" + e + "); run under Xvfb with DEMPANO_GL=x11", e);
        }
    }

    /** What to tell a user whose context failed. */
    static String hint() {
        return switch (choice()) {
            case "x11", "glx" -> "check that $DISPLAY (" + System.getenv("DISPLAY") + ") is reachable, e.g. run under "
                    + "'xvfb-run -a', and that Mesa's GL drivers are installed (apt-get install libgl1-mesa-dri libglx-mesa0)";
            default -> "headless rendering needs EGL and an OpenGL 4.5 driver: on Debian/Ubuntu 'apt-get install "
                    + "libegl1 libegl-mesa0 libgl1 libgl1-mesa-dri' (Mesa llvmpipe works without a GPU); "
                    + "or run under Xvfb with DEMPANO_GL=x11";
        };
    }
}
