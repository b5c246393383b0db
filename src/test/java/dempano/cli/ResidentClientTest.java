package dempano.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The start script's side of the resident process: when it is used, which folder and stamp, and, through the
 * installed script, a resident process started, reused, stopped, ended by a client's going away, and runs
 * rendered in the client's own process where it cannot be had.
 */
class ResidentClientTest {
    /**
     * What a process started under one environment would do differently for another client: the JVM's option variables
     * and the dynamic linker's are in the stamp (a process started with JDK_JAVA_OPTIONS=-Xmx24m served later clients,
     * whose runs failed for want of heap); a relative cache folder is the client's folder's (it was the socket folder's).
     */
    @Test
    void theJvmsOptionVariablesAndRelativeCacheFoldersShapeTheStamp() {
        Map<String, String> base = Map.of("PATH", "/usr/bin");
        for (String k : List.of("JDK_JAVA_OPTIONS", "JAVA_TOOL_OPTIONS", "_JAVA_OPTIONS", "LD_LIBRARY_PATH", "LD_PRELOAD")) {
            Map<String, String> with = new HashMap<>(base);
            with.put(k, "-Xmx24m");
            assertNotEquals(ResidentClient.stamp(base), ResidentClient.stamp(with), k);
        }
        Map<String, String> env = Map.of("DEMPANO_CACHE_DIR", "relc", "XDG_CACHE_HOME", "/abs/cache", "PATH", "/usr/bin");
        Map<String, String> abs = ResidentClient.withAbsoluteCacheDirs(env);
        assertEquals(Path.of("relc").toAbsolutePath().normalize().toString(), abs.get("DEMPANO_CACHE_DIR"));
        assertEquals("/abs/cache", abs.get("XDG_CACHE_HOME"));
        assertEquals("off", ResidentClient.withAbsoluteCacheDirs(Map.of("DEMPANO_CACHE_DIR", "off")).get("DEMPANO_CACHE_DIR"));
        // The stamp sees the absolute folder: the same relative name from another folder is another process.
        assertEquals(ResidentClient.stamp(env), ResidentClient.stamp(abs));
    }

    @ParameterizedTest(name = "DEMPANO_RESIDENT={0}: {1}")
    @CsvSource({"on, true", "ON, true", "1, true", "true, true", "yes, true", "off, false", "0, false", "'', false",
            "maybe, false"})
    void theEnvironmentSwitchesItOn(String value, boolean wanted) {
        assertEquals(wanted, ResidentClient.wanted(Map.of("DEMPANO_RESIDENT", value)));
        assertFalse(ResidentClient.wanted(Map.of()));
    }

    @ParameterizedTest(name = "{0}: {1}")
    @CsvSource(delimiter = '|', value = {
            "--lat 46 --lon 8 --dem-dir d | true",
            "--out p | true",
            "--lat 46 --lon 8 --dem-dir d --repeat 3 | true",
            "--help | false",
            "-h | false",
            "--version | false",
            "-V | false",
            "photo x.jpg | true",
            "photo x.jpg --dem-dir d --out p | true",
            "photo --help | false",
            "photo x.jpg -h | false",
            "photo -V | false",
            "batch v.csv | false",
            "fly | false",
            "resident status | false",
            "help | false"})
    void onlyPanoramasAndPhotosAreHandedOn(String args, boolean served) {
        assertEquals(served, ResidentClient.serves(args.trim().split(" ")));
    }

    @Test
    void theStampFollowsTheSettingsThatShapeARunAndNoOthers() {
        Map<String, String> env = new HashMap<>(Map.of("HOME", "/home/a", "PATH", "/usr/bin"));
        String base = ResidentClient.stamp(env);
        assertTrue(base.matches("[0-9a-f]{16}"), base);
        env.put("PATH", "/bin:/usr/bin");
        env.put("TERM", "xterm");
        assertEquals(base, ResidentClient.stamp(env), "unrelated variables");
        for (String shaping : List.of("DEMPANO_CACHE_DIR", "XDG_CACHE_HOME", "DEMPANO_GL", "DISPLAY", "MESA_GL_VERSION_OVERRIDE",
                "LIBGL_ALWAYS_SOFTWARE", "GALLIUM_DRIVER", "LP_NUM_THREADS", "DEMPANO_RESIDENT_IDLE_S", "LANG", "LC_ALL",
                "LC_CTYPE", "TZ")) {
            Map<String, String> other = new HashMap<>(env);
            other.put(shaping, "1");
            assertNotEquals(base, ResidentClient.stamp(other), shaping);
        }
    }

