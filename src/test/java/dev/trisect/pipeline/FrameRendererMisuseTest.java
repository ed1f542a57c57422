package dev.trisect.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.math.Mat4;
import dev.trisect.math.Viewport;
import dev.trisect.render.BorderStyle;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderSettings;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;

/**
 * The internal renderer refuses what it cannot do right, with a message: outlining a framebuffer of
 * another size than the frame it drew, and every call after {@link FrameRenderer#close()}.
 */
class FrameRendererMisuseTest {
    private final SceneAsset scene = DemoScenes.boxes();
    private final Mat4 vp = scene.camera().viewProjection(new Viewport(64, 48));
    private final RenderSettings settings = RenderSettings.defaults();

    @Test
    void bordersIntoAFramebufferOfAnotherSizeAreRefused() {
        try (FrameRenderer r = new FrameRenderer(2)) {
            Framebuffer drawn = new Framebuffer(64, 48);
            r.render(scene.mesh(), scene.textureArray(), vp, settings, drawn);
            Framebuffer other = new Framebuffer(1000, 10);
            int[] before = other.colour().clone();
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> r.drawBorders(other, BorderStyle.plain(), settings.tessellation()));
            assertEquals("the framebuffer is 1000x10 but the frame last drawn was 64x48: outline the framebuffer that"
                    + " was rendered", e.getMessage());
            assertTrue(java.util.Arrays.equals(before, other.colour()), "nothing drawn into it");
            assertTrue(r.drawBorders(drawn, BorderStyle.plain(), settings.tessellation()) >= 0, "the drawn one is fine");
        }
    }

    @Test
    void everyCallAfterCloseSaysTheRendererIsClosed() {
        FrameRenderer r = new FrameRenderer(2);
        Framebuffer frame = new Framebuffer(64, 48);
        r.render(scene.mesh(), scene.textureArray(), vp, settings, frame);
        FrameRecord drawn = r.drawn();
        r.close();
        r.close(); // twice is harmless
        List<Executable> calls = List.of(
                () -> r.render(scene.mesh(), scene.textureArray(), vp, settings, frame),
                () -> r.coverage(scene.mesh(), scene.textureArray(), vp, settings, 64, 48),
                () -> r.drawBorders(frame, BorderStyle.plain(), settings.tessellation()),
                r::drawn,
                () -> drawn.pieceAt(32, 24, 0, 1),
                () -> drawn.fallbackOutlineAt(32, 24, 1),
                () -> drawn.knotsAt(32, 24, 0, 1),
                drawn::coverage);
        for (Executable call : calls) {
            IllegalStateException e = assertThrows(IllegalStateException.class, call);
            assertEquals("this FrameRenderer is closed: its threads have stopped", e.getMessage());
        }
    }

    @Test
    void aRecordOfAnEarlierFrameRefusesToAnswer() {
        try (FrameRenderer r = new FrameRenderer(2)) {
            Framebuffer frame = new Framebuffer(64, 48);
            r.render(scene.mesh(), scene.textureArray(), vp, settings, frame);
            FrameRecord first = r.drawn();
            assertEquals(64, first.width());
            first.pieceAt(32, 24, 0, 1); // current: answers
            r.render(scene.mesh(), scene.textureArray(), vp, settings, frame);
            IllegalStateException e = assertThrows(IllegalStateException.class, () -> first.pieceAt(32, 24, 0, 1));
            assertTrue(e.getMessage().startsWith("this record is of an earlier frame"), e.getMessage());
            assertThrows(IllegalStateException.class, first::coverage);
            r.drawn().pieceAt(32, 24, 0, 1); // the new record answers
        }
    }
}
