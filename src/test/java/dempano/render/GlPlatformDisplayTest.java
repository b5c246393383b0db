package dempano.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.HashMap;
import java.util.Map;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Whether the fly-through may try to open a window, decided from the environment before jME starts. */
class GlPlatformDisplayTest {
    @ParameterizedTest(name = "{0} DISPLAY={1} WAYLAND_DISPLAY={2} XDG_RUNTIME_DIR={3} on {4}")
    @CsvSource(delimiter = '|', nullValues = "-", value = {
            // choice | DISPLAY | WAYLAND_DISPLAY | XDG_RUNTIME_DIR | os.name | problem (- = none)
            "headless | -     | -          | -          | Linux      | no display is set",
            "headless | ''    | ' '        | /run/u/1   | Linux      | no display is set",
            "headless | :0    | -          | -          | Linux      | -",
            "headless | -     | wayland-0  | /run/u/1   | Linux      | -",
            "headless | -     | wayland-0  | -          | Linux      | $XDG_RUNTIME_DIR",
            "headless | -     | /run/w.sock| -          | Linux      | -",
            "native   | -     | -          | -          | FreeBSD    | no display is set",
            "x11      | -     | wayland-0  | /run/u/1   | Linux      | $DISPLAY is not set (DEMPANO_GL=x11 uses X only)",
            "glx      | :99   | -          | -          | Linux      | -",
            "headless | -     | -          | -          | Windows 11 | -",
            "x11      | -     | -          | -          | Mac OS X   | -"})
    void aWindowNeedsADisplayOnUnix(String choice, String display, String wayland, String runtime, String os, String problem) {
        Map<String, String> env = new HashMap<>();
        env.put("DISPLAY", display);
        env.put("WAYLAND_DISPLAY", wayland);
        env.put("XDG_RUNTIME_DIR", runtime);
        String got = GlPlatform.displayProblem(choice, env, os);
        if (problem == null) {
            assertNull(got);
        } else {
            assertEquals(true, got != null && got.contains(problem), got);
        }
    }
}
