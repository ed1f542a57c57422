package dev.trisect.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.code_intelligence.jazzer.junit.FuzzTest;
import dev.trisect.base.InputException;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;

/**
 * Jazzer fuzz target: the OBJ reader with its MTL library. The input is the OBJ text, a NUL byte, then
 * the MTL text (named {@code m.mtl} and {@code mät.mtl}, so an OBJ with {@code mtllib m.mtl} or
 * {@code mtllib mät.mtl} reads it). Every input must give
 * a consistent model or an {@link InputException} with a one-line message naming a file; any other
 * exception, a hang or running out of memory is a finding. Seeds and regression cases are in
 * {@code src/test/resources/dev/trisect/mesh/ObjMtlFuzzTestInputs}.
 */
class ObjMtlFuzzTest {
    @FuzzTest(maxDuration = "5m")
    void objAndMtlGiveAModelOrAOneLineError(byte[] input) throws IOException {
        Path dir = Files.createTempDirectory("trisect-fuzz");
        try {
            int nul = 0;
            while (nul < input.length && input[nul] != 0) {
                nul++;
            }
            Path obj = Files.write(dir.resolve("m.obj"), Arrays.copyOf(input, nul));
            byte[] mtl = nul < input.length ? Arrays.copyOfRange(input, nul + 1, input.length) : new byte[0];
            Files.write(dir.resolve("m.mtl"), mtl);
            // The same library under a name outside ASCII, so that `mtllib mät.mtl` finds it too (where the
            // locale maps file names as UTF-8; elsewhere such a name cannot be made at all).
            try {
                Files.write(dir.resolve("m\u00e4t.mtl"), mtl);
            } catch (java.nio.file.InvalidPathException e) {
                // Not a UTF-8 locale: the fuzzer still reaches the reader's UTF-8 checks through names.
            }
            try {
                ObjModel model = ObjReader.read(obj, true);
                Mesh mesh = model.mesh();
                assertEquals(mesh.materialCount(), model.materialTextures().size());
                for (int c : mesh.cornerPositions()) {
                    assertTrue(c >= 0 && 3 * c < mesh.positions().length, "corner index in range");
                }
                for (int c : mesh.cornerUvs()) {
                    assertTrue(c >= -1 && 2 * c < mesh.uvs().length, "UV index in range");
                }
            } catch (InputException e) {
                assertTrue(e.getMessage().startsWith(dir.toString()), e.getMessage());
                assertFalse(e.getMessage().contains("\n") || e.getMessage().contains("\r"), e.getMessage());
            }
        } finally {
            try (var files = Files.list(dir)) {
                for (Path f : files.toList()) {
                    Files.delete(f);
                }
            }
            Files.delete(dir);
        }
    }
}
