package dev.trisect.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.base.InputException;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.io.TempDir;

/** OBJ and MTL files written into a temporary folder, read, and their one-line errors, for the ObjReader tests. */
abstract class ObjFixture {
    static final String TRIANGLE_VERTICES = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

    @TempDir
    Path dir;

    Path write(String name, String text) throws IOException {
        Path file = dir.resolve(name);
        Files.createDirectories(file.getParent());
        Files.write(file, text.getBytes(StandardCharsets.ISO_8859_1));
        return file;
    }

    ObjModel read(String text) throws IOException {
        return ObjReader.read(write("scene.obj", text), false);
    }

    /** The error that reading {@code file} gives, with the temporary directory cut from its front. */
    String error(Path file, boolean readMaterials) {
        InputException e = assertThrows(InputException.class, () -> ObjReader.read(file, readMaterials));
        assertEquals(1, e.exitStatus());
        String message = e.getMessage();
        assertTrue(message.indexOf('\n') < 0 && message.indexOf('\r') < 0, message);
        String prefix = dir + dir.getFileSystem().getSeparator();
        assertTrue(message.startsWith(prefix), message);
        return message.substring(prefix.length());
    }

    String error(String text) throws IOException {
        return error(write("scene.obj", text), false);
    }
}
