package dempano.cli;

import dempano.terrain.DeviationStore;
import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.dem.DemException;
import dempano.dem.DemoTerrain;
import dempano.io.OutputSet;
import dempano.io.PanoramaWriter;
import dempano.panorama.Layer;
import dempano.panorama.Panorama;
import dempano.render.GlUnavailableException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code dempano}: renders a 360° panorama and its distance map for a viewpoint. */
@Command(name = "dempano", mixinStandardHelpOptions = true, version = "dempano 0.1.0", sortOptions = false,
        description = {"Renders the 360° landscape panorama seen from a point, and a distance map, from SRTM .hgt tiles.",
                "With no --lat/--lon/--dem-dir it renders the built-in demo scene (generated into testdata/demo-dem)."},
        footer = {"", "Writes P.png, P-distance.npy (or .pfm), P-distance.png, P-<layer>.npy and P.json for --out P.",
                "Exit codes: 0 done, 1 input or rendering failure (tiles, DEM data, output folder, summit list, memory, OpenGL), 2 bad arguments."})
public final class Main implements Callable<Integer> {
    @Option(names = "--lat", description = "Viewpoint latitude, degrees north (-90..90). Default: the demo scene's.")
    Double latDeg;
    @Option(names = "--lon", description = "Viewpoint longitude, degrees east (-180..180). Default: the demo scene's.")
    Double lonDeg;
    @Option(names = "--dem-dir", paramLabel = "DIR", description = "Directory of DEM tiles: SRTM (N46E008.hgt, *.hgt.zip) "
            + "and GeoTIFFs in lat/lon (N46E008.tif, Copernicus_DSM_COG_10_N46_00_E008_00_DEM.tif). Repeatable, in priority "
            + "order: where the first has a void or no tile, the next fills it. Default: the demo DEM.")
    List<Path> demDirs;
    @Option(names = "--out", paramLabel = "PREFIX", description = "Output prefix (default: ${DEFAULT-VALUE}).", defaultValue = "build/panorama/panorama")
    String out;
    /** The options every panorama command shares (dempano batch and the Spark job too). */
    @CommandLine.Mixin
    PanoramaOptions panorama = new PanoramaOptions();
    @Option(names = "--altitude-m", description = "Absolute standing altitude, metres above sea level, instead of the DEM height (+ offset).")
    Double altitudeMetres;
    @Option(names = "--summits", paramLabel = "FILE", description = "Summit list (.txt as de Ferranti's alps.txt, .csv name,lat,lon,elevation, .geojson OSM peaks): writes P-summits.json, P-summits.csv and P-labels.png.")
    Path summitsFile;

    @Option(names = "--max-labels", paramLabel = "N", defaultValue = "0",
            description = "At most N summit labels in P-labels.png (default: ${DEFAULT-VALUE} = no limit).")
    int maxLabels;

    @Option(names = "--label-spacing-px", paramLabel = "PX",
            description = "Least horizontal distance between labelled summits, pixels (default: one text line, about 18 px).")
    Double labelSpacingPx;

    @Option(names = "--label-order", paramLabel = "ORDER", defaultValue = "height",
            description = "Which summits win where labels compete: height (highest first), angle (highest in the picture first) or distance (nearest first) (default: ${DEFAULT-VALUE}).")
    String labelOrder;

    @Option(names = "--lenient-summits", description = "Skip bad lines of the summit list (reported) instead of failing.")
    boolean lenientSummits;


    @Option(names = "--repeat", description = "Render this many times in one process and print a timing table (cold = run 1, warm = the rest); files are written once (default: ${DEFAULT-VALUE}).", defaultValue = "1")
    int repeat;


    @Option(names = "--snap-to-summit-m", paramLabel = "R", description = "Move the viewpoint to the highest DEM point within R metres (a surveyed summit beside the DEM's own); the move is reported.")
    Double snapToSummitMetres;
    @Option(names = "--clear-view-m", paramLabel = "R", description = "Raise the eye until no terrain within R metres rises above its horizontal (+0.5 m); the lift is reported.")
    Double clearViewMetres;

