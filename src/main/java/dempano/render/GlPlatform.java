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
import java.util.Locale;
import java.util.Map;

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
     * For a visible window (the fly-through): X11 when {@code DEMPANO_GL=x11}, otherwise whatever GLFW
     * finds (never the null platform, which has no screen).
     */
    static synchronized void configureWindow() {
        String choice = choice();
        glfwInitHint(GLFW_PLATFORM, choice.equals("x11") || choice.equals("glx") ? GLFW_PLATFORM_X11
                : org.lwjgl.glfw.GLFW.GLFW_ANY_PLATFORM);
    }

    /** What to tell a user whose window failed. */
    static String windowHint() {
        return "the fly-through needs a display: $DISPLAY is " + System.getenv("DISPLAY")
                + "; without a screen run it under 'xvfb-run -a' with DEMPANO_GL=x11 (apt-get install xvfb xauth)";
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
