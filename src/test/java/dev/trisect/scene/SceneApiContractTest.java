package dev.trisect.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.mesh.Primitives;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * What the scene API's Javadoc promises a library user, held to the letter: found by trying the API
 * from a program of its own (the API trial).
 */
class SceneApiContractTest {
    private static SceneObject box() {
        return new SceneObject(Primitives.box(1, 1, 1), Material.colour(0x808080));
    }

    /** The Javadoc says unmodifiable: a caller's edit would otherwise look as if it changed the scene. */
    @Test
    void snapshotAndObjectsAreUnmodifiable() {
        Scene scene = new Scene();
        scene.add(box());
        List<Scene.Placed> placed = scene.snapshot();
        List<SceneObject> objects = scene.objects();
        assertThrows(UnsupportedOperationException.class, () -> placed.clear());
        assertThrows(UnsupportedOperationException.class, () -> objects.add(box()));
        assertEquals(1, placed.size());
        assertEquals(1, objects.size());
    }

    /** A refused add changes nothing: the nodes before the bad one were added before the check. */
    @Test
    void aRefusedAddAddsNothing() {
        Group group = new Group("g");
        Group elsewhere = new Group("elsewhere");
        SceneObject a = box();
        elsewhere.add(a);
        assertThrows(IllegalArgumentException.class, () -> group.add(a, new Scene()));
        assertEquals(List.of(), group.children());
        assertEquals(elsewhere, a.parent());
        Group outer = new Group("outer");
        outer.add(group);
        assertThrows(IllegalArgumentException.class, () -> group.add(a, outer));
        assertEquals(List.of(), group.children());
        assertEquals(List.of(a), elsewhere.children());
        assertThrows(NullPointerException.class, () -> group.add(a, null));
        assertEquals(List.of(), group.children());
    }

    /**
     * Every thread of a renderer starts with it: an unbounded count (257 went through, 100,000 started
     * tens of thousands of threads and ended in an OutOfMemoryError that left them running) is refused
     * as the view and the command line refuse it.
     */
    @Test
    void threadCountsBeyondTheLimitAreRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new SceneRenderer(257));
        assertEquals("threads must be between 1 and 256, got 257", e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new SceneRenderer(0));
        try (SceneRenderer r = new SceneRenderer()) {
            assertTrue(r.threads() >= 1 && r.threads() <= 256, "threads " + r.threads());
        }
    }

    /** update(null) failed inside the lock with the JDK's message about a local variable. */
    @Test
    void updateNamesAMissingRunnable() {
        assertEquals("changes is null",
                assertThrows(NullPointerException.class, () -> new Scene().update(null)).getMessage());
    }

    /**
     * A program loading an OBJ was told of a command-line option it has not got ("no --texture"), and a
     * null notes consumer passed whenever the file gave no note, failing only for files that did.
     */
    @Test
    void loadSpeaksToTheLibraryAndRefusesNullNotes(@TempDir Path dir) throws IOException {
        Path obj = Files.writeString(dir.resolve("tri.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        List<String> notes = new ArrayList<>();
        SceneObject.load(obj, notes::add);
        assertEquals(1, notes.size(), notes.toString());
        assertFalse(notes.get(0).contains("--"), notes.get(0));
        assertEquals("tri.obj: no texture for material default (no map_Kd); using the built-in UV grid", notes.get(0));
        assertEquals("notes is null: pass note -> { } to ignore them",
                assertThrows(NullPointerException.class, () -> SceneObject.load(obj, null)).getMessage());
        assertEquals("OBJ path is null", assertThrows(NullPointerException.class, () -> SceneObject.load(null)).getMessage());
    }
}