    @Test
    void theUmaskIsReadAsTheShellShowsIt() throws Exception {
        // Part of the stamp: a client with another umask gets another process, which writes with that umask.
        org.junit.jupiter.api.Assumptions.assumeTrue(Files.isReadable(Path.of("/proc/self/status")), "no /proc here");
        Process sh = new ProcessBuilder("/bin/sh", "-c", "umask").start(); // a child has this process's umask
        String shown = new String(sh.getInputStream().readAllBytes(), StandardCharsets.US_ASCII).trim();
        assertEquals(0, sh.waitFor());
        assertEquals(Integer.parseInt(shown, 8), Integer.parseInt(ResidentClient.umask(), 8), shown);
    }

    @Test
    void theFolderIsTheUsersAlone(@TempDir Path dir) throws IOException {
        Path own = dir.resolve("mine");
        assertEquals(own.toAbsolutePath(), ResidentClient.directory(Map.of("DEMPANO_RESIDENT_DIR", own.toString())));
        assertEquals("rwx------", PosixFilePermissions.toString(Files.getPosixFilePermissions(own)));
        Path shared = Files.createDirectory(dir.resolve("shared"));
        Files.setPosixFilePermissions(shared, PosixFilePermissions.fromString("rwxrwxrwx"));
        IOException e = assertThrows(IOException.class,
                () -> ResidentClient.directory(Map.of("DEMPANO_RESIDENT_DIR", shared.toString())));
        assertTrue(e.getMessage().contains("is not this user's alone"), e.getMessage());
        assertEquals(dir.resolve("dempano"), ResidentClient.directory(Map.of("XDG_RUNTIME_DIR", dir.toString())));
        Path file = Files.writeString(dir.resolve("a-file"), "");
        IOException notFolder = assertThrows(IOException.class,
                () -> ResidentClient.directory(Map.of("DEMPANO_RESIDENT_DIR", file.toString())));
        assertTrue(notFolder.getMessage().contains("is not a folder"), notFolder.getMessage());
    }

    @Test
    void aSocketPathTooLongForUnixIsRefusedBeforeAnythingStarts(@TempDir Path dir) throws Exception {
        Path deep = dir.resolve("a".repeat(60)).resolve("b".repeat(60));
        IOException e = assertThrows(IOException.class,
                () -> ResidentClient.socket(Map.of("DEMPANO_RESIDENT_DIR", deep.toString()), "0123456789abcdef"));
        assertTrue(e.getMessage().contains("set DEMPANO_RESIDENT_DIR to a shorter folder"), e.getMessage());
        // Said before any process is started (no wait for one that cannot bind), and rendered in the client.
        String[] r = StartScriptTest.run(Map.of("DEMPANO_RESIDENT", "on", "DEMPANO_RESIDENT_DIR", deep.toString()),
                "--ppd", "2", "--out", dir.resolve("p").toString());
        assertEquals("0", r[0], r[2]);
        assertTrue(r[2].contains("shorter folder") && r[2].contains("rendering in this process"), r[2]);
        try (var files = Files.list(deep)) {
            assertEquals(List.of(), files.toList(), "no process was started (it would have its log there)");
        }
    }

    /** What a fake resident process does with the one connection it accepts (then it holds it open, silent). */
    private interface Behaviour {
        void on(java.nio.channels.SocketChannel c) throws IOException;
    }

