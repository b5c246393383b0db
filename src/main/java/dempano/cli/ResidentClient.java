package dempano.cli;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.net.StandardProtocolFamily;
import java.net.UnixDomainSocketAddress;
import java.nio.channels.SocketChannel;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;

/**
 * The start script's side of the resident process ({@code DEMPANO_RESIDENT=on}): hands a panorama or photo command to
 * this user's resident process for this installation ({@link ResidentServer}), starting one where none runs,
 * and passes its output and exit code on. Loads nothing of the renderer or of picocli, so that the JVM it runs
 * in stays small and quick.
 *
 * <p>Which resident process: one per user, installation and setting, found by its socket
 * {@code DIR/STAMP.sock}. DIR is {@code $DEMPANO_RESIDENT_DIR}, else {@code $XDG_RUNTIME_DIR/dempano}, else
 * {@code ~/.cache/dempano/resident}, made readable by the user alone. STAMP is a hash of everything a run's
 * result may depend on besides its arguments and working directory: the Java installation, the JVM's options,
 * every class path entry's path, size and modification time (a rebuilt or reinstalled dempano has another
 * stamp, so a resident process never serves a run of other code), and the environment variables the renderer
 * reads (the deviation cache's folder, the GL platform and Mesa's settings, the display). A process whose stamp
 * nobody uses any more ends after its idle time.
 */
final class ResidentClient {
    /** {@link #run}'s answer where it did not render: the caller renders in its own process. */
    static final int NOT_SERVED = Integer.MIN_VALUE;
    /** Idle time after which a resident process ends, seconds, unless {@code DEMPANO_RESIDENT_IDLE_S} says. */
    static final int DEFAULT_IDLE_SECONDS = 600;
    /** How long a client waits for a resident process it started to accept, milliseconds. */
    private static final long START_WAIT_MILLIS = 30_000;

    private ResidentClient() {
    }

    /** Whether the environment asks for the resident process: {@code DEMPANO_RESIDENT} is on, 1, true or yes. */
    static boolean wanted(Map<String, String> env) {
        String v = env.get("DEMPANO_RESIDENT");
        return v != null && Set.of("on", "1", "true", "yes").contains(v.trim().toLowerCase(Locale.ROOT));
    }

    /**
     * Whether the resident process renders these arguments: a panorama, or {@code photo} (not another subcommand,
     * help or the version, which are quicker here).
     */
    static boolean serves(String... args) {
        boolean photo = args.length > 0 && args[0].equals("photo");
        if (!photo && Main.needsSubcommands(args)) {
            return false;
        }
        for (int i = photo ? 1 : 0; i < args.length; i++) {
            String a = args[i];
            if (a.equals("--help") || a.equals("--version") || (i == 1 && a.equals("help"))
                    || (a.startsWith("-") && !a.startsWith("--") && (a.indexOf('V') > 0 || a.indexOf('h') > 0))) {
                return false;
            }
        }
        return true;
    }

    /**
     * Renders by the resident process, starting one if needed; its standard output and error go to this
     * process's. Returns the run's exit code, or {@link #NOT_SERVED} (with a line on standard error saying why)
     * where no resident process could take it: the caller then renders itself.
     */
    static int run(String... args) {
        Map<String, String> env = System.getenv();
        try {
            String stamp = stamp(env); // stats every jar: once a run
            Path socket = socket(env, stamp);
            ResidentProtocol.Request request = new ResidentProtocol.Request(ResidentProtocol.RENDER, stamp,
                    Path.of("").toAbsolutePath().toString(), List.of(args));
            for (int attempt = 1; ; attempt++) {
                SocketChannel channel = connect(socket);
                if (channel == null) {
                    channel = awaitStart(socket, start(socket, stamp, env));
                }
                try (SocketChannel ch = channel) {
                    return exchange(ch, request, System.out, System.err);
                } catch (Unanswered e) {
                    if (attempt == 2) {
                        throw e;
                    }
                    // It was ending as this client connected (its last client stopped, its idle time out): once more.
                }
            }
        } catch (Refused e) {
            System.err.println("dempano: " + e.getMessage() + ": rendering in this process");
            return NOT_SERVED;
        } catch (IOException e) {
            // e.g. a folder where the socket should be: its path alone was the message
            System.err.println("dempano: no resident process (" + dempano.io.IoMessages.describe(e) + "): rendering in this process");
            return NOT_SERVED;
        } catch (RuntimeException e) {
            System.err.println("dempano: no resident process (" + e.getMessage() + "): rendering in this process");
            return NOT_SERVED;
        }
    }

