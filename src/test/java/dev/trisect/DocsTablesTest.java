package dev.trisect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The Markdown tables of the README and docs/ render as tables: a row (a line that starts and ends
 * with {@code |}) follows another row or a blank line, and a table's first row is followed by its
 * delimiter row ({@code |---|}). A note left between two rows would otherwise end the table and show
 * the rows after it as plain text (GitHub Flavored Markdown, "Tables (extension)").
 */
class DocsTablesTest {
    @Test
    void everyTableRowIsInATable() throws IOException {
        List<Path> files = new ArrayList<>(List.of(Path.of("README.md")));
        try (Stream<Path> docs = Files.walk(Path.of("docs"))) {
            docs.filter(p -> p.toString().endsWith(".md")).sorted().forEach(files::add);
        }
        assertTrue(files.size() > 10, "the docs were found: " + files);
        List<String> broken = new ArrayList<>();
        for (Path f : files) {
            broken.addAll(brokenRows(f.toString(), Files.readAllLines(f)));
        }
        assertEquals(List.of(), broken);
    }

    @Test
    void aNoteBetweenTwoRowsIsCaught() {
        List<String> lines = List.of("| a | b |", "|---|---|", "| 1 | 2 |", "(a note)", "| 3 | 4 |", "",
                "| c |", "not a delimiter", "", "```", "| in | code |", "```");
        assertEquals(List.of("x.md:5: a table row after text", "x.md:7: a table without its delimiter row"),
                brokenRows("x.md", lines));
    }

    /** The rows of {@code lines} that do not render as table rows, as {@code name:line: why}. */
    static List<String> brokenRows(String name, List<String> lines) {
        List<String> broken = new ArrayList<>();
        boolean code = false;
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i).strip();
            if (line.startsWith("```")) {
                code = !code;
            }
            if (code || !row(line)) {
                continue;
            }
            String before = i == 0 ? "" : lines.get(i - 1).strip();
            if (!before.isEmpty() && !row(before)) {
                broken.add(name + ":" + (i + 1) + ": a table row after text");
            } else if (before.isEmpty()
                    && !(i + 1 < lines.size() && lines.get(i + 1).strip().matches("\\|( *:?-+:? *\\|)+"))) {
                broken.add(name + ":" + (i + 1) + ": a table without its delimiter row");
            }
        }
        return broken;
    }

    private static boolean row(String line) {
        return line.length() > 1 && line.startsWith("|") && line.endsWith("|");
    }
}
