package dempano.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The fly-through, scripted, in a window under Xvfb (GLX on llvmpipe): the screenshot shows terrain
 * below sky and the HUD's text, and the HUD's numbers describe where the script flew.
 */
class FlyThroughTest {
    @Test
    void scriptedFlightUnderXvfbShowsTerrainAndHud(@TempDir Path tmp) throws Exception {
        Assumptions.assumeTrue(Files.isExecutable(Path.of("/usr/bin/xvfb-run")),
                "xvfb-run is not installed (apt-get install xvfb xauth): the window test needs a virtual display");
        Path shot = tmp.resolve("fly.png");
        List<String> cmd = new ArrayList<>(List.of("/usr/bin/xvfb-run", "-a", "-s", "-screen 0 1024x768x24",
                Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xmx2g", "-cp",
                System.getProperty("java.class.path"), "dempano.cli.Main", "fly", "--no-dialog", "--frames", "30",
                "--screenshot", shot.toString(), "--width", "640", "--height", "400", "--above-ground-m", "300",
                "--pitch-deg", "-10", "--speed-mps", "300", "--range-km", "30", "--out-dir", tmp.toString(),
                "--panorama-at-end"));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true);
        pb.environment().put("DEMPANO_GL", "x11");
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(5, TimeUnit.MINUTES), "fly-through did not finish");
        assertEquals(0, p.exitValue(), out);
        BufferedImage img = ImageIO.read(shot.toFile());
        assertEquals(640, img.getWidth());
        assertEquals(400, img.getHeight());
        int[] sky = {Math.round(OffscreenRenderer.SKY_RGBA[0] * 255), Math.round(OffscreenRenderer.SKY_RGBA[1] * 255),
            Math.round(OffscreenRenderer.SKY_RGBA[2] * 255)};
        // Looking 10° down from 300 m: the bottom third is terrain, not sky.
        int terrain = 0, n = 0;
        for (int y = 270; y < 400; y++) {
            for (int x = 0; x < 640; x += 2) {
                n++;
                terrain += distance(img.getRGB(x, y), sky) > 40 ? 1 : 0;
            }
        }
        assertTrue(terrain > 0.95 * n, "terrain pixels in the bottom third: " + terrain + " of " + n);
        // Sky above the horizon somewhere in the upper part (not an empty or black frame).
        int skyPixels = 0;
        for (int y = 120; y < 180; y++) {
            for (int x = 0; x < 640; x += 2) {
                skyPixels += distance(img.getRGB(x, y), sky) < 12 ? 1 : 0;
            }
        }
        assertTrue(skyPixels > 100, "sky pixels " + skyPixels);
        // The HUD: white text in the top-left corner.
        int white = 0;
        for (int y = 0; y < 110; y++) {
            for (int x = 0; x < 400; x++) {
                int c = img.getRGB(x, y);
                white += ((c >> 16) & 0xff) > 235 && ((c >> 8) & 0xff) > 235 && (c & 0xff) > 235 ? 1 : 0;
            }
        }
        assertTrue(white > 300, "HUD text pixels " + white);
        // The HUD's numbers: 30 frames of 10 m along a 10° descent lose 52 m of the 300 m above ground
        // (give or take the slope of the ground passed over); heading 0, pitch −10.
        Matcher m = Pattern.compile("altitude (\\d+) m above sea, (-?\\d+) m above ground").matcher(out);
        assertTrue(m.find(), out);
        double aboveGround = Double.parseDouble(m.group(2));
        assertTrue(aboveGround > 100 && aboveGround < 400, "above ground " + aboveGround);
        assertTrue(out.contains("heading 0.0 deg  pitch -10.0 deg"), out);
        assertTrue(Pattern.compile("crosshair: DEM \\d+ m at").matcher(out).find(), out);
        // Key P's panorama, rendered through the offscreen pipeline in its own JVM, from where the camera is.
        assertTrue(out.contains("panorama written: "), out);
        assertTrue(Files.size(tmp.resolve("fly-panorama-1-distance.npy")) > 7200L * 1200 * 4, "distance map");
        String json = Files.readString(tmp.resolve("fly-panorama-1.json"));
        Matcher eye = Pattern.compile("\"eyeAltitudeMetres\"\\s*:\\s*([0-9.]+)").matcher(json);
        assertTrue(eye.find(), json);
        Matcher hud = Pattern.compile("altitude (\\d+) m above sea").matcher(out);
        assertTrue(hud.find());
        assertEquals(Double.parseDouble(hud.group(1)), Double.parseDouble(eye.group(1)), 1.0, "panorama eye vs HUD altitude");
    }

    private static double distance(int rgb, int[] c) {
        return Math.abs(((rgb >> 16) & 0xff) - c[0]) + Math.abs(((rgb >> 8) & 0xff) - c[1]) + Math.abs((rgb & 0xff) - c[2]);
    }
}