    /**
     * Seconds a resident process may stay silent before the client gives it up: it acknowledges a run at once and
     * sends a heartbeat every {@link ResidentServer#HEARTBEAT_MILLIS} while the run lasts; status and stop are
     * answered at once. (Not final: a test waits less.)
     */
    static volatile int ANSWER_SECONDS = 15;

    /** The connection ended before the resident process answered at all (it was ending). */
    static final class Unanswered extends IOException {
        Unanswered(String message) {
            super(message);
        }
    }

    /** The resident process would not take the request (busy, another stamp); the message is why. */
    static final class Refused extends IOException {
        Refused(String reason) {
            super("the resident process " + reason);
        }
    }

    /**
     * Sends a request and copies the frames that come back to {@code out} and {@code err}; returns the exit code.
     *
     * @throws Refused      where the process would not take it
     * @throws IOException  where the connection ends without an exit code
     */
    static int exchange(SocketChannel ch, ResidentProtocol.Request request, PrintStream out, PrintStream err)
            throws IOException {
        try {
            request.write(new DataOutputStream(new java.io.BufferedOutputStream(ResidentProtocol.out(ch))));
        } catch (IOException e) {
            throw new Unanswered("the resident process could not be told the run (" + e.getMessage() + ")");
        }
        DataInputStream in = new DataInputStream(new java.io.BufferedInputStream(ResidentProtocol.in(ch)));
        // A process that accepts but never answers, or stops answering during the run (stopped, hung), must not hang
        // this client: after ANSWER_SECONDS without a frame the connection is closed, and the run renders here (status
        // and stop say so). Closing it also ends the resident process once it runs again (it notices the hang-up).
        Object log = logOf(socketOf(ch)); // while the channel is open (a closed one has no address)
        java.util.concurrent.atomic.AtomicLong lastFrame = new java.util.concurrent.atomic.AtomicLong(System.nanoTime());
        java.util.concurrent.atomic.AtomicBoolean finished = new java.util.concurrent.atomic.AtomicBoolean();
        java.util.concurrent.atomic.AtomicBoolean timedOut = new java.util.concurrent.atomic.AtomicBoolean();
        Thread watchdog = new Thread(() -> {
            long limit = ANSWER_SECONDS * 1_000_000_000L;
            try {
                while (!finished.get()) {
                    long silent = System.nanoTime() - lastFrame.get();
                    if (silent > limit) {
                        timedOut.set(true);
                        ch.close();
                        return;
                    }
                    Thread.sleep(Math.max(1, Math.min(250, (limit - silent) / 1_000_000 + 1)));
                }
            } catch (InterruptedException | IOException e) {
                // done either way
            }
        }, "dempano-resident-watchdog");
        watchdog.setDaemon(true);
        watchdog.start();
        try {
            return frames(in, out, err, lastFrame, timedOut, log);
        } finally {
            finished.set(true);
        }
    }

    /** The frames of one exchange, copied to {@code out} and {@code err}, until the exit code (see {@link #exchange}). */
    private static int frames(DataInputStream in, PrintStream out, PrintStream err,
                              java.util.concurrent.atomic.AtomicLong lastFrame,
                              java.util.concurrent.atomic.AtomicBoolean timedOut, Object log)
            throws IOException {
        for (boolean answered = false; ; answered = true) {
            ResidentProtocol.Frame f;
            try {
                f = ResidentProtocol.Frame.read(in);
                lastFrame.set(System.nanoTime());
            } catch (IOException e) {
                out.flush();
                String why = timedOut.get() ? "the resident process " + (answered ? "fell silent during the run for " : "did not answer within ")
                        + ANSWER_SECONDS + " s (stopped or hung? `kill` it; its log: " + log + ")"
                        : "the resident process ended before the run did (" + (e.getMessage() == null
                        ? e.getClass().getSimpleName() : e.getMessage()) + "; its log: " + log + ")";
                if (timedOut.get()) {
                    throw new IOException(why, e); // not again: a second wait would only double the delay
                }
                throw answered ? new IOException(why, e) : new Unanswered(why);
            }
            switch (f.type()) {
                case ResidentProtocol.OUT -> out.write(f.bytes(), 0, f.bytes().length);
                case ResidentProtocol.ERR -> err.write(f.bytes(), 0, f.bytes().length);
                case ResidentProtocol.EXIT -> {
                    out.flush();
                    err.flush();
                    return f.code();
                }
                case ResidentProtocol.REFUSED -> throw new Refused(f.reason());
                default -> throw new IOException("bad frame " + f.type());
            }
        }
    }

