package dev.trisect.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * MeshBuilder refuses, at the call, positions and texture coordinates the mesh could not keep as
 * finite floats (NaN, infinities, doubles beyond the float range), naming the values, as Transform and
 * Camera refuse theirs; the builder is unchanged by a refused call.
 */
class MeshBuilderLimitsTest {
    @ParameterizedTest
    @ValueSource(doubles = {Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, 1e39, -3.5e38})
    void aPositionThatIsNotAFiniteFloatIsRefusedNamingIt(double bad) {
        MeshBuilder b = new MeshBuilder();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> b.position(1, bad, 2));
        assertTrue(e.getMessage().startsWith("position (1.0, " + bad + ", 2.0) is not a finite float"), e.getMessage());
        assertEquals(0, b.positionCount());
    }

    @ParameterizedTest
    @ValueSource(doubles = {Double.NaN, Double.POSITIVE_INFINITY, 1e39})
    void aTextureCoordinateThatIsNotAFiniteFloatIsRefusedNamingIt(double bad) {
        MeshBuilder b = new MeshBuilder();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> b.uv(bad, 0.5));
        assertTrue(e.getMessage().startsWith("texture coordinate (" + bad + ", 0.5) is not a finite float"),
                e.getMessage());
        assertEquals(0, b.uvCount());
    }

    @Test
    void theLargestFloatsAreKept() {
        MeshBuilder b = new MeshBuilder();
        b.position(Float.MAX_VALUE, -Float.MAX_VALUE, Float.MIN_VALUE);
        b.uv(-Float.MAX_VALUE, 1e-45);
        Mesh m = b.build();
        assertEquals(Float.MAX_VALUE, m.positions()[0]);
        assertEquals(-Float.MAX_VALUE, m.uvs()[0]);
    }
}
