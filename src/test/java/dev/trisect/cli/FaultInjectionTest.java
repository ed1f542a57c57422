package dev.trisect.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.io.Faults;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Function;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 14's fault injection: for every command with outputs, a failure at each of its writes — the
 * output's folder missing, the disk full at that file (injected, {@link Faults}), standard output full or
 * closed — ends the command with one line and a non-zero status, leaves every old output as it was and no
 * temporary file behind, and still prints what was computed when only a file failed.
 */
class FaultInjectionTest {
    @TempDir
    Path dir;

    @AfterEach
    void clear() {
        Faults.clear();
    }

    /** A command: its arguments for a folder, the files it writes there, whether it prints results. */
    private record Command(String name, Function<Path, List<String>> args, List<String> files, boolean prints) {
    }

    private List<Command> commands(Path inputs) {
        List<String> small = List.of("--scene", "floor", "--size", "16x12");
        List<String> quick = List.of("--frames", "2", "--warmup", "0");
        return List.of(
                new Command("render", d -> cat(List.of("render", "--stats", "--out", s(d, "r.png"), "--uv-out",
                        s(d, "r.pfm")), small), List.of("r.png", "r.pfm"), true),
                new Command("compare", d -> cat(List.of("compare", "--heatmap", s(d, "h.png"), "--out", s(d, "c.png")),
                        small), List.of("h.png", "c.png"), true),
                new Command("diff", d -> List.of("diff", "--image", s(inputs, "a.png"), "--uv", s(inputs, "a.pfm"),
                        "--reference", s(inputs, "b.png"), "--reference-uv", s(inputs, "b.pfm"), "--heatmap",
                        s(d, "d.png")), List.of("d.png"), true),
                new Command("export", d -> List.of("export", "--scene", "floor", "--to", s(d, "e.obj")),
                        List.of("e.obj", "e.mtl", "e-floor.ppm"), true),
                new Command("bench --sweep", d -> cat(cat(List.of("bench", "--sweep", "--edges", "64", "--errors", "4",
                        "--plot", s(d, "s.png")), small), quick), List.of("s.png"), true),
                new Command("bench --target-ms", d -> cat(cat(List.of("bench", "--target-ms", "5", "--plot",
                        s(d, "t.png")), small), quick), List.of("t.png"), true),
                new Command("bench --json", d -> cat(cat(List.of("bench", "--json"), small), quick), List.of(), true),
                new Command("render --list-scenes", d -> List.of("render", "--list-scenes"), List.of(), true));
    }