    private static Path socketOf(SocketChannel ch) {
        try {
            return ((UnixDomainSocketAddress) ch.getRemoteAddress()).getPath();
        } catch (IOException | RuntimeException e) {
            return Path.of("?");
        }
    }

    /** The log file of a resident process: its socket's name with {@code .log}. */
    static Path logOf(Path socket) {
        String name = socket.getFileName().toString();
        return socket.resolveSibling(name.replaceFirst("\\.sock$", "") + ".log");
    }

    /** A connection to the resident process at {@code socket}, or null where none listens (a stale file is removed). */
    static SocketChannel connect(Path socket) throws IOException {
        return connect(socket, true);
    }

    /**
     * A connection, or null where there is no socket file or nobody listens on it; {@code removeStale}: remove a file
     * nobody listens on (not while a process may be starting: between binding and listening it refuses too).
     */
    private static SocketChannel connect(Path socket, boolean removeStale) throws IOException {
        if (!Files.exists(socket, LinkOption.NOFOLLOW_LINKS)) {
            return null;
        }
        SocketChannel ch = SocketChannel.open(StandardProtocolFamily.UNIX);
        try {
            ch.connect(UnixDomainSocketAddress.of(socket));
            return ch;
        } catch (java.net.ConnectException | java.nio.file.NoSuchFileException e) {
            ch.close();
            if (removeStale && Files.exists(socket, LinkOption.NOFOLLOW_LINKS)) {
                if (!isSocket(socket)) { // a file of the user's own, say: not ours to remove
                    throw new IOException(socket + " is not a socket (left as it is)");
                }
                Files.deleteIfExists(socket); // left by a process that was killed: nobody listens
            }
            return null;
        } catch (IOException e) {
            ch.close();
            if (removeStale && Files.exists(socket, LinkOption.NOFOLLOW_LINKS)) {
                throw e;
            }
            return null; // (or removed as it ended, between the check above and connecting: none listens)
        }
    }

    /** Whether {@code path} itself (not a link's target) is a Unix socket. */
    private static boolean isSocket(Path path) {
        try {
            return ((Integer) Files.getAttribute(path, "unix:mode", LinkOption.NOFOLLOW_LINKS) & 0170000) == 0140000;
        } catch (IOException | RuntimeException e) {
            return false;
        }
    }

    /** Waits for the process {@code started} (or another client's, which won the socket) to accept. */
    private static SocketChannel awaitStart(Path socket, Process started) throws IOException {
        long until = System.nanoTime() + START_WAIT_MILLIS * 1_000_000;
        while (System.nanoTime() < until) {
            SocketChannel ch = connect(socket, false);
            if (ch != null) {
                return ch;
            }
            // It ends at once, with 0, where another process has the socket (keep waiting for that one to accept).
            if (!started.isAlive() && started.exitValue() != 0) {
                throw new IOException("the resident process could not start (exit " + started.exitValue()
                        + "; its log: " + logOf(socket) + ")");
            }
            try {
                Thread.sleep(20);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IOException("interrupted while the resident process started");
            }
        }
        throw new IOException("the resident process did not start within " + START_WAIT_MILLIS / 1000 + " s (its log: "
                + logOf(socket) + ")");
    }

    /** The longest socket path, bytes, that every Unix takes (Linux 107, macOS 103). */
    static final int MAX_SOCKET_PATH_BYTES = 100;

    /**
     * The socket of this user's resident process for this installation and setting ({@code stamp}: {@link #stamp}).
     *
     * @throws IOException where its path is too long for a Unix socket (a deep {@code DEMPANO_RESIDENT_DIR})
     */
    static Path socket(Map<String, String> env, String stamp) throws IOException {
        Path socket = directory(env).resolve(stamp + ".sock");
        int bytes = socket.toString().getBytes(java.nio.charset.StandardCharsets.UTF_8).length;
        if (bytes > MAX_SOCKET_PATH_BYTES) {
            throw new IOException("the socket path " + socket + " is " + bytes + " bytes, more than a Unix socket takes ("
                    + MAX_SOCKET_PATH_BYTES + "): set DEMPANO_RESIDENT_DIR to a shorter folder");
        }
        return socket;
    }

