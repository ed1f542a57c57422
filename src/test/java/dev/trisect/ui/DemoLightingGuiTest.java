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

    /**
     * The developer tools change the scene's shading, lights and fog directly; the keys step from what
     * the scene shows, not from a copy of their own: L after the tools' smooth went to flat, L put back
     * a fog the tools had turned off, the lamp stood still while the tools lit the scene, and the Fog
     * item stayed checked over a scene without fog.
     */
    @Test
    void keysAndFogItemFollowTheSceneWhoeverChangedIt() throws Exception {
        GuiTests.requireDisplay();
        window = onEdt(DemoWindows::demo);
        Scene scene = onEdt(() -> window.view().getScene());
        // The tools' Shading: smooth and their Lights on.
        SceneLighting.setShading(scene, Shading.SMOOTH);
        SceneLighting.lights(scene).forEach(l -> l.setVisible(true));
        assertEquals(Shading.SMOOTH, onEdt(() -> window.lighting.shading()));
        assertTrue(window.lighting.update(0.1, 1), "lit by the tools, the lamp circles");
        assertEquals(Shading.NONE, onEdt(() -> window.lighting.cycle()), "L steps on from smooth");
        assertFalse(window.lighting.update(0.1, 2), "unlit, nothing animates");

        javax.swing.Action g = onEdt(() -> window.commands.stream().map(DemoCommands.Entry::action)
                .filter(a -> "Fog".equals(a.getValue(javax.swing.Action.NAME))).findFirst().orElseThrow());
        javax.swing.JMenu sceneMenu = onEdt(() -> window.frame().getJMenuBar().getMenu(3));
        assertEquals("Scene", sceneMenu.getText());
        onEdt(() -> {
            g.actionPerformed(null);
            return null;
        });
        assertTrue(scene.fog().isPresent());
        // The tools' Fog: off. The item shows it when its menu opens, and G turns the fog on, not off.
        scene.setFog(null);
        onEdt(() -> {
            for (javax.swing.event.MenuListener l : sceneMenu.getMenuListeners()) {
                l.menuSelected(new javax.swing.event.MenuEvent(sceneMenu));
            }
            return null;
        });
        assertEquals(Boolean.FALSE, g.getValue(javax.swing.Action.SELECTED_KEY), "Fog unchecked");
        onEdt(() -> {
            g.actionPerformed(null);
            return null;
        });
        assertTrue(scene.fog().isPresent(), "G fogs a scene without fog");
        assertEquals(Boolean.TRUE, g.getValue(javax.swing.Action.SELECTED_KEY));
        // L leaves the fog as it is, the tools' choice included.
        scene.setFog(null);
        onEdt(() -> window.lighting.cycle());
        assertFalse(scene.fog().isPresent(), "L does not bring back the fog");
    }
}
