package dev.trisect.content;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The globe scenes used for timing against the triangle count have the counts their names say. */
class GlobeScenesTest {
    @Test
    void globesHaveTheirTriangleCounts() {
        assertEquals(10_000, DemoScenes.byName("sphere").orElseThrow().mesh().triangleCount());
        assertEquals(99_856, DemoScenes.byName("sphere100k").orElseThrow().mesh().triangleCount());
        assertEquals(160_000, DemoScenes.byName("sphere160k").orElseThrow().mesh().triangleCount());
        assertEquals(1_000_000, DemoScenes.byName("sphere1m").orElseThrow().mesh().triangleCount());
    }
}