    /**
     * The folder of the resident processes' sockets and logs, made if missing, readable by this user alone.
     *
     * @throws IOException where it cannot be made, or others may write to it
     */
    static Path directory(Map<String, String> env) throws IOException {
        Path dir;
        String own = env.get("DEMPANO_RESIDENT_DIR"), runtime = env.get("XDG_RUNTIME_DIR");
        if (own != null && !own.isBlank()) {
            dir = Path.of(own);
        } else if (runtime != null && !runtime.isBlank() && Files.isDirectory(Path.of(runtime))) {
            dir = Path.of(runtime, "dempano");
        } else {
            dir = Path.of(System.getProperty("user.home"), ".cache", "dempano", "resident");
        }
        dir = dir.toAbsolutePath();
        Set<PosixFilePermission> ownerOnly = PosixFilePermissions.fromString("rwx------");
        if (!Files.isDirectory(dir)) {
            Files.createDirectories(dir.getParent());
            try {
                Files.createDirectory(dir, PosixFilePermissions.asFileAttribute(ownerOnly));
            } catch (java.nio.file.FileAlreadyExistsException e) {
                // made meanwhile by another client
            }
        }
        if (!Files.isDirectory(dir)) {
            throw new IOException(dir + " is not a folder");
        }
        Set<PosixFilePermission> p = Files.getPosixFilePermissions(dir);
        if (!Files.getOwner(dir).getName().equals(System.getProperty("user.name"))
                || p.contains(PosixFilePermission.GROUP_WRITE) || p.contains(PosixFilePermission.OTHERS_WRITE)) {
            throw new IOException(dir + " is not this user's alone (owner " + Files.getOwner(dir).getName() + ", "
                    + PosixFilePermissions.toString(p) + ")");
        }
        return dir;
    }

    /** Environment variables that can change a run's result or its GL context, all kept in the stamp. */
    private static boolean shapesTheRun(String name) {
        // The JVM's own option variables and the dynamic linker's too: a process started under JDK_JAVA_OPTIONS=-Xmx24m
        // served every later client, whose runs then failed for want of heap.
        return Set.of("DEMPANO_CACHE_DIR", "XDG_CACHE_HOME", "DEMPANO_GL", "DEMPANO_DEBUG", "DISPLAY", "WAYLAND_DISPLAY",
                "DEMPANO_RESIDENT_IDLE_S", "JDK_JAVA_OPTIONS", "JAVA_TOOL_OPTIONS", "_JAVA_OPTIONS", "LD_LIBRARY_PATH",
                "LD_PRELOAD", "LANG", "LANGUAGE", "TZ").contains(name)
                // The locale: the JVM takes its file-name and console encodings from it at start (a process started under
                // LC_ALL=POSIX refused a later UTF-8 client's output name with an accent, which renders in a process of its own).
                || name.startsWith("LC_")
                || List.of("MESA_", "LIBGL_", "GALLIUM_", "LP_", "EGL_", "__GL", "__EGL").stream().anyMatch(name::startsWith);
    }

    /** The JVM's options as it was started (the class path left out: the stamp lists it file by file). */
    static List<String> jvmOptions() {
        List<String> all = ProcessHandle.current().info().arguments().map(List::of).orElse(null);
        if (all == null) {
            all = java.lang.management.ManagementFactory.getRuntimeMXBean().getInputArguments();
        }
        List<String> out = new ArrayList<>();
        for (int i = 0; i < all.size(); i++) {
            String a = all.get(i);
            if (a.equals(Main.class.getName()) || !a.startsWith("-")) {
                break; // the main class: the program's arguments follow
            }
            if (a.equals("-classpath") || a.equals("-cp") || a.equals("--class-path")) {
                i++;
                continue;
            }
            out.add(a);
        }
        return out;
    }

    /** Every class path entry's absolute path, size and modification time, a line each. */
    static String classPath() {
        StringBuilder s = new StringBuilder();
        for (String entry : System.getProperty("java.class.path").split(File.pathSeparator)) {
            File f = new File(entry);
            s.append(f.getAbsolutePath()).append(' ').append(f.length()).append(' ').append(f.lastModified()).append('\n');
        }
        return s.toString();
    }

    /**
     * A hash (16 hex digits) of what a run's result may depend on besides its arguments and working directory
     * (see the class comment).
     */
    /** This process's file-creation mask ("0022"), from /proc (Linux); "" where it cannot be read. */
    static String umask() {
        try {
            for (String line : Files.readAllLines(Path.of("/proc/self/status"))) {
                if (line.startsWith("Umask:")) {
                    return line.substring("Umask:".length()).trim();
                }
            }
        } catch (IOException | RuntimeException e) {
            // not Linux: every client shares a process, as before
        }
        return "";
    }

