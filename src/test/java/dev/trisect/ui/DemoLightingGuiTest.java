package dev.trisect.ui;

import static dev.trisect.GuiTests.onEdt;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.GuiTests;
import dev.trisect.content.SceneLighting;
import dev.trisect.render.Shading;
import dev.trisect.scene.Light;
import dev.trisect.scene.Scene;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The demo's L key cycles lighting off, flat, smooth over every material, with its lights; G fogs. */
@Tag("gui")
class DemoLightingGuiTest {
    private DemoWindow window;

    @AfterEach
    void close() throws Exception {
        if (window != null) {
            SwingUtilities.invokeAndWait(() -> window.frame().dispose());
        }
    }

    @Test
    void lightingCyclesOffFlatSmoothAndFogToggles() throws Exception {
        GuiTests.requireDisplay();
        window = onEdt(DemoWindows::demo);
        Scene scene = onEdt(() -> window.view().getScene());
        assertEquals(Shading.NONE, SceneLighting.shading(scene), "the demo opens unlit");
        assertEquals(3, SceneLighting.lights(scene).size());
        assertFalse(SceneLighting.lights(scene).stream().anyMatch(Light::isVisible));
        for (Shading want : new Shading[] {Shading.FLAT, Shading.SMOOTH, Shading.NONE}) {
            assertEquals(want, onEdt(() -> window.lighting.cycle()));
            assertEquals(want, SceneLighting.shading(scene));
            assertEquals(want != Shading.NONE, SceneLighting.lights(scene).stream().allMatch(Light::isVisible));
        }
        // The L key's status says the menu's words: off, flat, smooth (not the enum's NONE).
        javax.swing.Action key = onEdt(() -> window.commands.stream().map(DemoCommands.Entry::action)
                .filter(a -> String.valueOf(a.getValue(javax.swing.Action.NAME)).startsWith("Lighting: off, flat"))
                .findFirst().orElseThrow());
        for (String want : new String[] {"flat", "smooth", "off"}) {
            assertEquals("Lighting: " + want, onEdt(() -> {
                key.actionPerformed(null);
                return window.statusText();
            }));
        }
        onEdt(() -> {
            window.lighting.setFog(true);
            return null;
        });
        assertTrue(scene.fog().isPresent());
    }
}
