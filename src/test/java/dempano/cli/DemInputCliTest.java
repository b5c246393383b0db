package dempano.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.SharedData;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The CLI on bad DEM folders and places without data (issue 15, "Tiles and places"): exit 1 with a
 * message naming the entry and the problem, no stack trace, no output file; or a render with a
 * warning. Successes use the CPU reference renderer at 2 pixels per degree.
 */
class DemInputCliTest {
    @TempDir
    Path tmp;

    /** An SRTM3 tile of smooth hills (400–1000 m), named e.g. N43E006.hgt (name may carry a suffix). */
    static Path tile(Path dir, String name) throws IOException {
        int lat = Integer.parseInt(name.substring(1, 3)), lon = Integer.parseInt(name.substring(4, 7));
        ByteBuffer b = ByteBuffer.allocate(2 * 1201 * 1201);
        for (int r = 0; r < 1201; r++) {
            for (int c = 0; c < 1201; c++) {
                double la = lat + 1 - r / 1200.0, lo = lon + c / 1200.0;
                b.putShort((short) Math.round(700 + 150 * Math.sin(la * 20) + 150 * Math.cos(lo * 15)));
            }
        }
        return Files.write(dir.resolve(name), b.array());
    }

    interface Setup {
        void in(Path dem) throws IOException;
    }

    static Arguments c(String name, Setup setup, String args, int exit, String... expected) {
        return Arguments.of(name, setup, args, exit, List.of(expected));
    }

    static Stream<Arguments> cases() {
        List<Arguments> t = new ArrayList<>();
        t.add(c("mid-Atlantic", d -> { }, "--lat 30 --lon -40 --dem-dir {shared}", 1,
                "no DEM data around 30.0, -40.0", "is in {shared}", "--missing-tiles sea"));
        t.add(c("empty folder", d -> { }, "--lat 43.5 --lon 7.5", 1, "none of the tiles needed within range [N43E007] is in {dem}"));
        t.add(c("explicit sea on an empty folder", d -> { }, "--lat 43.5 --lon 7.5 --missing-tiles sea", 0,
                "warning: no data for [N43E007] in {dem}: treated as sea level"));
        t.add(c("--lat 60.5 beside a folder of tiles", d -> tile(d, "N43E007.hgt"), "--lat 60.5 --lon 7.5", 1,
                "no DEM data around 60.5, 7.5", "is in {dem}"));
        t.add(c("viewpoint's tile missing", d -> tile(d, "N43E006.hgt"), "--lat 43.5 --lon 7.05", 1,
                "tile N43E007 under the viewpoint", "is not in {dem}", "--altitude-m", "--missing-tiles sea"));
        t.add(c("viewpoint's tile missing, --altitude-m 100", d -> tile(d, "N43E006.hgt"), "--lat 43.5 --lon 7.05 --altitude-m 100",
                0, "warning: no data for [N43E007] in {dem}"));
        t.add(c("a neighbour missing (coast)", d -> tile(d, "N43E007.hgt"), "--lat 43.5 --lon 7.05", 0,
                "warning: no data for [N43E006] in {dem}"));
        t.add(c("--missing-tiles error, two missing", d -> {
            tile(d, "N43E006.hgt");
            tile(d, "N44E006.hgt");
        }, "--lat 43.95 --lon 7.05 --range-km 10 --missing-tiles error", 1, "2 tiles [N44E007, N43E007] are needed", "{dem}"));
        t.add(c("directory named like the tile", d -> {
            tile(d, "N43E006.hgt");
            Files.createDirectory(d.resolve("N43E007.hgt"));
        }, "--lat 43.5 --lon 7.05", 1, "{dem}/N43E007.hgt is a directory"));
        t.add(c("dangling link", d -> Files.createSymbolicLink(d.resolve("N43E007.hgt"), d.resolve("missing/N43E007.hgt")),
                "--lat 43.5 --lon 7.5", 1, "{dem}/N43E007.hgt is a dangling symbolic link"));
        t.add(c("junk N99E999.hgt beside a good tile", d -> {
            tile(d, "N43E007.hgt");
            Files.write(d.resolve("N99E999.hgt"), new byte[] {1, 2, 3});
            Files.write(d.resolve("SHA256SUMS"), new byte[] {1, 2, 3});
        }, "--lat 43.5 --lon 7.5", 0, "warning: ignored 1 file in {dem} named like tiles but with no valid tile name [N99E999.hgt]"));
        t.add(c("duplicates", d -> {
            tile(d, "N43E007.hgt");
            tile(d, "N43E007-broken.hgt");
            tile(d, "n43e007.hgt");
        }, "--lat 43.5 --lon 7.5", 1, "tile N43E007 is ambiguous: {dem} holds 3 files for it (N43E007-broken.hgt, N43E007.hgt, n43e007.hgt); keep one"));
        t.add(c("zip holding another tile", d -> {
            Path p = tile(d, "N48E010.hgt");
            zip(d.resolve("N43E007.hgt.zip"), "N48E010.hgt", Files.readAllBytes(p));
            Files.delete(p);
        }, "--lat 43.5 --lon 7.5", 1, "{dem}/N43E007.hgt.zip: its name says tile N43E007 but the zip holds N48E010.hgt"));
        t.add(c("random bytes named .hgt.zip", d -> Files.write(d.resolve("N43E007.hgt.zip"), randomBytes(4096)),
                "--lat 43.5 --lon 7.5", 1, "{dem}/N43E007.hgt.zip is not a zip archive"));
        return t.stream();
    }

    static void zip(Path file, String entry, byte[] content) throws IOException {
        try (OutputStream out = Files.newOutputStream(file); ZipOutputStream z = new ZipOutputStream(out)) {
            z.putNextEntry(new ZipEntry(entry));
            z.write(content);
            z.closeEntry();
        }
    }

    static byte[] randomBytes(int n) {
        byte[] b = new byte[n];
        new java.util.Random(5).nextBytes(b);
        return b;
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void demInputProblems(String name, Setup setup, String args, int exit, List<String> expected) throws IOException {
        Path dem = Files.createDirectory(tmp.resolve("dem")), out = Files.createDirectory(tmp.resolve("out"));
        setup.in(dem);
        String shared = args.contains("{shared}") ? SharedData.demDir().toString() : "";
        List<String> argv = new ArrayList<>(List.of(args.replace("{shared}", shared).split(" ")));
        if (!args.contains("--dem-dir")) {
            argv.addAll(List.of("--dem-dir", dem.toString()));
        }
        if (!args.contains("--range-km")) {
            argv.addAll(List.of("--range-km", "20"));
        }
        argv.addAll(List.of("--ppd", "2", "--renderer", "reference", "--out", out.resolve("p").toString()));
        String[] r = MainTest.run(argv.toArray(String[]::new));
        assertEquals(Integer.toString(exit), r[0], r[1]);
        for (String e : expected) {
            String s = e.replace("{dem}", dem.toString()).replace("{shared}", shared);
            assertTrue(r[1].contains(s), "'" + s + "' not in: " + r[1]);
        }
        assertFalse(r[1].contains("\tat "), "no stack trace: " + r[1]);
        try (Stream<Path> written = Files.list(out)) {
            List<String> files = written.map(p -> p.getFileName().toString()).sorted().toList();
            if (exit == 0) {
                assertTrue(files.contains("p.png") && files.contains("p.json"), "written: " + files);
            } else {
                assertEquals(List.of(), files, "a failure writes nothing");
                assertTrue(r[1].contains("dempano: "), r[1]);
            }
        }
    }
}
