package dev.trisect.devtools;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.content.SceneLighting;
import dev.trisect.math.Vec3;
import dev.trisect.render.Colour;
import dev.trisect.render.Fog;
import dev.trisect.render.Shading;
import dev.trisect.scene.Light;
import dev.trisect.scene.Scene;
import dev.trisect.view.internal.ViewController;
import java.util.ArrayList;
import java.util.List;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;

/** The developer tools' light and fog section, without a window: its fields read the fog drawn. */
class LightSectionTest {

    @Test
    void theFogFieldsShowTheScenesFogWhoeverSetIt() throws Exception {
        SwingUtilities.invokeAndWait(() -> {
            Tools t = Tools.open();
            LightSection light = t.light();
            Scene scene = t.scene();
            // As the demo's G key sets it: from the camera's distance to its target to eight times that.
            scene.setFog(Fog.linear(16.03, 128.25, Colour.WHITE));
            light.refresh(null, null, null);
            NumberField[] f = light.fogFields();
            assertEquals("16.03", f[0].getText(), "Fog start");
            assertEquals("128.25", f[1].getText(), "Fog end");
            assertEquals("linear", light.readoutFog());
            scene.setFog(Fog.exp2(0.0025, Colour.WHITE));
            light.refresh(null, null, null);
            assertEquals("0.0025", f[2].getText(), "Fog density, a large scene's");
            assertEquals("exp2", light.readoutFog());
        });
    }

    @Test
    void aStartTheFogRefusesIsNotKept() throws Exception {
        SwingUtilities.invokeAndWait(() -> {
            Tools t = Tools.open();
            LightSection light = t.light();
            Scene scene = t.scene();
            Fog fog = Fog.linear(10, 80, Colour.BLACK);
            scene.setFog(fog);
            light.refresh(null, null, null);
            NumberField start = light.fogFields()[0];
            start.setText("200");
            start.commit();
            assertEquals(fog, scene.fog().orElseThrow(), "the fog in force stays");
            assertEquals("10.00", start.getText(), "and the field shows it, not the refused start");
            start.setText("20");
            start.commit();
            assertEquals(20, scene.fog().orElseThrow().start());
            assertEquals("20.00", start.getText());
        });
    }

    @Test
    void theShadingSaysTheDemosWordsAndWarnsWhenNothingLightsIt() throws Exception {
        SwingUtilities.invokeAndWait(() -> {
            Tools t = Tools.open();
            List<String> said = t.said();
            LightSection light = t.light();
            Scene scene = t.scene();
            javax.swing.JComboBox<String> combo = light.shadingCombo();
            List<String> items = new ArrayList<>();
            for (int i = 0; i < combo.getItemCount(); i++) {
                items.add(combo.getItemAt(i));
            }
            assertEquals(List.of("off", "flat", "smooth"), items, "the demo's menu and status say these");
            light.refresh(null, null, null);
            assertEquals("off", light.readoutShading());
            assertFalse(light.readout("Lights").contains("black"), light.readout("Lights"));
            assertTrue(LightSection.lights(scene).isEmpty(), "the boxes come without a light");

            combo.setSelectedItem("flat");
            assertEquals(Shading.FLAT, SceneLighting.shading(scene));
            assertEquals(List.of(LightSection.NO_LIGHT), said, "said where the user looks: the status line");
            light.refresh(null, null, null);
            assertTrue(light.readout("Lights").endsWith(LightSection.NO_LIGHT), light.readout("Lights"));

            // Lights there but hidden, as the demo's with its lighting off: tick Lights on, or L.
            Light lamp = Light.directional(new Vec3(0, 0, 1), Colour.WHITE);
            lamp.setVisible(false);
            scene.add(lamp);
            said.clear();
            combo.setSelectedItem("smooth");
            assertEquals(List.of(LightSection.UNLIT), said);
            light.refresh(null, null, null);
            assertEquals("smooth", light.readoutShading());
            assertTrue(light.readout("Lights").endsWith(LightSection.UNLIT), light.readout("Lights"));

            said.clear();
            light.lightsOnBox().doClick();
            assertTrue(lamp.isVisible());
            light.refresh(null, null, null);
            assertEquals(List.of(), said, "a shining light: nothing to say");
            assertFalse(light.readout("Lights").contains("black"), light.readout("Lights"));
            light.lightsOnBox().doClick();
            assertEquals(List.of(LightSection.UNLIT), said, "hiding the last light says it too");

            said.clear();
            combo.setSelectedItem("off");
            light.refresh(null, null, null);
            assertEquals(List.of(), said, "unlit: the lights do not matter");
            assertFalse(light.readout("Lights").contains("black"), light.readout("Lights"));
        });
    }

    @Test
    void theFogFieldsTakeWhatTheFogTakesAndRefuseWhatItRefusesWithItsMessage() throws Exception {
        SwingUtilities.invokeAndWait(() -> {
            Tools t = Tools.open();
            List<String> said = t.said();
            LightSection light = t.light();
            Scene scene = t.scene();
            scene.setFog(Fog.linear(10, 80, Colour.BLACK));
            light.refresh(null, null, null);
            NumberField[] f = light.fogFields();
            // Fog.linear takes a start behind the eye: the fog is already part-way at depth 0.
            f[0].setText("-5");
            f[0].commit();
            assertEquals(-5, scene.fog().orElseThrow().start());
            assertEquals(80, scene.fog().orElseThrow().end());
            assertEquals("-5.00", f[0].getText());
            f[1].setText("2e6");
            f[1].commit();
            assertEquals(2e6, scene.fog().orElseThrow().end(), "an end beyond a million too");
            assertEquals(List.of(), said);

            f[0].setText("1e400");
            f[0].commit();
            assertEquals(List.of("Fog: fog values must be finite"), said, "the fog's own message");
            assertEquals(-5, scene.fog().orElseThrow().start());
            assertEquals("-5.00", f[0].getText());
            said.clear();
            f[0].setText("-1.7e308");
            f[1].setText("1.7e308");
            f[1].commit();
            f[0].commit();
            assertEquals(1, said.size(), said.toString());
            assertTrue(said.get(0).startsWith("Fog: linear fog's end - start must be finite"), said.get(0));
            assertEquals(-5, scene.fog().orElseThrow().start());
            assertEquals(1.7e308, scene.fog().orElseThrow().end());
            assertEquals("1.70000e+308", f[1].getText(), "a huge end in few digits");

            // A density below 0 is refused while the fog is linear too, not kept for later.
            said.clear();
            f[2].setText("-0.5");
            f[2].commit();
            assertEquals(List.of("Fog: fog density must be >= 0, not -0.5"), said);
            assertEquals("0.0500", f[2].getText());
            said.clear();
            f[2].setText("x");
            f[2].commit();
            assertEquals(1, said.size());
            assertTrue(said.get(0).endsWith("Fog density: \"x\" is not a number; kept 0.0500"), said.get(0));
        });
    }

    /** The boxes' windowless controller, its developer tools' Light and fog section, its scene, and what it says. */
    private record Tools(ViewController controller, LightSection light, Scene scene, List<String> said) {
        static Tools open() {
            ViewController c = WindowlessController.boxes();
            List<String> said = new ArrayList<>();
            c.addMessageListener(said::add);
            return new Tools(c, new DevToolsPanel(c).section(LightSection.class), c.state().scene(), said);
        }
    }
}
