package dempano.cli;

import dempano.PanoramaRenderer;
import dempano.dem.DemSource;
import dempano.dem.HgtTile;
import dempano.dem.TileId;
import dempano.render.GlUnavailableException;
import dempano.render.RenderFailedException;
import dempano.terrain.DeviationStore;
import java.io.DataInputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.net.StandardProtocolFamily;
import java.net.UnixDomainSocketAddress;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * The resident process ({@code DEMPANO_RESIDENT=on}, started by {@link ResidentClient}): renders the panoramas
 * that start scripts hand it, one at a time, with one OpenGL renderer kept open from run to run, so that a run
 * from the shell costs a warm render instead of a JVM's, a GL context's and a mesh's start (docs/cold-start.md).
 *
 * <p>What it keeps, and what keeps it right: the GL context; the renderer's patch deviations and meshes, which
 * are dropped wherever a tile's heights changed (each run opens its DEM folders afresh, so a file added, removed
 * or rewritten since is seen, and the renderer compares every tile it is given with those it built from:
 * {@link dempano.terrain.DeviationCache#forgetChanged}); nothing else from run to run. Relative paths are the
 * client's (its working directory travels with the request). It serves only clients of its own stamp (the
 * same installation, JVM options and environment: {@link ResidentClient#stamp}).
 *
 * <p>How it ends: after its idle time without a request; on {@code dempano resident stop}; when its socket file
 * is removed or replaced; when a jar of its class path changes (dempano rebuilt or reinstalled: clients then
 * have another stamp and start another process); when a client goes away during its run (Ctrl-C: the run stops as a killed process's
 * does, and the next run on that output prefix clears what it left); after a run whose renderer failed (no
 * OpenGL, a failed GL thread, out of memory), so that the next run starts afresh.
 */
public final class ResidentServer {
    private final Path socket;
    private final String stamp;
    private final Duration idle;
    private final Instant started = Instant.now();
    final AtomicBoolean busy = new AtomicBoolean();
    private volatile Instant lastActivity = Instant.now();
    private volatile int runs;
    private volatile boolean stopRequested;
    /** Whether the heap was collected since the last run (see {@link #IDLE_COLLECT}). */
    private volatile boolean collected = true;
    /**
     * Idle time after which the heap is collected once (a full collection, which returns what the runs left to the
     * system): back-to-back runs over several areas grew the process to 2.8 GB of resident memory, most of it garbage
     * the collector had no reason to collect yet.
     */
    static final Duration IDLE_COLLECT = Duration.ofSeconds(5);
    /**
     * What a client's going away during its run does: end this process at once, as a Ctrl-C ends a process
     * rendering in the shell (tests put something else here).
     */
    Runnable onHangUp = () -> {
        closeQuietly(); // no new client may connect to a process that is ending (the exit itself takes a while)
        dempano.io.OutputSet.discardUncommitted(); // halt runs no shutdown hook: the run's staging folder, removed here
        Runtime.getRuntime().halt(130);
    };
    /**
     * Milliseconds between the empty frames a run sends while it lasts, so that its client tells a long silent stage
     * from a stopped or hung process ({@link ResidentClient#ANSWER_SECONDS}). (Not final: a test sends them faster.)
     */
    static volatile long HEARTBEAT_MILLIS = 2000;
    /** Run before each render (tests make a long silent run with it). */
    Runnable beforeRender = () -> { };
    private final KeptRenderer renderers = new KeptRenderer();
    private ServerSocketChannel server;
    /** The socket file's identity (inode) once bound. */
    private Object fileKey;
    /** Every class path entry's path, size and modification time when this process started. */
    private final String classPath = ResidentClient.classPath();

    ResidentServer(Path socket, String stamp, Duration idle) {
        this.socket = socket;
        this.stamp = stamp;
        this.idle = idle;
    }

    /** {@code ResidentServer SOCKET STAMP IDLE_SECONDS}: what {@link ResidentClient} starts. */
    public static void main(String[] args) throws Exception {
        System.setProperty("java.awt.headless", "true"); // as Main: a dead DISPLAY must not end the process
        if (args.length != 3) {
            System.err.println("usage: ResidentServer SOCKET STAMP IDLE_SECONDS (started by dempano itself)");
            System.exit(2);
        }
        ResidentServer s = new ResidentServer(Path.of(args[0]), args[1], Duration.ofSeconds(Long.parseLong(args[2])));
        if (!s.bind()) {
            System.exit(0); // another resident process took the socket first: it serves
        }
        log("resident process " + ProcessHandle.current().pid() + " listening on " + s.socket);
        s.serve();
        log("resident process " + ProcessHandle.current().pid() + " ends");
        System.exit(0);
    }

    /** The process's own standard output (its log file), kept: during a run System.out is the client's. */
    private static final PrintStream LOG = System.out;

    private static void log(String line) {
        LOG.println(Instant.now() + " " + line);
        LOG.flush();
    }

    /** Binds the socket; false where another process already listens there. */
    boolean bind() throws IOException {
        server = ServerSocketChannel.open(StandardProtocolFamily.UNIX);
        try {
            server.bind(UnixDomainSocketAddress.of(socket));
            fileKey = Files.readAttributes(socket, java.nio.file.attribute.BasicFileAttributes.class,
                    java.nio.file.LinkOption.NOFOLLOW_LINKS).fileKey();
            return true;
        } catch (java.net.BindException e) {
            server.close();
            return false;
        }
    }

    /** Accepts requests until one of the ends in the class comment; the socket file is removed at the end. */
    void serve() throws IOException {
        Thread watch = new Thread(() -> {
            while (server.isOpen()) {
                try {
                    Thread.sleep(1000);
                } catch (InterruptedException e) {
                    return;
                }
                if (busy.get()) {
                    continue; // a run under way is finished first
                }
                Duration idleFor = Duration.between(lastActivity, Instant.now());
                if (!collected && idleFor.compareTo(IDLE_COLLECT) > 0) {
                    collected = true;
                    System.gc();
                }
                boolean idleOut = idleFor.compareTo(idle) > 0;
                boolean reinstalled = !classPath.equals(ResidentClient.classPath());
                if ((idleOut || reinstalled || !ours()) && server.isOpen()) {
                    log(idleOut ? "idle for " + idle.toSeconds() + " s" : reinstalled
                            ? "its class path changed (dempano rebuilt or reinstalled): clients use another process now"
                            : "socket file removed or replaced");
                    closeQuietly();
                }
            }
        }, "dempano-resident-watch");
        watch.setDaemon(true);
        watch.start();
        try {
            while (server.isOpen()) {
                SocketChannel ch;
                try {
                    ch = server.accept();
                } catch (java.nio.channels.AsynchronousCloseException e) {
                    break;
                }
                Thread t = new Thread(() -> handle(ch), "dempano-resident-connection");
                t.setDaemon(true);
                t.start();
            }
        } finally {
            closeQuietly();
            // A run under way (stop asked for during it, the socket file removed) is finished before the end.
            while (busy.get()) {
                try {
                    Thread.sleep(50);
                } catch (InterruptedException e) {
                    break;
                }
            }
            renderers.close();
        }
    }

    /** Whether the socket file is still the one this process bound (not removed, not another process's). */
    private boolean ours() {
        try {
            return fileKey != null && fileKey.equals(Files.readAttributes(socket,
                    java.nio.file.attribute.BasicFileAttributes.class, java.nio.file.LinkOption.NOFOLLOW_LINKS).fileKey());
        } catch (IOException e) {
            return false;
        }
    }

    /** Stops accepting, and removes the socket file where it is still this process's. */
    private synchronized void closeQuietly() {
        try {
            if (server.isOpen()) {
                if (ours()) {
                    Files.deleteIfExists(socket); // first: once closed, serve() may return at once
                }
                server.close();
            }
        } catch (IOException e) {
            // ending anyway
        }
    }

    /**
     * One connection: a request and its answer. Status is answered at once; stop ends this process after the run
     * under way, if any; a render is refused while another runs (its client renders itself).
     */
    private void handle(SocketChannel ch) {
        try (ch) {
            DataInputStream in = new DataInputStream(ResidentProtocol.in(ch));
            ResidentProtocol.Request req = ResidentProtocol.Request.read(in);
            ResidentProtocol.Writer w = new ResidentProtocol.Writer(ResidentProtocol.out(ch));
            // Status and stop come from `dempano resident`, which asks every process in the (user's own) folder.
            if (!req.stamp().equals(stamp) && req.kind().equals(ResidentProtocol.RENDER)) {
                w.refused("serves another installation or setting");
                return;
            }
            switch (req.kind()) {
                case ResidentProtocol.STATUS -> answer(w, status());
                case ResidentProtocol.STOP -> {
                    log("stop requested");
                    stopRequested = true;
                    answer(w, busy.get() ? "the resident process " + ProcessHandle.current().pid()
                            + " ends after the run under way" : "stopped the resident process " + ProcessHandle.current().pid());
                    if (!busy.get()) {
                        closeQuietly();
                    }
                }
                case ResidentProtocol.RENDER -> {
                    if (!busy.compareAndSet(false, true)) {
                        w.refused("is busy with another run");
                        return;
                    }
                    boolean released = false;
                    try {
                        // Taken: the client's first frame, at once. Within the try: a client gone before it (it gave
                        // up waiting on a stopped process) must not leave this process busy for good.
                        w.bytes(ResidentProtocol.ERR, new byte[0], 0, 0);
                        int code = render(in, req, w);
                        if (stopRequested || renderers.broken) {
                            log(stopRequested ? "ending, as requested" : "the renderer failed: ending, so that the next run starts afresh");
                            closeQuietly(); // busy until the exit code is sent: the process ends after that
                        } else {
                            // Free before the client hears the exit code: its next run may come at once.
                            lastActivity = Instant.now();
                            collected = false;
                            released = true;
                            busy.set(false);
                        }
                        w.exit(code);
                    } finally {
                        if (!released) {
                            busy.set(false); // ending, or failed before its exit code (the client gone)
                        }
                    }
                }
                default -> w.refused("cannot do '" + req.kind() + "'");
            }
        } catch (IOException | RuntimeException e) {
            log("request failed: " + e);
        }
    }

    private static void answer(ResidentProtocol.Writer w, String text) throws IOException {
        byte[] b = (text + "\n").getBytes(StandardCharsets.UTF_8);
        w.bytes(ResidentProtocol.OUT, b, 0, b.length);
        w.exit(0);
    }

    /** Runs a render request with its output framed back; returns its exit code (the caller sends it). */
    private int render(DataInputStream in, ResidentProtocol.Request req, ResidentProtocol.Writer w) {
        int run = ++runs;
        log("run " + run + " in " + req.workingDir() + ": " + String.join(" ", req.args()));
        // The client sends nothing more: the end of its stream means it went away (Ctrl-C). Stop as a killed
        // process would; the output set's staging folder is cleared by the next run on its prefix.
        AtomicBoolean done = new AtomicBoolean();
        Thread hangUp = new Thread(() -> {
            try {
                int b = in.read();
                if (b < 0 && !done.get()) {
                    log("client went away during run " + run + ": ending");
                    onHangUp.run();
                }
            } catch (IOException e) {
                if (!done.get()) {
                    log("client connection failed during run " + run + " (" + e.getMessage() + "): ending");
                    onHangUp.run();
                }
            }
        }, "dempano-resident-hangup");
        hangUp.setDaemon(true);
        hangUp.start();
        Thread heartbeat = new Thread(() -> {
            try {
                while (!done.get()) {
                    Thread.sleep(HEARTBEAT_MILLIS);
                    if (!done.get()) {
                        w.bytes(ResidentProtocol.ERR, new byte[0], 0, 0);
                    }
                }
            } catch (InterruptedException | IOException e) {
                // its client went away (the hang-up thread sees to that)
            }
        }, "dempano-resident-heartbeat");
        heartbeat.setDaemon(true);
        heartbeat.start();
        PrintStream out = System.out, err = System.err;
        PrintStream runOut = new PrintStream(w.stream(ResidentProtocol.OUT), true, StandardCharsets.UTF_8);
        PrintStream runErr = new PrintStream(w.stream(ResidentProtocol.ERR), true, StandardCharsets.UTF_8);
        int code;
        System.setOut(runOut);
        System.setErr(runErr);
        try {
            runErr.printf(Locale.ROOT, "  resident process %d, run %d%n", ProcessHandle.current().pid(), run);
            beforeRender.run();
            code = Main.run(new RunContext(Path.of(req.workingDir()), renderers), req.args().toArray(String[]::new));
            runOut.flush();
            runErr.flush();
        } finally {
            System.setOut(out);
            System.setErr(err);
            done.set(true); // the heartbeat ends at its next wake-up (an interrupt during its write would close the channel)
        }
        log("run " + run + " exit " + code);
        return code;
    }

    /** What {@code dempano resident status} prints. */
    String status() {
        Runtime rt = Runtime.getRuntime();
        return String.format(Locale.ROOT, "resident process %d: up %d s, %d runs, heap %.0f MB used of %.0f MB, "
                        + "resident memory %s; ends after %d s idle (DEMPANO_RESIDENT_IDLE_S); socket %s",
                ProcessHandle.current().pid(), Duration.between(started, Instant.now()).toSeconds(), runs,
                (rt.totalMemory() - rt.freeMemory()) / 1e6, rt.maxMemory() / 1e6, residentMemory(), idle.toSeconds(), socket);
    }

    /** This process's resident memory (VmRSS of /proc/self/status), or "unknown". */
    private static String residentMemory() {
        try {
            for (String line : Files.readAllLines(Path.of("/proc/self/status"))) {
                if (line.startsWith("VmRSS:")) {
                    return String.format(Locale.ROOT, "%.0f MB", Long.parseLong(line.replaceAll("\\D", "")) / 1e3);
                }
            }
        } catch (IOException | RuntimeException e) {
            // not Linux
        }
        return "unknown";
    }

    /**
     * One OpenGL renderer kept open from run to run over a DEM source that each run sets (its folders opened
     * afresh); the CPU reference is opened per run.
     */
    static final class KeptRenderer implements Main.Renderers {
        private final Switching dem = new Switching();
        private PanoramaRenderer gl;
        volatile boolean broken;

        @Override
        public Lease lease(DemSource source, boolean reference, int repeat) {
            if (reference) {
                return PER_RUN.lease(source, true, repeat);
            }
            dem.now = source;
            if (gl == null) {
                gl = PanoramaRenderer.openInBackground(dem).withDeviationStore(DeviationStore.userDefault());
            }
            return new Lease(gl, () -> { }); // kept for the next run
        }

        @Override
        public void failed(Throwable t) {
            if (t instanceof GlUnavailableException || t instanceof RenderFailedException || t instanceof Error) {
                broken = true;
            }
        }

        void close() {
            if (gl != null) {
                gl.close();
                gl = null;
            }
        }
    }

    /** The DEM source of the run under way. */
    private static final class Switching implements DemSource {
        volatile DemSource now;

        @Override
        public Optional<HgtTile> tile(TileId id) {
            return now.tile(id);
        }

        @Override
        public String describe() {
            return now.describe();
        }
    }
}
