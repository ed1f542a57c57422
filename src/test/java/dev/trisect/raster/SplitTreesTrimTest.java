package dev.trisect.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * {@link SplitTrees#shrinkTo} gives back what a spike took, whichever of its arrays the spike grew:
 * a frame of a million input triangles that were not split grows only the groups' references.
 */
class SplitTreesTrimTest {
    @Test
    void aSpikeOfUnsplitTrianglesGivesItsStorageBack() {
        SplitTrees trees = new SplitTrees();
        for (int i = 0; i < 1_000_000; i++) {
            trees.addSingle(i);
        }
        trees.clear();
        trees.addSingle(7);
        trees.addSingle(9);
        // About what Chunk.trimIfOversized asks for after such a spike.
        trees.shrinkTo(8192);
        assertTrue(trees.refs().length <= 8192, "references kept for " + trees.refs().length + " groups");
        assertEquals(2, trees.count());
        assertEquals(-1 - 7, trees.refs()[0]);
        assertEquals(-1 - 9, trees.refs()[1]);
    }
}
