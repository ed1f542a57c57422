package dev.trisect.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.EnumSet;
import org.junit.jupiter.api.Test;

/**
 * What the paths and split policies answer when a stage asks: which paths divide, split or place knots,
 * which threshold a policy reads and writes and its floor; and that the span path's knot spacing is a
 * setting of its own, apart from the error policy's threshold.
 */
class PathQuestionsTest {
    @Test
    void eachPathAnswersWhatItDoes() {
        EnumSet<RenderMode> divides = EnumSet.noneOf(RenderMode.class);
        EnumSet<RenderMode> splits = EnumSet.noneOf(RenderMode.class);
        EnumSet<RenderMode> knots = EnumSet.noneOf(RenderMode.class);
        for (RenderMode m : RenderMode.values()) {
            if (m.divides()) {
                divides.add(m);
            }
            if (m.splits()) {
                splits.add(m);
            }
            if (m.knots()) {
                knots.add(m);
            }
        }
        assertEquals(EnumSet.of(RenderMode.PERSPECTIVE, RenderMode.SPANS), divides);
        assertEquals(EnumSet.of(RenderMode.TESSELLATED), splits);
        assertEquals(EnumSet.of(RenderMode.SPANS), knots);
        assertEquals("spans", RenderMode.SPANS.id());
    }

    @Test
    void eachPolicyReadsAndWritesItsOwnThreshold() {
        TessellationSettings t = TessellationSettings.defaults().withMaxEdge(24).withMaxError(0.3);
        assertEquals(24, SplitPolicy.EDGE.threshold(t));
        assertEquals(0.3, SplitPolicy.ERROR.threshold(t));
        TessellationSettings e = SplitPolicy.EDGE.withThreshold(t, 7);
        assertEquals(7, e.maxEdge());
        assertEquals(0.3, e.maxError(), "the other threshold is left as it is");
        TessellationSettings r = SplitPolicy.ERROR.withThreshold(t, 0.125);
        assertEquals(0.125, r.maxError());
        assertEquals(24, r.maxEdge());
        assertEquals(2, SplitPolicy.EDGE.floor());
        assertEquals(0.05, SplitPolicy.ERROR.floor());
        assertTrue(SplitPolicy.ERROR.measuresError());
        assertFalse(SplitPolicy.EDGE.measuresError());
        assertEquals("error", SplitPolicy.ERROR.id());
    }

    @Test
    void theKnotSpacingIsApartFromTheErrorPolicysThreshold() {
        RenderSettings s = RenderSettings.defaults().withMode(RenderMode.SPANS);
        assertEquals(RenderSettings.DEFAULT_KNOT_ERROR, s.knotError());
        RenderSettings finer = s.withKnotError(0.1);
        assertEquals(0.1, finer.knotError());
        assertEquals(s.tessellation(), finer.tessellation(), "the split settings do not move");
        RenderSettings other = s.withTessellation(s.tessellation().withMaxError(3));
        assertEquals(RenderSettings.DEFAULT_KNOT_ERROR, other.knotError(), "the knots do not follow max error");
        assertThrows(IllegalArgumentException.class, () -> s.withKnotError(0));
        assertThrows(IllegalArgumentException.class, () -> s.withKnotError(Double.NaN));
    }
}