    public static void main(String[] args) {
        if (!List.of(args).contains("fly")) {
            // Images are drawn without a display: with DISPLAY set to an X server that cannot be reached (a stale
            // DISPLAY in tmux or ssh), AWT failed after the render and every output was lost. The fly-through keeps AWT
            // for its settings dialog.
            System.setProperty("java.awt.headless", "true");
        }
        // DEMPANO_RESIDENT=on: a panorama is rendered by this user's resident process for this installation (started
        // if none runs), which keeps the GL context, tiles and meshes warm; anything else, or no resident process to
        // be had, runs here. Decided before picocli is loaded: the client stays a small, quick JVM.
        if (ResidentClient.wanted(System.getenv()) && ResidentClient.serves(args)) {
            int code = ResidentClient.run(args);
            if (code != ResidentClient.NOT_SERVED) {
                System.exit(code);
            }
        }
        System.exit(run(args));
    }

    /** Runs the CLI and returns the exit code (for tests). */
    public static int run(String... args) {
        return run(RunContext.HERE, args);
    }

    /**
     * Runs the CLI with relative paths taken from the context's working directory and the renderer from its
     * renderers; returns the exit code. The resident process's way in.
     */
    static int run(RunContext context, String... args) {
        try {
            return commandLine(context, args).execute(args);
        } catch (OutOfMemoryError e) {
            // The estimate made before rendering (InsufficientMemoryException) missed: say what to do, no stack trace.
            context.renderers().failed(e);
            System.err.println("dempano: " + outOfMemoryMessage(e));
            return 1;
        }
    }

    /** Where this run's relative paths lead and its renderer comes from. */
    private RunContext context = RunContext.HERE;

    /**
     * Where a panorama's renderer comes from: opened for the run and closed after it (the CLI), or kept open
     * from run to run (the resident process, {@link ResidentServer}).
     */
    interface Renderers {
        /** A renderer for {@code dem}; closing the lease ends what the run alone needed. */
        Lease lease(dempano.dem.DemSource dem, boolean reference, int repeat);

        /** Told of a run's failure (before it is reported), e.g. to give up a renderer that cannot draw. */
        default void failed(Throwable t) {
        }

        /** A renderer for the length of one run, and what closing the lease does (close it, or nothing: kept). */
        record Lease(PanoramaRenderer renderer, Runnable onClose) implements AutoCloseable {
            @Override
            public void close() {
                onClose.run();
            }
        }

        /** Opened for each run, closed after it. */
        Renderers PER_RUN = (dem, reference, repeat) -> {
            PanoramaRenderer r = reference ? PanoramaRenderer.openReference(dem) : openGl(dem, repeat);
            return new Lease(r, r::close);
        };
    }

    /** The subcommands' names (picocli builds each one's model, by reflection, when it is added). */
    static final List<String> SUBCOMMANDS = List.of("fly", "photo", "batch", ResidentCommand.NAME);

    /**
     * Whether the arguments may name a subcommand or ask for help (which lists them): any argument equal to a
     * subcommand's name or {@code help}, a help option, or no argument at all. Otherwise the subcommands' models
     * are not built: a panorama from the shell starts sooner (docs/cold-start.md), and parses as before.
     */
    static boolean needsSubcommands(String... args) {
        if (args.length == 0) {
            return true;
        }
        for (String a : args) {
            if (SUBCOMMANDS.contains(a) || a.equals("help") || a.equals("--help")
                    || (a.startsWith("-") && !a.startsWith("--") && a.indexOf('h') > 0)) {
                return true;
            }
        }
        return false;
    }

    /**
     * The OpenGL renderer of a panorama from the shell: patch deviations kept on disk; for one panorama (no
     * {@code --repeat}) no meshes kept either, so that they are freed before the stitch (nothing would draw them again).
     */
    private static PanoramaRenderer openGl(dempano.dem.DemSource dem, int repeat) {
        PanoramaRenderer r = PanoramaRenderer.openInBackground(dem).withDeviationStore(DeviationStore.userDefault());
        return repeat == 1 ? r.withoutMeshCache() : r;
    }

