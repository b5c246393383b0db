package dempano.cli;

/**
 * Whether stderr, where the batch's progress goes, is a terminal, and how wide: asked of file descriptor 2 itself
 * (JLine's native isatty and TIOCGWINSZ). {@link System#console()} tells of stdin and stdout instead: with
 * {@code 2>log} from a shell the bar's returns and escapes filled the log, with {@code >/dev/null} no bar was shown on
 * the terminal. Where the native library cannot be loaded (an unusual platform, a temporary folder that cannot hold
 * it), stderr counts as no terminal: plain lines.
 */
final class StderrTerminal {
    /** Columns assumed where the terminal does not say. */
    static final int DEFAULT_COLUMNS = 80;
    private static final int STDERR = 2;

    private StderrTerminal() {
    }

    /** Whether stderr is a terminal that can show a bar: a tty, and {@code TERM} not {@code dumb}. */
    static boolean isInteractive() {
        return !"dumb".equals(System.getenv("TERM")) && isTerminal();
    }

    private static boolean isTerminal() {
        try {
            return org.jline.nativ.CLibrary.isatty(STDERR) == 1;
        } catch (Throwable e) { // UnsatisfiedLinkError, or the loader's own errors
            return false;
        }
    }

    /** The terminal's width in columns now (it may have been resized), {@link #DEFAULT_COLUMNS} where it does not say. */
    static int columns() {
        try {
            int columns = org.jline.nativ.CLibrary.getTerminalWidth(STDERR);
            return columns > 0 ? columns : DEFAULT_COLUMNS;
        } catch (Throwable e) {
            return DEFAULT_COLUMNS;
        }
    }
}
