package dempano.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.renderer.RenderManager;
import com.jme3.renderer.ViewPort;
import com.jme3.scene.Node;
import com.jme3.scene.control.AbstractControl;
import dempano.PanoramaRenderer;
import dempano.panorama.DepthMode;
import dempano.panorama.Panorama;
import dempano.panorama.PanoramaGeometry;
import dempano.panorama.ViewLayout;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * An Error on the GL thread (out of memory while rendering, as a 400 MB heap met it) reaches the
 * caller at once instead of parking it forever; the renderer then says so on every call, and a new
 * renderer gets a working context. Runs in its own JVM: it breaks the process's shared GL context.
 */
class GlThreadFailureTest {
    /** The child: prints one line per step. */
    public static void main(String[] args) {
        OffscreenRenderer.Handle handle = OffscreenRenderer.acquire();
        Node failing = new Node("failing");
        failing.addControl(new AbstractControl() {
            @Override
            protected void controlUpdate(float tpf) {
                throw new OutOfMemoryError("simulated on the GL thread");
            }

            @Override
            protected void controlRender(RenderManager rm, ViewPort vp) {
            }
        });
        ViewLayout layout = ViewLayout.forPanorama(PanoramaGeometry.of(2, -10, 10), 8, 1);
        try {
            handle.renderer().render(failing, layout, DepthMode.SHADER_RANGE, 1, 1000, false);
            System.out.println("1 no failure");
        } catch (OutOfMemoryError e) {
            System.out.println("1 " + e.getMessage());
        }
        try {
            handle.renderer().render(new Node("empty"), layout, DepthMode.SHADER_RANGE, 1, 1000, false);
            System.out.println("2 no failure");
        } catch (RenderFailedException e) {
            System.out.println("2 " + e.getMessage());
        }
        handle.close();
        try (PanoramaRenderer r = PanoramaRenderer.open(RenderGeometryTest.dem(RenderGeometryTest.TERRAIN, 46, 8, 1, 1))) {
            Panorama p = r.render(RendererLifecycleTest.small());
            System.out.println("3 rendered " + p.widthPx() + "x" + p.heightPx());
        }
        System.exit(0);
    }

    @Test
    void anErrorOnTheGlThreadReachesTheCallerAndANewRendererWorks() throws Exception {
        Process child = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                System.getProperty("java.class.path"), GlThreadFailureTest.class.getName())
                .redirectErrorStream(true).start();
        boolean ended = child.waitFor(180, TimeUnit.SECONDS);
        if (!ended) {
            child.destroyForcibly();
        }
        String out = new String(child.getInputStream().readAllBytes());
        assertTrue(ended, "the child hung: " + out);
        assertEquals(0, child.exitValue(), out);
        assertTrue(out.contains("1 simulated on the GL thread"), out);
        assertTrue(out.contains("2 this renderer's OpenGL thread failed earlier (java.lang.OutOfMemoryError: simulated on "
                + "the GL thread); open a new renderer"), out);
        assertTrue(out.contains("3 rendered 1440x80"), out);
        assertTrue(!out.contains("\tat "), "no stack trace printed: " + out);
    }
}
