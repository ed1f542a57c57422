package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;

import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.Primitives;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Material;
import dev.trisect.scene.Pick;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.scene.internal.DrawnFrame;
import dev.trisect.texture.ProceduralTextures;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Picking the frame on screen: at once from its UV output, or by drawing it again without. */
class PicksTest {
    private static FrameSlot drawn(FrameRenderer r, Scene scene, boolean uv) {
        FrameSlot slot = new FrameSlot(160, 120);
        slot.drawn = new DrawnFrame(scene.snapshot(), Camera.looking(new Vec3(0, 0, 5), Vec3.ZERO), 160, 120, slot.draws);
        slot.drawnRender = RenderSettings.defaults();
        slot.frame.recordUv(uv);
        r.render(slot.draws, slot.drawnRender, slot.frame);
        return slot;
    }

    @Test
    void aFrameWithoutUvOutputIsDrawnAgainAndAnswersAsOneWithIt() {
        Scene scene = new Scene();
        SceneObject box = new SceneObject(Primitives.box(1, 1, 1), Material.of(ProceduralTextures.crate(64)),
                Transform.translation(0.2, 0, 0));
        scene.add(box);
        Picks picks = new Picks();
        List<Pick> answers = new ArrayList<>();
        try (FrameRenderer r = new FrameRenderer(1)) {
            FrameSlot withUv = drawn(r, scene, true);
            picks.request(withUv, 90, 70, answers::add);
            assertEquals(1, answers.size(), "answered at once from the frame's UV output");
            FrameSlot without = drawn(r, scene, false);
            picks.request(without, 90, 70, answers::add);
            assertEquals(1, answers.size(), "waits for the render thread");
            picks.serve(r);
            assertEquals(2, answers.size());
            picks.serve(r);
            assertEquals(2, answers.size(), "answered once");
            Pick a = answers.get(0);
            Pick b = answers.get(1);
            assertSame(box, a.object());
            assertSame(box, b.object());
            assertEquals(a.triangle(), b.triangle());
            assertEquals(a.point(), b.point());
            assertEquals(a.texelX(), b.texelX());
            assertEquals(a.texelY(), b.texelY());
            picks.request(without, 2, 2, answers::add);
            picks.serve(r);
            assertEquals(3, answers.size());
            assertNull(answers.get(2), "the background: no object");
        }
    }
}