    /** A number option's value: a plain decimal (no hexadecimal such as 0x1p5, no type suffix such as 46d). */
    static Double decimal(String text) {
        String t = text.trim();
        if (!dempano.util.Decimals.isPlain(t) && !t.matches("[+-]?Infinity|NaN")) {
            throw new CommandLine.TypeConversionException("'" + text + "' is not a decimal number");
        }
        return Double.valueOf(t);
    }

    private static CommandLine commandLine(RunContext context, String... args) {
        Main main = new Main();
        main.context = context;
        CommandLine cl = new CommandLine(main);
        if (needsSubcommands(args)) {
            cl.addSubcommand("fly", new FlyCommand());
            PhotoCommand photo = new PhotoCommand();
            photo.context = main.context;
            cl.addSubcommand("photo", photo);
            cl.addSubcommand("batch", new BatchCommand());
            cl.addSubcommand(ResidentCommand.NAME, new ResidentCommand());
        }
        // Numbers as the batch CSV reads them: plain decimals (NaN and Infinity pass, for the options' own messages).
        // One converter object for both: two method references of one signature here crashed the JDK's class-data
        // dump (two identical lambda-proxy entries in the class list; SIGSEGV in adjust_lambda_proxy_class_dictionary).
        CommandLine.ITypeConverter<Double> decimal = Main::decimal;
        cl.registerConverter(Double.class, decimal).registerConverter(double.class, decimal);
        // "--out fly" is a file named fly, not the fly command (a subcommand's name is taken as an option's value).
        cl.setAllowSubcommandsAsOptionParameters(true);
        cl.setParameterExceptionHandler((ex, a) -> {
            PrintWriter err = ex.getCommandLine().getErr();
            err.println("dempano: " + ex.getMessage());
            err.println("Try '" + ex.getCommandLine().getCommandSpec().qualifiedName() + " --help' for the options.");
            return 2;
        });
        cl.setExecutionExceptionHandler((ex, c, parsed) -> {
            context.renderers().failed(ex);
            PrintWriter err = c.getErr();
            if (ex instanceof IllegalArgumentException) {
                err.println("dempano: " + ex.getMessage());
                return 2;
            }
            if (ex instanceof DemException || ex instanceof GlUnavailableException || ex instanceof java.io.IOException
                    || ex instanceof dempano.summits.SummitFormatException || ex instanceof dempano.InsufficientMemoryException
                    || ex instanceof dempano.render.RenderFailedException) {
                err.println("dempano: " + ex.getMessage());
                return 1;
            }
            err.println("dempano: unexpected failure: " + ex);
            ex.printStackTrace(err);
            return 1;
        });
        return cl;
    }

    /**
     * An optional number flag: NaN where not given; a NaN given is refused (NaN means "not given" inside, so
     * {@code --altitude-m NaN} would silently be no altitude).
     */
    static double given(String flag, Double v) {
        if (v == null) {
            return Double.NaN;
        }
        if (Double.isNaN(v)) {
            throw new IllegalArgumentException(flag + " must be a number, got NaN");
        }
        return v;
    }

    /** The way out of an out-of-memory failure, with the heap size in use. */
    static String outOfMemoryMessage(OutOfMemoryError e) {
        return String.format(Locale.ROOT, "out of memory (%s; Java heap limit %.0f MB): lower --ppd, --elevation-range "
                + "or --range-km, or give Java more memory, e.g. DEMPANO_OPTS=-Xmx%dg", e.getMessage(),
                Runtime.getRuntime().maxMemory() / 1e6, Math.max(2, 2 * (int) Math.ceil(Runtime.getRuntime().maxMemory() / 1e9)));
    }