    @Test
    void everyFaultAtEveryWriteOfEveryCommandKeepsTheOldOutputsAndFails() throws IOException {
        Path inputs = Files.createDirectories(dir.resolve("inputs"));
        for (String n : new String[] {"a", "b"}) {
            assertEquals(0, CliRun.of("render", "--scene", "floor", "--size", "16x12", "--mode",
                    n.equals("a") ? "affine" : "perspective", "--out", s(inputs, n + ".png"), "--uv-out",
                    s(inputs, n + ".pfm")).status());
        }
        int cases = 0;
        int outputs = 0;
        List<String> failures = new ArrayList<>();
        for (Command c : commands(inputs)) {
            // Without a fault: it works, and writes exactly its files (each through the batch, counted).
            Path clean = Files.createDirectories(dir.resolve(c.name().replace(' ', '_') + "-clean"));
            var written = Faults.fullDiskAt(0);
            CliRun ok = CliRun.of(c.args().apply(clean).toArray(String[]::new));
            assertEquals(0, ok.status(), c.name() + ": " + ok.err());
            assertEquals(c.files().size(), written.get(), c.name() + ": files written");
            assertEquals(c.files(), c.files().stream().filter(f -> Files.exists(clean.resolve(f))).toList());
            outputs += c.files().size() + 1;
            // The disk full at each file in turn, and each file's folder missing.
            for (int k = 1; k <= c.files().size(); k++) {
                cases++;
                Path d = seeded(c, "full" + k);
                Faults.fullDiskAt(k);
                CliRun r = CliRun.of(c.args().apply(d).toArray(String[]::new));
                Faults.clear();
                check(failures, c, "disk full at " + c.files().get(k - 1), r, d, "No space left on device");
                if (c.prints() && r.out().isBlank()) {
                    failures.add(c.name() + ", disk full at " + c.files().get(k - 1) + ": nothing printed");
                }
                if (k == 1 || !c.name().equals("export")) {
                    // Export makes its folder; what it cannot make is a folder where a file is in the way.
                    cases++;
                    Path m = seeded(c, "missing" + k);
                    Path bad = c.name().equals("export") ? Files.writeString(m.resolve("file"), "") : m.resolve("nowhere");
                    List<String> args = new ArrayList<>(c.args().apply(m));
                    String target = s(m, c.files().get(k - 1));
                    args.set(args.indexOf(target), s(bad, c.files().get(k - 1)));
                    CliRun missing = CliRun.of(args.toArray(String[]::new));
                    check(failures, c, "folder missing for " + c.files().get(k - 1), missing, m,
                            c.name().equals("export") ? "cannot create the directory" : "no such directory");
                    if (!missing.out().isEmpty()) {
                        failures.add(c.name() + ": a missing folder is found before the work, yet it printed "
                                + missing.out());
                    }
                }
            }
            // Standard output full (a disk, /dev/full) or closed (a reader gone: a pipe, >&-).
            for (String reason : List.of("No space left on device", "Broken pipe")) {
                cases++;
                Path d = seeded(c, "stdout-" + reason.charAt(0));
                CliRun r = CliRun.withFailingStdout(reason, c.args().apply(d).toArray(String[]::new));
                check(failures, c, "standard output: " + reason, r, d, "cannot write to standard output: " + reason);
            }
        }
        assertEquals(List.of(), failures);
        // The counts the closing note reports.
        assertEquals(8, commands(inputs).size());
        assertEquals(18, outputs, "outputs, standard output included");
        assertEquals(34, cases, "faults injected");
    }

    /** A fresh folder for one case, with an old version of each of the command's files. */
    private Path seeded(Command c, String label) throws IOException {
        Path d = Files.createDirectories(dir.resolve(c.name().replace(' ', '_') + "-" + label));
        for (String f : c.files()) {
            Files.writeString(d.resolve(f), "OLD " + f);
        }
        return d;
    }

    private static void check(List<String> failures, Command c, String fault, CliRun r, Path d, String reason)
            throws IOException {
        String what = c.name() + ", " + fault + ": ";
        String err = r.err().strip();
        if (r.status() != 1) {
            failures.add(what + "exit " + r.status() + " " + err);
        }
        if (err.contains("\n") || err.contains("\tat ") || !err.contains(reason)) {
            failures.add(what + "not one line with '" + reason + "': " + err);
        }
        for (String f : c.files()) {
            if (!Files.readString(d.resolve(f)).equals("OLD " + f)) {
                failures.add(what + f + " was changed");
            }
        }
        try (Stream<Path> files = Files.list(d)) {
            List<String> left = files.map(p -> p.getFileName().toString())
                    .filter(n -> !c.files().contains(n) && !n.equals("file")).toList();
            if (!left.isEmpty()) {
                failures.add(what + "left " + left);
            }
        }
    }

    private static String s(Path d, String name) {
        return d.resolve(name).toString();
    }

    private static List<String> cat(List<String> a, List<String> b) {
        List<String> all = new ArrayList<>(a);
        all.addAll(b);
        return all;
    }

    @Test
    @Timeout(value = 120, unit = TimeUnit.SECONDS)
    void aSweepWhosePlotCannotBeWrittenFailsBeforeTheWork() {
        // A million frames per setting would take hours: the missing folder must be found first (no
        // row on standard output; the timeout only guards against a hang).
        CliRun r = CliRun.of("bench", "--scene", "floor", "--sweep", "--frames", "1000000", "--plot",
                dir.resolve("nowhere/s.png").toString());
        assertEquals(1, r.status(), r.err());
        assertEquals("trisect: " + dir.resolve("nowhere/s.png") + ": cannot write: no such directory "
                + dir.resolve("nowhere"), r.errLine());
        assertEquals("", r.out());
    }
}