    /**
     * A request of {@code kind} to a fake resident process that behaves so and then says nothing: the client must give
     * up after ANSWER_SECONDS (1 s here), not try again, and pass on what came before. Returns the error and stderr.
     */
    private static String[] exchangeWithSilent(Path dir, String kind, Behaviour behaviour) throws Exception {
        Path socket = dir.resolve("s.sock");
        try (java.nio.channels.ServerSocketChannel server = java.nio.channels.ServerSocketChannel.open(
                java.net.StandardProtocolFamily.UNIX)) {
            server.bind(java.net.UnixDomainSocketAddress.of(socket));
            java.util.List<java.nio.channels.SocketChannel> held = new java.util.concurrent.CopyOnWriteArrayList<>();
            Thread acceptor = new Thread(() -> {
                try {
                    java.nio.channels.SocketChannel c = server.accept();
                    held.add(c);
                    behaviour.on(c);
                } catch (IOException e) {
                    // closed
                }
            });
            acceptor.setDaemon(true);
            acceptor.start();
            int before = ResidentClient.ANSWER_SECONDS;
            ResidentClient.ANSWER_SECONDS = 1;
            long t0 = System.nanoTime();
            java.io.ByteArrayOutputStream err = new java.io.ByteArrayOutputStream();
            IOException e;
            try (java.nio.channels.SocketChannel ch = ResidentClient.connect(socket)) {
                e = assertThrows(IOException.class, () -> ResidentClient.exchange(ch, new ResidentProtocol.Request(
                        kind, "stamp", dir.toString(), List.of()), System.out, new java.io.PrintStream(err)));
                assertFalse(e instanceof ResidentClient.Unanswered, "not tried again");
            } finally {
                ResidentClient.ANSWER_SECONDS = before;
                for (java.nio.channels.SocketChannel c : held) {
                    c.close();
                }
            }
            assertTrue((System.nanoTime() - t0) / 1e9 < 10, "gave up after about a second");
            return new String[] {e.getMessage(), err.toString(java.nio.charset.StandardCharsets.UTF_8)};
        }
    }

    @Test
    void aProcessThatAcceptsButNeverAnswersDoesNotHangTheClient(@TempDir Path dir) throws Exception {
        // A resident process stopped (kill -STOP) or hung: the kernel still accepts connections. Every later run and
        // `resident stop` hung; now the client gives up after ANSWER_SECONDS and the run renders in the client.
        String[] r = exchangeWithSilent(dir, ResidentProtocol.STATUS, c -> { }); // not a byte back
        assertTrue(r[0].contains("did not answer within 1 s"), r[0]);
    }

    @Test
    void aProcessThatFallsSilentDuringTheRunDoesNotHangTheClient(@TempDir Path dir) throws Exception {
        // Stopped (kill -STOP) or hung after it took the run: the client waited for ever (the watch covered only the
        // first frame). A live process sends a heartbeat every ResidentServer.HEARTBEAT_MILLIS.
        String[] r = exchangeWithSilent(dir, ResidentProtocol.RENDER, c -> {
            ResidentProtocol.Request.read(new java.io.DataInputStream(ResidentProtocol.in(c)));
            ResidentProtocol.Writer w = new ResidentProtocol.Writer(ResidentProtocol.out(c));
            w.bytes(ResidentProtocol.ERR, new byte[0], 0, 0); // taken
            w.bytes(ResidentProtocol.ERR, "stitching\n".getBytes(java.nio.charset.StandardCharsets.UTF_8), 0, 10);
        });
        assertTrue(r[0].contains("fell silent during the run for 1 s"), r[0]);
        assertEquals("stitching\n", r[1], "what came before the silence was passed on");
    }

    @Test
    void aFileThatIsNoSocketIsLeftAsItIs(@TempDir Path dir) throws IOException {
        // `dempano resident status` removed any *.sock file nobody listened on, a user's notes.sock included.
        Path notes = Files.writeString(dir.resolve("notes.sock"), "important\n");
        IOException e = assertThrows(IOException.class, () -> ResidentClient.connect(notes));
        assertTrue(e.getMessage().contains("is not a socket"), e.getMessage());
        assertEquals("important\n", Files.readString(notes));
        Path link = Files.createSymbolicLink(dir.resolve("link.sock"), notes);
        assertThrows(IOException.class, () -> ResidentClient.connect(link));
        assertTrue(Files.isSymbolicLink(link), "a link is not removed either");
    }

