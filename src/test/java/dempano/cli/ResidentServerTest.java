package dempano.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.Synthetic;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The resident process in this JVM ({@link ResidentServer} on a socket in a temporary folder) and requests as the
 * start script's JVM sends them ({@link ResidentClient#exchange}): the client's relative paths, output and exit
 * code; the renderer kept warm, yet a tile rewritten between runs drawn as it is now; refusals; status and stop.
 */
class ResidentServerTest {
    private static final String STAMP = "0123456789abcdef";
    /** Massifs and ridges of several wavelengths around (46.5° N, 8.5° E). */
    private static final java.util.function.DoubleBinaryOperator RUGGED = (lat, lon) -> {
        double y = (lat - 46.5) * 111_195, x = (lon - 8.5) * 76_500;
        return 1200 + 700 * Math.sin(x / 3100) * Math.cos(y / 4300) + 250 * Math.sin((x + 2 * y) / 1900);
    };
    @TempDir
    Path dir;
    private Path socket, work;
    private ResidentServer server;
    private Thread serving;
    private final List<String> hangUps = new ArrayList<>();

    /** The run's output: exit code, standard output, standard error. */
    private record Result(int code, String out, String err) {
    }

    @BeforeEach
    void start() throws IOException {
        socket = dir.resolve("r.sock");
        work = Files.createDirectories(dir.resolve("work"));
        Files.createDirectories(work.resolve("dem"));
        Files.createDirectories(work.resolve("out"));
        Synthetic.writeHgt(work.resolve("dem"), RUGGED, 46, 8);
        server = new ResidentServer(socket, STAMP, Duration.ofSeconds(120));
        server.onHangUp = () -> hangUps.add("hung up");
        assertTrue(server.bind());
        serving = new Thread(() -> {
            try {
                server.serve();
            } catch (IOException e) {
                throw new RuntimeException(e);
            }
        });
        serving.start();
    }

    @AfterEach
    void stop() throws Exception {
        if (serving.isAlive()) {
            send(ResidentProtocol.STOP, STAMP);
        }
        serving.join(TimeUnit.SECONDS.toMillis(60));
        assertFalse(serving.isAlive(), "the server ended");
        assertFalse(Files.exists(socket), "its socket file is removed");
        assertEquals(List.of(), hangUps);
    }

