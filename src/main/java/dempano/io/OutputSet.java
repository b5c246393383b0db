package dempano.io;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonParser;
import java.io.BufferedOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.DirectoryStream;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.security.SecureRandom;
import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The files of one output prefix P ({@code P.png}, {@code P-distance.npy}, …, {@code P.json}) written
 * as one set: after any failure or crash, the folder holds the complete previous set or the complete
 * new one, never a mix.
 *
 * <p>How: every file is first written into a hidden staging folder beside the outputs
 * ({@code .P.dempano-<pid>-<start>-<random>}), with the permissions any new file gets (the umask).
 * {@link #commit()} then writes a commit mark into the staging folder (the point of no return),
 * deletes the previous {@code P.json} and the previous set's files that the new set does not have
 * (the old JSON's {@code files} list), renames each staged file into place and {@code P.json} last.
 * So {@code P.json}, when present, always describes the files beside it. A process killed before the
 * mark leaves a staging folder that the next {@link #open} of the same prefix deletes; killed after
 * it, the next open finishes the renames (roll forward). Staging folders of a live process are left
 * alone. Commits and recovery of one prefix are serialized within the JVM and, through a short-lived
 * lock file {@code .P.dempano-lock}, across processes.
 *
 * <p>Not covered: a power cut (files are not forced to disk) and writers that bypass this class.
 */
public final class OutputSet implements AutoCloseable {
    private static final String STAGING_INFIX = ".dempano-";
    private static final String COMMIT_MARK = "COMMIT";
    private static final Pattern STAGING_SUFFIX = Pattern.compile("(\\d+)-(\\d+)-([0-9a-f]{8})");
    private static final SecureRandom RANDOM = new SecureRandom();
    /** Staging folders of this JVM in use (a folder of our pid not listed here is stale). */
    private static final Set<Path> ACTIVE = ConcurrentHashMap.newKeySet();
    /** In-JVM serialization of commits and recovery, by prefix (file locks are per process). */
    private static final Object[] STRIPES = new Object[64];

    static {
        for (int i = 0; i < STRIPES.length; i++) {
            STRIPES[i] = new Object();
        }
    }

    private static final java.util.concurrent.atomic.AtomicBoolean CLEANUP_HOOKED = new java.util.concurrent.atomic.AtomicBoolean();
    private static final Set<Runnable> FINISHING = ConcurrentHashMap.newKeySet();

    /**
     * Registers work that an interrupted process lets finish before the exit cleanup discards the uncommitted sets (a
     * batch finishes the row in progress on Ctrl-C): {@code awaitDone} blocks until that work is done or given up,
     * and the cleanup runs it first. Unregister with {@link #noLongerFinishing}.
     */
    public static void finishBeforeCleanup(Runnable awaitDone) {
        FINISHING.add(awaitDone);
    }

    /** Undoes {@link #finishBeforeCleanup}. */
    public static void noLongerFinishing(Runnable awaitDone) {
        FINISHING.remove(awaitDone);
    }

    /**
     * Removes this JVM's staging folders that were never committed (run at exit, Ctrl-C included): the previous sets
     * stay as they were, and no hidden folder of half-written files is left for the next run of the prefix to find. A
     * folder whose commit has begun is left alone under the prefix's lock (the commit finishes first, or the next
     * run finishes it). Public for a process that ends by {@code Runtime.halt} (no hooks run): the resident process
     * when its client goes away.
     */
    public static void discardUncommitted() {
        for (Runnable finishing : List.copyOf(FINISHING)) {
            try {
                finishing.run(); // an orderly end in progress (a batch's row being finished): its commit comes first
            } catch (RuntimeException e) {
                // given up: what it left uncommitted is discarded below
            }
        }
        for (Path staging : List.copyOf(ACTIVE)) {
            String name = staging.getFileName().toString();
            int infix = name.lastIndexOf(STAGING_INFIX);
            if (infix <= 1) {
                continue;
            }
            try {
                withLock(staging.getParent(), name.substring(1, infix), () -> {
                    if (ACTIVE.contains(staging) && !Files.exists(staging.resolve(COMMIT_MARK))) {
                        deleteTree(staging);
                        ACTIVE.remove(staging);
                    }
                });
            } catch (IOException | RuntimeException e) {
                // left for the next run of the prefix, which removes it
            }
        }
    }

    /** Test hook: told each step of a commit ("staged NAME", "marked", "moved NAME"); a no-op otherwise. */
    static volatile Consumer<String> checkpoint = step -> { };

    private final String prefix;
    private final Path directory;
    private final String base;
    private final Path staging;
    private final Map<String, Path> staged = new LinkedHashMap<>();
    private final Map<Path, String> inputs = new LinkedHashMap<>();
    private boolean done;

    private OutputSet(String prefix, Path directory, String base, Path staging) {
        this.prefix = prefix;
        this.directory = directory;
        this.base = base;
        this.staging = staging;
    }

    /**
     * Starts a set for a prefix: checks it names files in an existing, writable folder, finishes or
     * removes what a killed earlier run left for this prefix, and creates the staging folder. Call it
     * before the expensive work, so that an unwritable destination is found first.
     *
     * @param prefix a path whose last part is the start of a file name ({@code out/p} → {@code out/p.png})
     * @throws IllegalArgumentException for an empty prefix or one that names a folder ({@code out/})
     * @throws IOException naming the prefix, the folder and the reason when files cannot be created there
     */
    /** The longest file name, bytes, on Linux's file systems (ext4, xfs, btrfs, tmpfs). */
    static final int MAX_NAME_BYTES = 255;

    public static OutputSet open(String prefix) throws IOException {
        Path abs = checkPrefix(prefix);
        Path dir = abs.getParent();
        String base = abs.getFileName().toString();
        if (!Files.exists(dir)) {
            throw new IOException("cannot write " + prefix + ".*: folder " + dir + " does not exist");
        }
        if (!Files.isDirectory(dir)) {
            throw new IOException("cannot write " + prefix + ".*: " + dir + " is a file, not a folder");
        }
        long start = ProcessHandle.current().info().startInstant().map(i -> i.toEpochMilli()).orElse(0L);
        String stagingName = "." + base + STAGING_INFIX + ProcessHandle.current().pid() + "-" + start + "-"
                + String.format("%08x", RANDOM.nextInt());
        int nameBytes = base.getBytes(java.nio.charset.StandardCharsets.UTF_8).length;
        int extra = stagingName.getBytes(java.nio.charset.StandardCharsets.UTF_8).length - nameBytes;
        if (nameBytes + extra > MAX_NAME_BYTES) {
            // The hidden staging folder is the longest name a set needs; a prefix whose outputs all fit failed there with
            // "file name too long", which did not say what to shorten.
            throw new IOException("cannot write " + prefix + ".*: its last part is " + nameBytes + " bytes long, at most "
                    + (MAX_NAME_BYTES - extra) + " fit (file names have at most " + MAX_NAME_BYTES + " bytes, and the"
                    + " hidden folder the files are staged in adds " + extra + "): shorten it");
        }
        try {
            withLock(dir, base, () -> recover(dir, base));
        } catch (IOException e) {
            throw new IOException("cannot write " + prefix + ".*: cannot create files in " + dir + " ("
                    + IoMessages.reason(e) + ")", e);
        }
        Path staging = dir.resolve(stagingName);
        try {
            Files.createDirectory(staging);
        } catch (IOException e) {
            throw new IOException("cannot write " + prefix + ".*: cannot create files in " + dir + " ("
                    + IoMessages.reason(e) + ")", e);
        }
        ACTIVE.add(staging);
        if (CLEANUP_HOOKED.compareAndSet(false, true)) {
            Runtime.getRuntime().addShutdownHook(new Thread(OutputSet::discardUncommitted, "dempano-output-cleanup"));
        }
        return new OutputSet(prefix, dir, base, staging);
    }

    /**
     * Checks an output prefix without touching the disk.
     *
     * @return the prefix as an absolute path
     * @throws IllegalArgumentException for null, blank, or a prefix that ends in a folder
     */
    public static Path checkPrefix(String prefix) {
        if (prefix == null || prefix.isBlank()) {
            throw new IllegalArgumentException("the output prefix is empty: give a path such as out/panorama");
        }
        if (prefix.endsWith("/") || prefix.endsWith(File.separator)) {
            throw new IllegalArgumentException("the output prefix '" + prefix + "' names a folder: add the start of a "
                    + "file name, such as " + prefix + "panorama");
        }
        Path abs;
        try {
            abs = Path.of(prefix).toAbsolutePath().normalize();
        } catch (InvalidPathException e) {
            throw new IllegalArgumentException("the output prefix '" + prefix + "' is not a valid path: " + e.getReason());
        }
        String name = Path.of(prefix).getFileName() == null ? "" : Path.of(prefix).getFileName().toString();
        if (abs.getParent() == null || name.isEmpty() || name.equals(".") || name.equals("..")) {
            throw new IllegalArgumentException("the output prefix '" + prefix + "' names a folder: add the start of a "
                    + "file name, such as " + prefix + "/panorama");
        }
        return abs;
    }

    /** The final path of the file with this suffix ({@code "-distance.npy"} → {@code P-distance.npy}). */
    public Path target(String suffix) {
        return Path.of(prefix + suffix);
    }

    /**
     * Checks that none of the files the set will have is blocked by a folder or other non-file of
     * the same name (call it before the expensive work).
     *
     * @throws IOException naming the blocked file
     */
    public void checkTargets(Collection<String> suffixes) throws IOException {
        for (String s : suffixes) {
            Path t = directory.resolve(base + s);
            if (Files.exists(t, LinkOption.NOFOLLOW_LINKS) && !Files.isRegularFile(t, LinkOption.NOFOLLOW_LINKS)
                    && !Files.isSymbolicLink(t)) {
                throw new IOException("cannot write " + target(s) + ": "
                        + (Files.isDirectory(t) ? "a folder" : "something that is not a file") + " of that name is in the way");
            }
            String input = inputAt(t);
            if (input != null) {
                throw new IOException("cannot write " + target(s) + ": it is " + input + ", which this run reads;"
                        + " choose another output prefix");
            }
        }
    }

    /**
     * Names a file the run reads (a photo, a summit list), which the set must neither overwrite nor, as a file of
     * the previous set, delete: {@link #checkTargets} and {@link #write} refuse a target that is the same file
     * (links followed). Call before writing.
     *
     * @param input the file; null: nothing
     * @param what  what it is, for the message ("the photo IMAGE")
     * @return this set
     */
    public OutputSet protect(Path input, String what) {
        if (input != null) {
            inputs.put(input, what);
        }
        return this;
    }

    /** What the protected input at {@code target} is, or null when it is none of them. */
    private String inputAt(Path target) {
        if (inputs.isEmpty() || !Files.exists(target)) {
            return null;
        }
        for (Map.Entry<Path, String> in : inputs.entrySet()) {
            try {
                if (Files.exists(in.getKey()) && Files.isSameFile(target, in.getKey())) {
                    return in.getValue() + " (" + in.getKey() + ")";
                }
            } catch (IOException e) {
                // cannot tell: not the same file as far as this run can see
            }
        }
        return null;
    }

    /**
     * Writes one file of the set into the staging folder.
     *
     * @param suffix what follows the prefix, e.g. {@code ".png"}, {@code "-distance.npy"}
     * @return the path the file will have once committed
     * @throws IOException naming that final path and the reason
     */
    public Path write(String suffix, AtomicFiles.Body body) throws IOException {
        if (done) {
            throw new IllegalStateException("the output set for " + prefix + " is already committed or closed");
        }
        String name = base + suffix;
        if (name.contains("/") || name.contains(File.separator) || staged.containsKey(name)) {
            throw new IllegalArgumentException("bad or repeated output suffix '" + suffix + "'");
        }
        Path target = target(suffix);
        checkTargets(List.of(suffix));
        Path file = staging.resolve(name);
        try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(file, StandardOpenOption.CREATE_NEW,
                StandardOpenOption.WRITE), 1 << 16)) {
            body.writeTo(out);
        } catch (IOException e) {
            Files.deleteIfExists(file);
            throw new IOException("cannot write " + target + ": " + IoMessages.reason(e), e);
        }
        synchronized (staged) {
            staged.put(name, file);
        }
        checkpoint.accept("staged " + name);
        return target;
    }

    /**
     * Replaces the previous set by the files written: the previous {@code P.json} and the previous
     * set's files the new set lacks are deleted, the new files renamed into place, {@code P.json} last.
     *
     * @throws IOException naming the file that could not be put in place (the commit is then
     *                     finished by the next {@link #open} of this prefix)
     */
    public void commit() throws IOException {
        if (done) {
            throw new IllegalStateException("the output set for " + prefix + " is already committed or closed");
        }
        checkTargets(staged.keySet().stream().map(n -> n.substring(base.length())).toList());
        IOException[] failure = new IOException[1];
        withLock(directory, base, () -> {
            List<String> removals = new ArrayList<>(previousFilesNotIn(directory, base, staged.keySet()));
            removals.removeIf(n -> inputAt(directory.resolve(n)) != null); // an input listed by the previous set stays
            Path markTmp = staging.resolve(COMMIT_MARK + ".part");
            Files.writeString(markTmp, String.join("\n", removals) + "\n", StandardCharsets.UTF_8);
            Files.move(markTmp, staging.resolve(COMMIT_MARK), StandardCopyOption.ATOMIC_MOVE);
            checkpoint.accept("marked");
            try {
                rollForward(directory, base, staging);
            } catch (IOException e) {
                failure[0] = e;
            }
        });
        done = true;
        ACTIVE.remove(staging);
        if (failure[0] != null) {
            throw new IOException("cannot put the outputs for " + prefix + " in place (" + IoMessages.reason(failure[0])
                    + "); the next run with this prefix finishes it", failure[0]);
        }
    }

    /** Discards an uncommitted set (its staging folder); the previous set stays as it was. */
    @Override
    public void close() {
        if (!done) {
            done = true;
            deleteTree(staging);
            ACTIVE.remove(staging);
        }
    }

    private interface LockedWork {
        void run() throws IOException;
    }

    /** Runs work holding the prefix's in-JVM stripe and its cross-process lock file. */
    private static void withLock(Path dir, String base, LockedWork work) throws IOException {
        Path lockFile = dir.resolve("." + base + STAGING_INFIX + "lock");
        synchronized (STRIPES[Math.floorMod(lockFile.hashCode(), STRIPES.length)]) {
            byte[] token = String.format("%d-%016x", ProcessHandle.current().pid(), RANDOM.nextLong())
                    .getBytes(StandardCharsets.US_ASCII);
            while (true) {
                FileChannel channel;
                channel = FileChannel.open(lockFile, StandardOpenOption.CREATE, StandardOpenOption.WRITE,
                        StandardOpenOption.READ);
                try (channel; FileLock ignored = channel.lock()) {
                    // The file may have been deleted by the previous holder after we opened it: the lock
                    // is ours only if the name still leads to the file we locked (our token is in it).
                    try {
                        channel.truncate(0);
                        channel.write(ByteBuffer.wrap(token), 0);
                    } catch (IOException e) {
                        // No room for the token (a full disk): the empty file would stay behind, one per id. Nobody
                        // else can write a token either, so an empty file at the name is this one.
                        try {
                            if (Files.size(lockFile) == 0) {
                                Files.deleteIfExists(lockFile);
                            }
                        } catch (IOException gone) {
                            e.addSuppressed(gone);
                        }
                        throw e;
                    }
                    byte[] seen;
                    try {
                        seen = Files.readAllBytes(lockFile);
                    } catch (NoSuchFileException e) {
                        continue;
                    }
                    if (!java.util.Arrays.equals(seen, token)) {
                        continue;
                    }
                    try {
                        work.run();
                    } finally {
                        Files.deleteIfExists(lockFile); // before the lock is released (see above)
                    }
                    return;
                }
            }
        }
    }

    /** Finishes or removes staging folders of this prefix left by processes (or sets) that no longer run. */
    private static void recover(Path dir, String base) throws IOException {
        String start = "." + base + STAGING_INFIX;
        List<Path> stale = new ArrayList<>();
        try (DirectoryStream<Path> entries = Files.newDirectoryStream(dir, e -> e.getFileName().toString().startsWith(start))) {
            for (Path e : entries) {
                Matcher m = STAGING_SUFFIX.matcher(e.getFileName().toString().substring(start.length()));
                if (m.matches() && Files.isDirectory(e, LinkOption.NOFOLLOW_LINKS)
                        && !ownerRuns(Long.parseLong(m.group(1)), Long.parseLong(m.group(2)), e)) {
                    stale.add(e);
                }
            }
        }
        for (Path s : stale) {
            if (Files.exists(s.resolve(COMMIT_MARK))) {
                rollForward(dir, base, s);
            } else {
                deleteTree(s);
            }
        }
    }

    private static boolean ownerRuns(long pid, long startMillis, Path staging) {
        if (pid == ProcessHandle.current().pid()) {
            return ACTIVE.contains(staging);
        }
        return ProcessHandle.of(pid).map(h -> h.info().startInstant()
                .map(i -> startMillis == 0 || Math.abs(i.toEpochMilli() - startMillis) < 2000).orElse(true))
                .orElse(false);
    }

    /**
     * Puts a marked staging folder's files in place; idempotent, so a crash in the middle is finished
     * by running it again. The JSON goes last: deleted first, renamed last.
     */
    private static void rollForward(Path dir, String base, Path staging) throws IOException {
        String json = base + ".json";
        Path stagedJson = staging.resolve(json);
        if (Files.exists(stagedJson)) {
            Files.deleteIfExists(dir.resolve(json));
            checkpoint.accept("removed " + json);
            for (String old : Files.readAllLines(staging.resolve(COMMIT_MARK), StandardCharsets.UTF_8)) {
                if (!old.isEmpty()) {
                    Files.deleteIfExists(dir.resolve(old));
                }
            }
        }
        List<Path> files = new ArrayList<>();
        try (DirectoryStream<Path> entries = Files.newDirectoryStream(staging)) {
            entries.forEach(files::add);
        }
        files.sort(null);
        for (Path f : files) {
            String name = f.getFileName().toString();
            if (!name.equals(json) && !name.startsWith(COMMIT_MARK)) {
                move(f, dir.resolve(name));
                checkpoint.accept("moved " + name);
            }
        }
        if (Files.exists(stagedJson)) {
            move(stagedJson, dir.resolve(json));
            checkpoint.accept("moved " + json);
        }
        deleteTree(staging);
    }

    private static void move(Path from, Path to) throws IOException {
        try {
            Files.move(from, to, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } catch (AtomicMoveNotSupportedException e) {
            Files.move(from, to, StandardCopyOption.REPLACE_EXISTING);
        } catch (FileSystemException e) {
            throw new IOException("cannot write " + to + ": " + IoMessages.reason(e), e);
        }
    }

    /**
     * Names listed in the previous {@code P.json}'s {@code files} that the new set does not have:
     * only plain names of this prefix in this folder (a hand-edited JSON cannot delete anything else).
     */
    static List<String> previousFilesNotIn(Path dir, String base, Set<String> newNames) {
        List<String> out = new ArrayList<>();
        Path json = dir.resolve(base + ".json");
        if (!Files.isRegularFile(json)) {
            return out;
        }
        try {
            JsonElement files = JsonParser.parseString(Files.readString(json, StandardCharsets.UTF_8))
                    .getAsJsonObject().get("files");
            if (files instanceof JsonArray a) {
                for (JsonElement e : a) {
                    String n = e.isJsonPrimitive() ? e.getAsString() : "";
                    boolean ours = n.startsWith(base + ".") || n.startsWith(base + "-");
                    if (ours && !n.contains("/") && !n.contains(File.separator) && !n.equals(base + ".json")
                            && !newNames.contains(n) && Files.isRegularFile(dir.resolve(n), LinkOption.NOFOLLOW_LINKS)) {
                        out.add(n);
                    }
                }
            }
        } catch (IOException | RuntimeException e) {
            // Not our JSON, or unreadable: nothing of it is removed.
        }
        return out;
    }

    private static void deleteTree(Path dir) {
        try (DirectoryStream<Path> entries = Files.newDirectoryStream(dir)) {
            for (Path e : entries) {
                Files.deleteIfExists(e);
            }
        } catch (IOException e) {
            // best effort: the next open of this prefix tries again
        }
        try {
            Files.deleteIfExists(dir);
        } catch (IOException e) {
            // as above
        }
    }
}