    @Test
    void theIdleTimeIsWholeSecondsOrTheDefault() {
        assertEquals(ResidentClient.DEFAULT_IDLE_SECONDS, ResidentClient.idleSeconds(Map.of()));
        assertEquals(30, ResidentClient.idleSeconds(Map.of("DEMPANO_RESIDENT_IDLE_S", " 30 ")));
        for (String bad : List.of("0", "-5", "1.5", "ten")) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> ResidentClient.idleSeconds(Map.of("DEMPANO_RESIDENT_IDLE_S", bad)));
            assertTrue(e.getMessage().contains("DEMPANO_RESIDENT_IDLE_S"), e.getMessage());
        }
    }

    // Through the installed start script: real processes.

    /** The resident process a test started and has not stopped (ended after the test whatever happened). */
    private long started = -1;

    @org.junit.jupiter.api.AfterEach
    void endWhatWasStarted() {
        if (started > 0) {
            ProcessHandle.of(started).ifPresent(ProcessHandle::destroyForcibly);
        }
    }

    private static Map<String, String> env(Path dir) {
        return Map.of("DEMPANO_RESIDENT", "on", "DEMPANO_RESIDENT_DIR", dir.resolve("sock").toString(),
                "DEMPANO_RESIDENT_IDLE_S", "90");
    }

    private static long residentPid(String err, int run, Path dir) throws IOException {
        Matcher m = Pattern.compile("resident process (\\d+), run " + run + "\\b").matcher(err);
        if (!m.find()) {
            StringBuilder logs = new StringBuilder();
            try (var files = Files.list(dir.resolve("sock"))) {
                for (Path f : files.filter(f -> f.toString().endsWith(".log")).toList()) {
                    logs.append(f).append(":\n").append(Files.readString(f));
                }
            }
            throw new AssertionError("run " + run + " by a resident process: " + err + "\nlogs: " + logs);
        }
        return Long.parseLong(m.group(1));
    }

    /** The demo scene through the script at 2 px/° into {@code dir/name}: the pid of the resident process it started. */
    private long firstRun(Map<String, String> env, Path dir, String name) throws Exception {
        String[] first = StartScriptTest.run(env, "--ppd", "2", "--out", dir.resolve(name).toString());
        assertEquals("0", first[0], first[2]);
        started = residentPid(first[2], 1, dir);
        return started;
    }

    @Test
    void theScriptStartsAResidentProcessUsesItAgainAndStopsIt(@TempDir Path dir) throws Exception {
        Map<String, String> env = env(dir);
        long pid = firstRun(env, dir, "p1");
        assertTrue(pid != ProcessHandle.current().pid());
        Path cwd = Path.of("/proc", Long.toString(pid), "cwd");
        if (Files.exists(cwd)) { // Linux: it does not hold the folder it was started from
            assertEquals(dir.resolve("sock").toRealPath(), cwd.toRealPath());
        }
        assertTrue(Files.isRegularFile(dir.resolve("p1.png")));
        String[] second = StartScriptTest.run(env, "--ppd", "2", "--out", dir.resolve("p2").toString());
        assertEquals("0", second[0], second[2]);
        assertEquals(pid, residentPid(second[2], 2, dir), "the same process, warm");
        assertTrue(Files.isRegularFile(dir.resolve("p2.png")));

        String[] status = StartScriptTest.run(env, "resident", "status");
        assertEquals("0", status[0], status[2]);
        assertTrue(status[1].contains("resident process " + pid + ": up") && status[1].contains("2 runs"), status[1]);
        String[] stop = StartScriptTest.run(env, "resident", "stop");
        assertEquals("0", stop[0], stop[2]);
        assertTrue(stop[1].contains("stopped the resident process " + pid), stop[1]);
        String[] none = StartScriptTest.run(env, "resident", "status");
        assertEquals("1", none[0]);
        assertTrue(none[1].contains("no resident process"), none[1]);
        started = -1;
    }

    /**
     * A client stopped during its run (SIGTERM, as Ctrl-C) ends the resident process; the next run starts another,
     * and its output set is complete.
     */
    @Test
    void aClientStoppedDuringItsRunEndsTheResidentProcess(@TempDir Path dir) throws Exception {
        Map<String, String> env = env(dir);
        long pid = firstRun(env, dir, "p");
        Path socket;
        try (var files = Files.list(dir.resolve("sock"))) {
            List<Path> sockets = files.filter(f -> f.toString().endsWith(".sock")).toList();
            assertEquals(1, sockets.size(), sockets.toString());
            socket = sockets.get(0); // the script's stamp, not this JVM's
        }
        try (var ch = ResidentClient.connect(socket)) {
            assertTrue(ch != null, "the resident process listens there");
        }

        ProcessBuilder pb = new ProcessBuilder(StartScriptTest.SCRIPT.toString(), "--ppd", "20", "--out",
                dir.resolve("p").toString());
        pb.environment().remove("JAVA_OPTS");
        pb.environment().remove("DEMPANO_OPTS");
        pb.environment().putAll(env);
        pb.redirectOutput(ProcessBuilder.Redirect.DISCARD);
        Process client = pb.start();
        CountDownLatch drawing = new CountDownLatch(1);
        StringBuilder seen = new StringBuilder();
        Thread reader = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(client.getErrorStream(), StandardCharsets.UTF_8))) {
                for (String line; (line = r.readLine()) != null; ) {
                    synchronized (seen) {
                        seen.append(line).append('\n');
                    }
                    if (line.contains("] rendering")) {
                        drawing.countDown();
                    }
                }
            } catch (IOException e) {
                // the client ended
            }
        });
        reader.start();
        assertTrue(drawing.await(120, TimeUnit.SECONDS), "the second run draws: " + seen);
        client.destroy(); // SIGTERM
        assertTrue(client.waitFor(30, TimeUnit.SECONDS));
        reader.join(10_000);
        synchronized (seen) {
            assertTrue(seen.toString().contains("run 2"), seen.toString());
        }
        long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        boolean listening = true;
        while (listening && System.nanoTime() < until) {
            try (var ch = ResidentClient.connect(socket)) {
                listening = ch != null;
            }
            Thread.sleep(listening ? 100 : 0);
        }
        assertFalse(listening, "the resident process ended");

        String[] next = StartScriptTest.run(env, "--ppd", "2", "--out", dir.resolve("p").toString());
        assertEquals("0", next[0], next[2]);
        long again = residentPid(next[2], 1, dir);
        assertNotEquals(pid, again, "a new resident process");
        started = again;
        try (var files = Files.list(dir)) {
            assertEquals(List.of("p-distance.npy", "p-distance.png", "p.json", "p.png"),
                    files.map(f -> f.getFileName().toString()).filter(n -> n.startsWith("p")).sorted().toList(),
                    "a complete set, nothing staged left");
        }
        assertEquals("0", StartScriptTest.run(env, "resident", "stop")[0]);
        started = -1;
    }

    @Test
    void withoutAUsableFolderTheRunIsRenderedInTheClient(@TempDir Path dir) throws Exception {
        Path shared = Files.createDirectory(dir.resolve("shared"));
        Files.setPosixFilePermissions(shared, PosixFilePermissions.fromString("rwxrwxrwx"));
        String[] r = StartScriptTest.run(Map.of("DEMPANO_RESIDENT", "on", "DEMPANO_RESIDENT_DIR", shared.toString()),
                "--ppd", "2", "--out", dir.resolve("p").toString());
        assertEquals("0", r[0], r[2]);
        assertTrue(r[2].contains("is not this user's alone") && r[2].contains("rendering in this process"), r[2]);
        assertFalse(Pattern.compile("resident process \\d+").matcher(r[2]).find(), r[2]);
        assertTrue(Files.isRegularFile(dir.resolve("p.png")));
    }
}