    /**
     * The environment with a relative {@code DEMPANO_CACHE_DIR} or {@code XDG_CACHE_HOME} made absolute against the
     * client's working directory, as a local run takes it: the resident process, whose working directory is its socket
     * folder, put the cache there instead (and clients in other folders shared it).
     */
    static Map<String, String> withAbsoluteCacheDirs(Map<String, String> env) {
        Map<String, String> out = new java.util.HashMap<>(env);
        for (String k : List.of("DEMPANO_CACHE_DIR", "XDG_CACHE_HOME")) {
            String v = env.get(k);
            if (v != null && !v.isBlank() && !v.equalsIgnoreCase("off") && !Path.of(v).isAbsolute()) {
                out.put(k, Path.of(v).toAbsolutePath().normalize().toString());
            }
        }
        return out;
    }

    static String stamp(Map<String, String> env) {
        StringBuilder s = new StringBuilder();
        s.append(System.getProperty("java.home")).append('\n').append(System.getProperty("java.vm.version")).append('\n');
        jvmOptions().forEach(o -> s.append(o).append('\n'));
        s.append(classPath());
        new TreeMap<>(withAbsoluteCacheDirs(env)).forEach((k, v) -> {
            if (shapesTheRun(k)) {
                s.append(k).append('=').append(v).append('\n');
            }
        });
        // The umask too: the process writes the files with its own, which it inherits from the client that started it
        // (a client with umask 077 got files readable by all from a process started under 022).
        s.append("umask=").append(umask()).append('\n');
        long h = 0xCBF29CE484222325L;
        for (int i = 0; i < s.length(); i++) {
            h = (h ^ s.charAt(i)) * 0x100000001B3L;
        }
        return String.format("%016x", h);
    }

    /** Starts a resident process for {@code socket}, detached from this terminal's process group where possible. */
    private static Process start(Path socket, String stamp, Map<String, String> env) throws IOException {
        List<String> cmd = new ArrayList<>();
        for (String setsid : List.of("/usr/bin/setsid", "/bin/setsid")) {
            if (Files.isExecutable(Path.of(setsid))) {
                cmd.add(setsid); // Ctrl-C in this terminal later reaches only the client, which passes it on
                break;
            }
        }
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        // The client's own options, the client compiler alone included: with both compilers the process was faster
        // once warm (1.36 against 1.51 s a Mount Washington run) but its first runs were slower (6.0, 2.2, 2.0 s),
        // and 20 nearby viewpoints took longer in all (docs/cold-start.md).
        List<String> options = jvmOptions();
        cmd.addAll(options);
        if (options.stream().noneMatch(o -> o.startsWith("-XX:G1PeriodicGCInterval"))) {
            cmd.add("-XX:G1PeriodicGCInterval=60000"); // an idle process gives unused heap back to the system
        }
        cmd.add("-cp");
        cmd.add(System.getProperty("java.class.path"));
        cmd.add(ResidentServer.class.getName());
        cmd.add(socket.toString());
        cmd.add(stamp);
        cmd.add(Integer.toString(idleSeconds(env)));
        ProcessBuilder pb = new ProcessBuilder(cmd);
        pb.environment().putAll(withAbsoluteCacheDirs(pb.environment()));
        // Its own folder as working directory: every path of a run is the client's, resolved; and the folder this
        // client was started in is not held (kept from removal or unmounting) for as long as the process lives.
        pb.directory(socket.getParent().toFile());
        pb.redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")));
        File log = logOf(socket).toFile();
        pb.redirectOutput(ProcessBuilder.Redirect.appendTo(log));
        pb.redirectErrorStream(true);
        return pb.start();
    }

    /** The idle time of a resident process, seconds: {@code DEMPANO_RESIDENT_IDLE_S}, else the default. */
    static int idleSeconds(Map<String, String> env) {
        String v = env.get("DEMPANO_RESIDENT_IDLE_S");
        if (v == null || v.isBlank()) {
            return DEFAULT_IDLE_SECONDS;
        }
        try {
            int s = Integer.parseInt(v.trim());
            if (s >= 1) {
                return s;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        throw new IllegalArgumentException("DEMPANO_RESIDENT_IDLE_S must be a whole number of seconds in [1, "
                + Integer.MAX_VALUE + "], got " + v);
    }
}