    @Override
    public Integer call() throws Exception {
        boolean noDem = demDirs == null || demDirs.isEmpty();
        boolean demo = latDeg == null && lonDeg == null && noDem;
        if (!demo && (latDeg == null || lonDeg == null)) {
            throw new IllegalArgumentException("give both --lat and --lon (or neither, for the demo scene)");
        }
        if (!demo && noDem) {
            throw new IllegalArgumentException("--dem-dir is needed with --lat/--lon");
        }
        List<Path> dirs = demo ? List.of(DemoTerrain.ensure(context.resolve(DemoTerrain.DEFAULT_DIR)))
                : demDirs.stream().map(context::resolve).toList();
        Path summitsFile = context.resolve(this.summitsFile);
        double lat = demo ? DemoTerrain.viewpoint()[0] : latDeg, lon = demo ? DemoTerrain.viewpoint()[1] : lonDeg;
        Set<Layer> wanted = panorama.layers();
        PanoramaRequest req = panorama.applyTo(PanoramaRequest.at(lat, lon), demo ? 60_000 : PanoramaRequest.DEFAULT_RANGE_METRES)
                .withAltitudeMetres(given("--altitude-m", altitudeMetres))
                .withSnapToSummitMetres(given("--snap-to-summit-m", snapToSummitMetres))
                .withClearViewMetres(given("--clear-view-m", clearViewMetres));
        if (altitudeMetres != null && panorama.offsetMetres != 0) { // the offset was ignored without a word
            throw new IllegalArgumentException("--altitude-m and --offset-m both set the standing height (an absolute altitude, or the DEM's height plus an offset): give one");
        }
        dempano.io.OutputSet.checkPrefix(out); // an empty or folder prefix is a bad argument (exit 2)
        String out = context.resolve(this.out);
        Path outParent = Path.of(out).toAbsolutePath().getParent();
        if (outParent != null && this.out.startsWith("build/")) {
            Files.createDirectories(outParent); // the default location; user prefixes must point into an existing directory
        }
        dempano.dem.DemSource dem = dempano.dem.PriorityDem.open(dirs, panorama.demFill(),
                w -> System.err.println("  warning: " + w));
        dempano.io.SummitWriter.LabelOptions labelOptions = new dempano.io.SummitWriter.LabelOptions(maxLabels,
                given("--label-spacing-px", labelSpacingPx), switch (labelOrder.toLowerCase(Locale.ROOT)) {
                    case "height" -> dempano.io.SummitWriter.LabelOrder.HEIGHT;
                    case "angle" -> dempano.io.SummitWriter.LabelOrder.ANGLE;
                    case "distance" -> dempano.io.SummitWriter.LabelOrder.DISTANCE;
                    default -> throw new IllegalArgumentException("--label-order must be height, angle or distance, got "
                            + labelOrder);
                });
        dempano.summits.SummitList summitList = null;
        if (summitsFile != null && panorama.noDistance) {
            throw new IllegalArgumentException("--summits needs the distance map (visibility is decided from it): drop --no-distance");
        }
        if (summitsFile != null) {
            // Read before rendering: a bad list fails fast.
            try {
                summitList = dempano.summits.SummitReader.read(summitsFile, lenientSummits);
            } catch (java.io.IOException e) {
                throw new java.io.IOException("cannot read the summit list " + summitsFile + ": "
                        + dempano.io.IoMessages.reason(e), e);
            }
            for (String skipped : summitList.skipped()) {
                System.err.println("  summit list " + summitsFile + ": skipped " + skipped);
            }
            // Its warnings are printed once the summits without a height are placed on the DEM (after rendering).
        }
        if (repeat < 1 || repeat > 1000) {
            throw new IllegalArgumentException("--repeat must be in 1..1000, got " + repeat);
        }
        boolean reference = panorama.referenceRenderer();
        if (reference) {
            // The CPU reference casts every pixel's own ray: no views, depth buffer or near plane to set.
            List<String> unused = new java.util.ArrayList<>();
            if (panorama.views != 8) {
                unused.add("--views");
            }
            if (!panorama.view.depthMode.equals("shader")) {
                unused.add("--depth-mode");
            }
            if (panorama.view.supersampling != 1) {
                unused.add("--supersampling");
            }
            if (panorama.view.nearMetres != 1) {
                unused.add("--near-m");
            }
            if (!unused.isEmpty()) {
                System.err.println("  warning: " + String.join(", ", unused) + " not used: --renderer reference draws no views");
            }
        }
        PanoramaWriter.Options writing = new PanoramaWriter.Options(panorama.pfm, summitList == null ? null : java.util.List.of(),
                labelOptions);
        long t0 = System.nanoTime();
        java.util.List<java.nio.file.Path> files;
        Panorama p = null;
        double writingMillis;
        // The output set is opened before rendering: an unwritable destination is found first, and
        // after any failure the previous outputs stay as they were.
        try (OutputSet set = OutputSet.open(out)) {
            set.protect(summitsFile, "the summit list (--summits)");
            set.checkTargets(PanoramaWriter.suffixes(req.colour(), req.distance(), wanted, writing));
            System.err.printf(Locale.ROOT, "dempano: %.5f, %.5f, range %s km, DEM %s%n", lat, lon,
                    dempano.util.Decimals.shortest(req.rangeMetres() / 1000, 3), dem.describe());
            java.util.List<String> table = new java.util.ArrayList<>();
            // The GL context starts on another thread while the tiles load and the mesh is built; the renderer's
            // name is printed when the views are drawn (asking for it sooner would wait for the context).
            try (Renderers.Lease lease = context.renderers().lease(dem, reference, repeat)) {
                PanoramaRenderer r = lease.renderer();
                boolean[] named = {false};
                if (reference) {
                    System.err.println("  renderer: " + r.glRenderer());
                    named[0] = true;
                }
                for (int i = 1; i <= repeat; i++) {
                    long start = System.nanoTime();
                    p = r.render(req, stage -> {
                        if (!named[0] && stage.startsWith("rendering")) {
                            System.err.println("  renderer: " + r.glRenderer());
                            named[0] = true;
                        }
                        System.err.printf(Locale.ROOT, "  [%6.1f s] %s%n", (System.nanoTime() - t0) / 1e9, stage);
                    });
                    table.add(String.format(Locale.ROOT, "| %d | %s | %.0f | %s |", i, i == 1 ? "cold" : "warm",
                            (System.nanoTime() - start) / 1e6, p.metadata().timingsMillis().entrySet().stream()
                                    .map(e -> e.getKey() + " " + Math.round(e.getValue())).collect(java.util.stream.Collectors.joining(", "))));
                }
            }
            if (repeat > 1) {
                System.out.println("| run | state | total ms | stages ms |");
                System.out.println("|---|---|---|---|");
                table.forEach(System.out::println);
            }
            if (p.metadata().viewpointMove() != null) {
                System.err.println("  " + p.metadata().viewpointMove().describe());
            }
            for (String w : p.metadata().warnings()) {
                System.err.println("  warning: " + w);
            }
            java.util.List<dempano.summits.SummitSighting> sightings = null;
            if (summitList != null) {
                dempano.summits.SummitList placed = dempano.summits.SummitProjector.placedOnDem(summitList, dem, p.metadata());
                dempano.summits.SummitProjector.warnings(placed, p.metadata()).forEach(w -> System.err.println("  warning: " + w));
                sightings = dempano.summits.SummitProjector.withDem(p.summits(placed), dem);
            }
            long beforeWriting = System.nanoTime();
            files = PanoramaWriter.stage(set, p, new PanoramaWriter.Options(panorama.pfm, sightings, labelOptions));
            set.commit();
            writingMillis = (System.nanoTime() - beforeWriting) / 1e6;
            if (sightings != null) {
                System.err.printf(Locale.ROOT, "  summits: %d within range, %d visible%n", sightings.size(),
                        sightings.stream().filter(dempano.summits.SummitSighting::visible).count());
            }
        }
        System.err.printf(Locale.ROOT, "  [%6.1f s] wrote %s%n", (System.nanoTime() - t0) / 1e9, context.asGiven(files, this.out));
        System.err.printf(Locale.ROOT, "  eye at %.1f m (ground %.1f m), %d×%d px, stages %s ms, writing %.0f ms%n",
                p.metadata().eyeAltitudeMetres(), p.metadata().groundElevationMetres(), p.widthPx(), p.heightPx(),
                p.metadata().timingsMillis(), writingMillis);
        return 0;
    }
}
