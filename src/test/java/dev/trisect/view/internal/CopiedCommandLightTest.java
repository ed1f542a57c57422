package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.cli.Cli;
import dev.trisect.content.AssetScenes;
import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneLighting;
import dev.trisect.devtools.CliArgs;
import dev.trisect.math.Vec3;
import dev.trisect.metrics.Comparison;
import dev.trisect.render.Colour;
import dev.trisect.render.Fog;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.Shading;
import dev.trisect.mesh.Primitives;
import dev.trisect.scene.Light;
import dev.trisect.scene.Material;
import dev.trisect.scene.SceneObject;
import dev.trisect.scene.Scene;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The developer tools' copied compare command of a lit, fogged frame draws that frame: the command line
 * prints the numbers the tools show. It carried no light or fog, so it measured the unlit frame (the
 * demo lit smooth showed 39.6 dB where the command printed 30.5 dB).
 */
class CopiedCommandLightTest {
    private static double number(String json, String key) {
        Matcher m = Pattern.compile("\"" + key + "\":(-?[0-9.eE+-]+|null)").matcher(json);
        assertTrue(m.find(), key + " in " + json);
        return m.group(1).equals("null") ? Double.NaN : Double.parseDouble(m.group(1));
    }

    /** The loop's measurement of the first frame drawn with the default settings. */
    private static ViewState.Measurement measure(ViewState state) throws Exception {
        state.toolsOpen(true);
        return LoopRun.until(state, new TripleBuffer(), 2, "measurement", () -> {
            ViewState.Measurement m = state.measurement();
            return m != null && state.progress().frames() >= 1 ? m : null;
        });
    }

    /** The demo lit by a coloured ambient, a grey directional and an orange attenuated point light. */
    private static ViewState litDemo(Shading shading, Fog fog) {
        ViewState state = new ViewState(DemoScenes.demo());
        state.viewSize(320, 180);
        Scene scene = state.scene();
        scene.add(Light.ambient(new Colour(0.2, 0.25, 0.3)), Light.directional(new Vec3(0.3, 1, 0.7),
                Colour.grey(0.75)), Light.point(new Vec3(1, 2, -4), new Colour(1, 0.6, 0.3), 1, 0.2, 0.05));
        SceneLighting.setShading(scene, shading);
        scene.setFog(fog);
        return state;
    }

    @ParameterizedTest
    @CsvSource({"SMOOTH, LINEAR", "FLAT, EXP2", "NONE, EXP"})
    void theCopiedCommandOfALitFoggedFramePrintsTheToolsNumbers(Shading shading, Fog.Mode mode) throws Exception {
        Colour sky = Colour.of(RenderSettings.SKY);
        Fog fog = switch (mode) {
            case LINEAR -> Fog.linear(8, 60, sky);
            case EXP -> Fog.exp(0.03, sky);
            case EXP2 -> Fog.exp2(0.04, sky);
        };
        ViewState state = litDemo(shading, fog);
        ViewState.Measurement m = measure(state);
        assertNull(CliArgs.unreproducible(m));
        List<String> args = CliArgs.compare(AssetScenes.assetOf(state.scene()).orElseThrow(), m);
        assertTrue(args.contains("--fog"), args.toString());
        assertEquals(shading != Shading.NONE, args.contains("--shade"), args.toString());
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        assertEquals(0, Cli.run(new PrintWriter(out, true), new PrintWriter(err, true), args.toArray(String[]::new)),
                err.toString());
        Comparison c = m.comparison();
        String json = out.toString();
        assertEquals(c.psnrDb(), number(json, "psnr_db"), 0.0, json);
        assertEquals(c.texelDifferShare(), number(json, "texel_differ_share"), 0.0);
        assertEquals(c.maxDisplacement(), number(json, "max_displacement"), 0.0);
    }

    @Test
    void aFrameTheCommandLineCannotLightIsSaidSo() throws Exception {
        ViewState state = litDemo(Shading.SMOOTH, null);
        state.scene().add(Light.directional(new Vec3(-1, 1, 0), Colour.grey(0.3)));
        ViewState.Measurement m = measure(state);
        String why = CliArgs.unreproducible(m);
        assertNotEquals(null, why);
        assertTrue(why.contains("one of each"), why);
    }

    /**
     * What the demo adds to a scene (labels, axes, glass: X) is not the command's, which draws the scene's
     * mesh alone: an unlit addition to a lit scene does not make its materials "lit differently", while
     * the scene's own materials lit two ways do.
     */
    @Test
    void onlyTheScenesOwnMaterialsDecideItsShading() throws Exception {
        ViewState state = litDemo(Shading.FLAT, null);
        state.scene().add(new SceneObject(Primitives.box(1, 1, 1), Material.colour(0x3060A0)));
        ViewState.Measurement m = measure(state);
        assertNull(CliArgs.unreproducible(m));
        List<String> args = CliArgs.compare(AssetScenes.assetOf(state.scene()).orElseThrow(), m);
        assertEquals("flat", args.get(args.indexOf("--shade") + 1));

        ViewState mixed = litDemo(Shading.FLAT, null);
        SceneObject own = (SceneObject) mixed.scene().children().get(0);
        List<Material> materials = new java.util.ArrayList<>(own.materials());
        materials.set(0, materials.get(0).withShading(Shading.SMOOTH));
        own.setMaterials(materials);
        String why = CliArgs.unreproducible(measure(mixed));
        assertTrue(why != null && why.contains("lit differently"), why);
    }
}
