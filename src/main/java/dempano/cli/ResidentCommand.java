package dempano.cli;

import java.io.IOException;
import java.nio.channels.SocketChannel;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;

/** {@code dempano resident status|stop}: the resident process of this installation and setting. */
@Command(name = ResidentCommand.NAME, mixinStandardHelpOptions = true,
        description = {"The resident render process (DEMPANO_RESIDENT=on): with it, a panorama from the shell is "
                + "rendered by a process that keeps the OpenGL context, tiles and meshes warm from run to run, "
                + "started by the first such run and ended after DEMPANO_RESIDENT_IDLE_S seconds idle (default 600).",
                "status: whether one runs for this installation and setting, its memory and runs; stop: end it."},
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
        Path socket = ResidentClient.socket(env);
        SocketChannel ch = ResidentClient.connect(socket);
        if (ch == null) {
            System.out.println("no resident process for this installation and setting (socket " + socket + ")");
            return 1;
        }
        try (ch) {
            return ResidentClient.exchange(ch, new ResidentProtocol.Request(kind, ResidentClient.stamp(env),
                    Path.of("").toAbsolutePath().toString(), List.of()), System.out, System.err);
        } catch (ResidentClient.Refused e) {
            System.out.println(e.getMessage());
            return 1;
        }
    }
}
