package dempano.cli;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.OutputStream;
import java.util.ArrayList;
import java.util.List;

/**
 * What the start script's JVM and the resident process ({@link ResidentServer}) say to each other over the
 * resident process's Unix socket. One request a connection, then frames until the exit frame:
 *
 * <pre>
 * request:  int MAGIC, UTF kind (render | status | stop), UTF stamp, UTF working directory, int n, n × UTF argument
 * response: frames of byte type and its body:
 *           OUT, ERR: int length, that many bytes of the run's standard output or error (UTF-8)
 *           EXIT:     int exit code (the last frame)
 *           REFUSED:  UTF reason (busy, another installation): the client renders in its own process
 * </pre>
 *
 * Closing the connection before the exit frame (the client stopped: Ctrl-C) ends the resident process, so a
 * render stops where a killed process would: its output set is left incomplete and the next run on the prefix
 * removes it ({@link dempano.io.OutputSet}).
 */
final class ResidentProtocol {
    /** "DPN" and the protocol's version, 1. */
    static final int MAGIC = 0x44504E01;
    static final byte OUT = 1, ERR = 2, EXIT = 3, REFUSED = 4;
    static final String RENDER = "render", STATUS = "status", STOP = "stop";

    private ResidentProtocol() {
    }

    /**
     * A stream reading the channel directly. (Channels.newInputStream and newOutputStream hold the channel's
     * blocking lock while they wait, so that a read waiting for the client's hang-up would stop every write.)
     */
    static java.io.InputStream in(java.nio.channels.SocketChannel ch) {
        return new java.io.InputStream() {
            @Override
            public int read() throws IOException {
                byte[] b = new byte[1];
                return read(b, 0, 1) < 0 ? -1 : b[0] & 0xFF;
            }

            @Override
            public int read(byte[] b, int off, int len) throws IOException {
                if (len == 0) {
                    return 0;
                }
                return ch.read(java.nio.ByteBuffer.wrap(b, off, len));
            }
        };
    }

    /** A stream that writes whole arrays only: one byte is an array of one. */
    private abstract static class ArrayStream extends OutputStream {
        @Override
        public void write(int b) throws IOException {
            write(new byte[] {(byte) b}, 0, 1);
        }

        @Override
        public abstract void write(byte[] b, int off, int len) throws IOException;
    }

    /** A stream writing to the channel directly (see {@link #in}). */
    static OutputStream out(java.nio.channels.SocketChannel ch) {
        return new ArrayStream() {
            @Override
            public void write(byte[] b, int off, int len) throws IOException {
                java.nio.ByteBuffer buf = java.nio.ByteBuffer.wrap(b, off, len);
                while (buf.hasRemaining()) {
                    ch.write(buf);
                }
            }
        };
    }

    /** A request as sent. */
    record Request(String kind, String stamp, String workingDir, List<String> args) {
        void write(DataOutputStream out) throws IOException {
            out.writeInt(MAGIC);
            out.writeUTF(kind);
            out.writeUTF(stamp);
            out.writeUTF(workingDir);
            out.writeInt(args.size());
            for (String a : args) {
                out.writeUTF(a);
            }
            out.flush();
        }

        /**
         * Reads a request.
         *
         * @throws IOException for anything but a request of this protocol version (a foreign or older client)
         */
        static Request read(DataInputStream in) throws IOException {
            int magic = in.readInt();
            if (magic != MAGIC) {
                throw new IOException(String.format("not a dempano request of this version (%08x)", magic));
            }
            String kind = in.readUTF(), stamp = in.readUTF(), dir = in.readUTF();
            int n = in.readInt();
            if (n < 0 || n > 10_000) {
                throw new IOException("bad argument count " + n);
            }
            List<String> args = new ArrayList<>(n);
            for (int i = 0; i < n; i++) {
                args.add(in.readUTF());
            }
            return new Request(kind, stamp, dir, List.copyOf(args));
        }
    }

    /** A frame as received: its type and body (bytes of OUT and ERR, the code of EXIT, the reason of REFUSED). */
    record Frame(byte type, byte[] bytes, int code, String reason) {
        /**
         * Reads the next frame.
         *
         * @throws EOFException where the connection ends before it
         */
        static Frame read(DataInputStream in) throws IOException {
            byte type = in.readByte();
            switch (type) {
                case OUT, ERR -> {
                    int n = in.readInt();
                    if (n < 0 || n > (1 << 24)) {
                        throw new IOException("bad frame length " + n);
                    }
                    byte[] b = new byte[n];
                    in.readFully(b);
                    return new Frame(type, b, 0, null);
                }
                case EXIT -> {
                    return new Frame(type, null, in.readInt(), null);
                }
                case REFUSED -> {
                    return new Frame(type, null, 0, in.readUTF());
                }
                default -> throw new IOException("bad frame type " + type);
            }
        }
    }

    /** Writes frames; every method is atomic against the others (the run's threads print concurrently). */
    static final class Writer {
        private final DataOutputStream out;

        Writer(OutputStream out) {
            this.out = new DataOutputStream(new java.io.BufferedOutputStream(out, 1 << 16));
        }

        synchronized void bytes(byte type, byte[] b, int off, int len) throws IOException {
            out.writeByte(type);
            out.writeInt(len);
            out.write(b, off, len);
            out.flush();
        }

        synchronized void exit(int code) throws IOException {
            out.writeByte(EXIT);
            out.writeInt(code);
            out.flush();
        }

        synchronized void refused(String reason) throws IOException {
            out.writeByte(REFUSED);
            out.writeUTF(reason);
            out.flush();
        }

        /** A stream whose every write is one frame of {@code type}. */
        OutputStream stream(byte type) {
            return new ArrayStream() {
                @Override
                public void write(byte[] b, int off, int len) throws IOException {
                    if (len > 0) {
                        bytes(type, b, off, len);
                    }
                }
            };
        }
    }
}
