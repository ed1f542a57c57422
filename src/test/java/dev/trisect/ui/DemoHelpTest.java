package dev.trisect.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** The F1 panel and docs/demo.md show one table of keys and mouse gestures: DemoHelp's. */
class DemoHelpTest {
    @Test
    void theDocsTableIsTheHelpPanelsTable() throws Exception {
        String doc = Files.readString(Path.of("docs/demo.md"));
        int start = doc.indexOf("| input | does |");
        assertTrue(start >= 0, "docs/demo.md has the table");
        int end = doc.indexOf("\n\n", start);
        assertEquals(DemoHelp.markdown(), doc.substring(start, end + 1),
                "docs/demo.md's table of keys differs from DemoHelp.ROWS (the F1 panel's); paste this into the doc:\n"
                        + DemoHelp.markdown());
    }

    @Test
    void thePanelShowsEveryRow() {
        String html = DemoHelp.html();
        for (String[] row : DemoHelp.ROWS) {
            assertTrue(html.contains(row[0].replace("&", "&amp;")) && html.contains(row[1]), row[0]);
        }
    }
}