    private Result send(String kind, String stamp, String... args) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        try (var ch = ResidentClient.connect(socket)) {
            int code = ResidentClient.exchange(ch, new ResidentProtocol.Request(kind, stamp, work.toString(), List.of(args)),
                    new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8));
            return new Result(code, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
        }
    }

    private Result render(String... args) throws IOException {
        return send(ResidentProtocol.RENDER, STAMP, args);
    }

    private static final String[] SCENE = {"--lat", "46.518", "--lon", "8.51", "--dem-dir", "dem", "--range-km", "30",
            "--ppd", "4", "--elevation-range", "-20:20"};

    private static String[] scene(String... more) {
        List<String> all = new ArrayList<>(List.of(SCENE));
        all.addAll(List.of(more));
        return all.toArray(String[]::new);
    }

    @Test
    void aRunTakesTheClientsPathsAndGivesItsOutputAndExitCode() throws IOException {
        Result r = render(scene("--out", "out/p", "--renderer", "reference"));
        assertEquals(0, r.code(), r.err());
        assertTrue(r.err().contains("resident process " + ProcessHandle.current().pid() + ", run 1"), r.err());
        assertTrue(r.err().contains("wrote [out/p.png, out/p-distance.npy"), "paths as the client gave them: " + r.err());
        assertTrue(Files.isRegularFile(work.resolve("out/p.png")), "written in the client's working directory");
        assertFalse(Files.exists(Path.of("out", "p.png")), "not in the server's");

        Result bad = render(scene("--out", "out/q", "--ppd", "-3"));
        assertEquals(2, bad.code());
        assertTrue(bad.err().contains("dempano: ") && bad.err().contains("ppd"), bad.err());
        Result missing = render("--lat", "46.518", "--lon", "8.51", "--dem-dir", "no-such-dem", "--out", "out/q");
        assertEquals(1, missing.code());
        assertTrue(missing.err().contains(work.resolve("no-such-dem").toString()), "the folder named: " + missing.err());

        Result table = render(scene("--out", "out/r", "--renderer", "reference", "--repeat", "2"));
        assertEquals(0, table.code(), table.err());
        assertTrue(table.out().contains("| 2 | warm |"), "standard output passed on: " + table.out());
    }

    /**
     * The GL renderer is kept from run to run (the second run reuses the first's meshes), and its panorama is the one
     * a run in its own process makes; a tile file rewritten between runs is drawn as it is now.
     */
    @Test
    void theRendererIsKeptWarmAndATileRewrittenBetweenRunsIsDrawnAsItIsNow() throws IOException {
        Result first = render(scene("--out", "out/a"));
        assertEquals(0, first.code(), first.err());
        Result second = render(scene("--out", "out/b"));
        assertEquals(0, second.code(), second.err());
        assertTrue(reusedPatches(second.err()) > 0, "meshes kept: " + second.err());
        assertArrayEquals(Files.readAllBytes(work.resolve("out/a-distance.npy")),
                Files.readAllBytes(work.resolve("out/b-distance.npy")));

        assertEquals(0, Main.run(inThisProcess("out/local")));
        assertArrayEquals(Files.readAllBytes(work.resolve("out/local-distance.npy")),
                Files.readAllBytes(work.resolve("out/b-distance.npy")), "as a run in its own process");

        // The tile rewritten with a 600 m bump 5 km from the eye (a later modification time, whatever the clock).
        Path file = Synthetic.writeHgt(work.resolve("dem"), (lat, lon) -> RUGGED.applyAsDouble(lat, lon)
                + (lat > 46.55 && lat < 46.58 && lon > 8.55 && lon < 8.60 ? 600 : 0), 46, 8);
        Files.setLastModifiedTime(file, java.nio.file.attribute.FileTime.fromMillis(
                Files.getLastModifiedTime(file).toMillis() + 10_000));
        Result third = render(scene("--out", "out/c"));
        assertEquals(0, third.code(), third.err());
        assertEquals(0, Main.run(inThisProcess("out/fresh")));
        byte[] now = Files.readAllBytes(work.resolve("out/fresh-distance.npy"));
        assertFalse(java.util.Arrays.equals(now, Files.readAllBytes(work.resolve("out/b-distance.npy"))), "the bump shows");
        assertArrayEquals(now, Files.readAllBytes(work.resolve("out/c-distance.npy")), "drawn as the tile is now");
    }

    @Test
    void aPhotoTakesTheClientsPathsToo() throws IOException {
        String[] camera = {"--lat", "46.518", "--lon", "8.51", "--heading-deg", "40", "--pitch-deg", "2", "--roll-deg", "0",
                "--hfov-deg", "60", "--dem-dir", "dem", "--range-km", "30"};
        List<String> fromFlags = new ArrayList<>(List.of("photo", "--width-px", "240", "--height-px", "160", "--out", "out/view"));
        fromFlags.addAll(List.of(camera));
        Result view = render(fromFlags.toArray(String[]::new));
        assertEquals(0, view.code(), view.err());
        assertTrue(view.out().contains("wrote out/view.png"), view.out());
        assertTrue(Files.isRegularFile(work.resolve("out/view.png")));

        // The view as the photograph (a relative IMAGE), every value pinned: its own view again, on its pixels.
        List<String> ofPhoto = new ArrayList<>(List.of("photo", "out/view.png", "--out", "out/again"));
        ofPhoto.addAll(List.of(camera));
        Result again = render(ofPhoto.toArray(String[]::new));
        assertEquals(0, again.code(), again.err());
        assertTrue(again.err().contains("resident process " + ProcessHandle.current().pid() + ", run 2"), again.err());
        assertArrayEquals(Files.readAllBytes(work.resolve("out/view-distance.npy")),
                Files.readAllBytes(work.resolve("out/again-distance.npy")), "the same view");
        Result missing = render("photo", "out/none.jpg", "--dem-dir", "dem", "--out", "out/x");
        assertTrue(missing.code() != 0 && missing.err().contains(work.resolve("out/none.jpg").toString()), missing.err());
    }

    /** The scene's arguments for a run in this process (its own renderer, paths made absolute). */
    private String[] inThisProcess(String out) {
        String[] args = scene("--out", work.resolve(out).toString());
        for (int i = 1; i < args.length; i++) {
            if (args[i - 1].equals("--dem-dir")) {
                args[i] = work.resolve(args[i]).toString();
            }
        }
        return args;
    }

    private static int reusedPatches(String err) {
        Matcher m = Pattern.compile("(\\d+) patches reused").matcher(err);
        assertTrue(m.find(), err);
        return Integer.parseInt(m.group(1));
    }

    @Test
    void anotherStampOrABusyProcessIsRefusedAndStatusAnswersMeanwhile() throws IOException {
        assertThrows(ResidentClient.Refused.class, () -> send(ResidentProtocol.RENDER, "fedcba9876543210", SCENE));
        assertEquals(0, send(ResidentProtocol.STATUS, "fedcba9876543210").code(), "status answers any of the user's clients");
        server.busy.set(true); // as while another client's run is under way
        try {
            ResidentClient.Refused refused = assertThrows(ResidentClient.Refused.class, () -> render(scene("--out", "out/p")));
            assertTrue(refused.getMessage().contains("busy"), refused.getMessage());
            Result status = send(ResidentProtocol.STATUS, STAMP);
            assertEquals(0, status.code());
            assertTrue(status.out().contains("resident process " + ProcessHandle.current().pid() + ": up"), status.out());
        } finally {
            server.busy.set(false);
        }
        assertFalse(Files.exists(work.resolve("out/p.png")));
    }

    /** A run silent for longer than a client waits (a long stage) is kept alive by the heartbeat. */
    @Test
    void aLongSilentRunIsKeptAliveByItsHeartbeat() throws IOException {
        long heartbeat = ResidentServer.HEARTBEAT_MILLIS;
        int answer = ResidentClient.ANSWER_SECONDS;
        ResidentServer.HEARTBEAT_MILLIS = 200;
        ResidentClient.ANSWER_SECONDS = 1;
        server.beforeRender = () -> {
            try {
                Thread.sleep(3000); // three times what the client waits in silence
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        };
        try {
            Result r = render(scene("--out", "out/slow", "--renderer", "reference"));
            assertEquals(0, r.code(), r.err());
        } finally {
            ResidentServer.HEARTBEAT_MILLIS = heartbeat;
            ResidentClient.ANSWER_SECONDS = answer;
            server.beforeRender = () -> { };
        }
        assertTrue(Files.isRegularFile(work.resolve("out/slow.png")));
    }

    /**
     * A client gone before its run was taken (it gave up waiting on a stopped process, or was stopped itself) left
     * the process busy for good: every later client was refused, and neither idle time nor stop ended it.
     */
    @Test
    void aClientGoneBeforeItsRunWasTakenLeavesTheProcessFree() throws Exception {
        try (var ch = ResidentClient.connect(socket)) {
            ch.shutdownInput(); // first (no race with the process's answer): its first frame fails, as to a client gone
            new ResidentProtocol.Request(ResidentProtocol.RENDER, STAMP, work.toString(),
                    List.of(scene("--out", "out/never", "--renderer", "reference")))
                    .write(new java.io.DataOutputStream(ResidentProtocol.out(ch)));
            long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
            Result r = null;
            while (r == null && System.nanoTime() < until) {
                try {
                    r = render(scene("--out", "out/next", "--renderer", "reference"));
                } catch (ResidentClient.Refused busy) {
                    Thread.sleep(100); // the gone client's request may still be in hand
                }
            }
            assertTrue(r != null, "the process stayed busy with a run whose client was gone");
            assertEquals(0, r.code(), r.err());
        }
        assertFalse(Files.exists(work.resolve("out/never.png")), "the gone client's run was not made");
    }

    @Test
    void stopEndsTheProcessAndRemovesItsSocket() throws Exception {
        Result stop = send(ResidentProtocol.STOP, STAMP);
        assertEquals(0, stop.code());
        assertTrue(stop.out().contains("stopped the resident process"), stop.out());
        serving.join(TimeUnit.SECONDS.toMillis(30));
        assertFalse(serving.isAlive());
        assertFalse(Files.exists(socket));
        assertEquals(null, ResidentClient.connect(socket), "nobody listens");
    }

    @Test
    void aClientGoingAwayDuringItsRunEndsTheProcess() throws Exception {
        java.util.concurrent.CountDownLatch hungUp = new java.util.concurrent.CountDownLatch(1);
        server.onHangUp = hungUp::countDown;
        try (var ch = ResidentClient.connect(socket)) {
            new ResidentProtocol.Request(ResidentProtocol.RENDER, STAMP, work.toString(),
                    List.of(scene("--out", "out/gone", "--renderer", "reference")))
                    .write(new java.io.DataOutputStream(ResidentProtocol.out(ch)));
            java.io.DataInputStream in = new java.io.DataInputStream(ResidentProtocol.in(ch));
            ResidentProtocol.Frame.read(in); // the run has started
        }
        assertTrue(hungUp.await(60, TimeUnit.SECONDS), "the hang-up was noticed");
    }
}
