package dempano.cli;

import java.io.IOException;
import java.nio.channels.SocketChannel;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;

/** {@code dempano resident status|stop}: this user's resident processes (every one in the folder). */
@Command(name = ResidentCommand.NAME, mixinStandardHelpOptions = true,
        description = {"The resident render process (DEMPANO_RESIDENT=on): with it, a panorama from the shell is "
                + "rendered by a process that keeps the OpenGL context, tiles and meshes warm from run to run, "
                + "started by the first such run and ended after DEMPANO_RESIDENT_IDLE_S seconds idle (default 600).",
                "status: the resident processes of this user (one per installation and setting: panoramas and photos run"
                        + " in separate ones), their memory and runs; stop: end them."},
        footer = {"", "Exit codes: 0 done, 1 none running, 2 bad arguments."})
final class ResidentCommand implements Callable<Integer> {
    static final String NAME = "resident";

    @Parameters(paramLabel = "ACTION", description = "status or stop")
    String action;

    @Override
    public Integer call() throws IOException {
        String kind = switch (action) {
            case "status" -> ResidentProtocol.STATUS;
            case "stop" -> ResidentProtocol.STOP;
            default -> throw new IllegalArgumentException("resident: the action is status or stop, got '" + action + "'");
        };
        java.util.Map<String, String> env = System.getenv();
        Path dir;
        try {
            dir = ResidentClient.directory(env);
        } catch (IOException e) { // it said the bare path ("dempano: /tmp/afile")
            throw new IOException("the resident processes' folder cannot be used: " + dempano.io.IoMessages.describe(e), e);
        }
        List<Path> sockets;
        try (var files = java.nio.file.Files.list(dir)) {
            sockets = files.filter(f -> f.getFileName().toString().endsWith(".sock")).sorted().toList();
        }
        int answered = 0, silent = 0;
        String stamp = ResidentClient.stamp(env);
        for (Path socket : sockets) {
            SocketChannel ch;
            try {
                ch = ResidentClient.connect(socket); // a socket nobody listens on is removed
            } catch (IOException e) {
                System.out.println(socket + ": not a resident process's socket (" + dempano.io.IoMessages.reason(e) + ")");
                continue;
            }
            if (ch == null) {
                continue;
            }
            try (ch) {
                ResidentClient.exchange(ch, new ResidentProtocol.Request(kind, stamp,
                        Path.of("").toAbsolutePath().toString(), List.of()), System.out, System.err);
                answered++;
            } catch (IOException e) {
                System.out.println(socket + ": " + e.getMessage());
                silent++;
            }
        }
        if (answered == 0) {
            // A process that did not answer (stopped, hung) is still there: not "no resident process".
            System.out.println(silent > 0 ? "no resident process answered (" + silent + " did not: above; folder " + dir + ")"
                    : "no resident process (folder " + dir + ")");
            return 1;
        }
        return 0;
    }
}
