package dev.trisect.devtools;

import dev.trisect.content.SceneLighting;
import dev.trisect.render.Colour;
import dev.trisect.render.Fog;
import dev.trisect.render.Shading;
import dev.trisect.scene.Light;
import dev.trisect.scene.Scene;
import dev.trisect.view.internal.FrameSlot;
import dev.trisect.view.internal.ViewController;
import dev.trisect.view.internal.ViewSettings;
import dev.trisect.view.internal.ViewState;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import javax.swing.JCheckBox;
import javax.swing.JComboBox;
import javax.swing.JComponent;

/**
 * Developer tools: how the scene is lit and fogged (docs/conventions.md, "Light" and "Fog"). Shows the
 * shading of its materials and its lights, and changes them: one shading for every material, every
 * light on or off, and OpenGL's fog (linear from a start to an end depth, or exp and exp2 by a
 * density) towards the background's colour. The controls act on the scene itself, so they show what
 * the demo's keys set too.
 */
final class LightSection implements ToolSection {
    /** The fog choices, in the combo's order. */
    static final String[] FOGS = {"off", "linear", "exp", "exp2"};

    /** The shadings, in the combo's order: {@link Shading#values()}, in the demo's words. */
    static final String[] SHADINGS = Arrays.stream(Shading.values()).map(SceneLighting::word)
            .toArray(String[]::new);
    /**
     * Said under the lights when a lit shading has nothing to light it (every lit surface draws black:
     * the ambient colour is the sum of the shining lights, docs/conventions.md "Light").
     */
    static final String UNLIT = "No light shines, so flat and smooth shading draw every lit surface black: "
            + "tick Lights on (in the demo, press L for its lights).";
    /** As {@link #UNLIT}, for a scene without a light, hidden or not. */
    static final String NO_LIGHT = "The scene has no light, so flat and smooth shading draw every lit surface "
            + "black (in the demo, press L for its lights).";

    private final ToolsForm form = new ToolsForm("Light and fog");
    private final ViewController owner;
    private final JComboBox<String> shading = new JComboBox<>(SHADINGS);
    private final JCheckBox lightsOn = new JCheckBox("Lights on");
    private final JComboBox<String> fog = new JComboBox<>(FOGS);
    /** The fog's values in force: start and end depths, density. */
    private final double[] values = {5, 60, 0.05};
    /** The fields of {@link #values}, in its order. */
    private final NumberField[] fields = new NumberField[3];
    private int background;
    private boolean syncing;

    LightSection(ViewController owner) {
        this.owner = owner;
        shading.setToolTipText("How every material is lit: off (the texture as it is), flat (one colour per "
                + "triangle, its last corner's, as GL_FLAT) or smooth (corner colours interpolated)");
        shading.addActionListener(e -> {
            if (!syncing) {
                Scene s = scene();
                SceneLighting.setShading(s, Shading.values()[shading.getSelectedIndex()]);
                warn(s);
            }
        });
        form.row(ToolsForm.label("Shading", shading.getToolTipText()), shading);
        form.note("Lights", "The scene's visible lights: the ambient colour they sum to, and each directional "
                + "and point light's colour");
        lightsOn.setToolTipText("Show or hide every light of the scene (a hidden light does not shine)");
        lightsOn.addActionListener(e -> {
            boolean on = lightsOn.isSelected();
            Scene s = scene();
            s.update(() -> lights(s).forEach(l -> l.setVisible(on)));
            warn(s);
        });
        form.row(lightsOn);
        fog.setToolTipText("OpenGL's fog by eye-space depth towards the background's colour: linear from Start "
                + "to End, exp or exp2 by Density");
        fog.addActionListener(e -> applyFog());
        form.row(ToolsForm.label("Fog", fog.getToolTipText()), fog);
        field("Fog start", 0, 2);
        field("Fog end", 1, 2);
        // Four decimals: densities of large scenes are thousandths (0.002 read "0.00" with two).
        field("Fog density", 2, 4);
        form.row(ToolsForm.label("Fog start", "Linear fog: the depth where it begins, world units"), fields[0]);
        form.row(ToolsForm.label("Fog end", "Linear fog: the depth where only the fog shows, world units"), fields[1]);
        form.row(ToolsForm.label("Fog density", "Exp and exp2 fog: the density, per world unit"), fields[2]);
        // Folded until asked for: the tools keep fitting the screen with the sections used most open.
        form.setOpen(false);
    }

    /**
     * The field of {@code values[index]}: it takes any number the fog takes (Fog.linear: a start below 0
     * too) and applies the fog again. One the fog refuses (a linear start at or beyond its end, a density
     * below 0, a number beyond the double range) is not kept, whichever fog is on, and the fog's own
     * message says why: the field goes on showing the value in force.
     */
    private void field(String name, int index, int decimals) {
        fields[index] = new NumberField(name, "", Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY, v -> {
            double before = values[index];
            values[index] = v;
            try {
                fog(index < 2 ? "linear" : "exp");
                applyFog();
            } catch (IllegalArgumentException e) {
                owner.message("Fog: " + e.getMessage());
                values[index] = before;
            }
            fields[index].show(values[index]);
        }, owner::message).decimals(decimals);
        fields[index].show(values[index]);
    }

    /** The shading combo's choice, for tests. */
    String readoutShading() {
        return (String) shading.getSelectedItem();
    }

    /** The shading combo, for tests. */
    JComboBox<String> shadingCombo() {
        return shading;
    }

    /** The Lights on box, for tests. */
    JCheckBox lightsOnBox() {
        return lightsOn;
    }

    /** The fog combo's choice, for tests. */
    String readoutFog() {
        return (String) fog.getSelectedItem();
    }

    /** The start, end and density fields, for tests. */
    NumberField[] fogFields() {
        return fields.clone();
    }

    private Scene scene() {
        return owner.state().scene();
    }

    /** Every light node of {@code scene}, hidden ones too. */
    static List<Light> lights(Scene scene) {
        return SceneLighting.lights(scene);
    }

    /** Sets the scene's fog from the controls (whose values the fog takes: the fields keep no other). */
    private void applyFog() {
        if (!syncing) {
            scene().setFog(fog((String) fog.getSelectedItem()));
        }
    }

    /**
     * The fog of {@code kind} ({@link #FOGS}) with the values in force, or null for "off".
     *
     * @throws IllegalArgumentException with the fog's message when it refuses them
     */
    private Fog fog(String kind) {
        Colour c = Colour.of(background);
        return switch (kind) {
            case "linear" -> Fog.linear(values[0], values[1], c);
            case "exp" -> Fog.exp(values[2], c);
            case "exp2" -> Fog.exp2(values[2], c);
            default -> null;
        };
    }

    @Override
    public void sync(ViewSettings settings) {
        background = settings.render().background();
    }

    @Override
    public void refresh(ViewState.Progress progress, FrameSlot front, ViewState.Measurement measurement) {
        Scene s = scene();
        syncing = true;
        try {
            shading.setSelectedIndex(SceneLighting.shading(s).ordinal());
            List<Light> all = lights(s);
            lightsOn.setEnabled(!all.isEmpty());
            lightsOn.setSelected(all.stream().anyMatch(Light::isVisible));
            fog.setSelectedItem(s.fog().map(f -> f.mode().name().toLowerCase(Locale.ROOT)).orElse("off"));
            s.fog().ifPresent(this::showFog);
        } finally {
            syncing = false;
        }
        String warning = warning(s);
        form.set("Lights", warning.isEmpty() ? describe(s) : describe(s) + ". " + warning);
    }

    /** Says {@link #warning} in the status line, where the user looks after a change, if there is one. */
    private void warn(Scene s) {
        String warning = warning(s);
        if (!warning.isEmpty()) {
            owner.message(warning);
        }
    }

    /**
     * Why {@code scene} draws black, or "": its materials are lit (flat or smooth) while no light shines
     * ({@link #UNLIT}, or {@link #NO_LIGHT} without any light to show).
     */
    static String warning(Scene scene) {
        if (SceneLighting.shading(scene) == Shading.NONE || !scene.capture().lights().isEmpty()) {
            return "";
        }
        return lights(scene).isEmpty() ? NO_LIGHT : UNLIT;
    }

    /**
     * Shows the values of {@code f}, the scene's fog, which the demo's G key or the program may have set:
     * the fields read what is drawn. A field being typed into is left alone.
     */
    private void showFog(Fog f) {
        if (f.mode() == Fog.Mode.LINEAR) {
            show(0, f.start());
            show(1, f.end());
        } else {
            show(2, f.density());
        }
    }

    private void show(int index, double value) {
        values[index] = value;
        if (!fields[index].isFocusOwner()) {
            fields[index].show(value);
        }
    }

    /** The scene's shining lights in a line or two: "ambient 0.20 0.20 0.20; directional 1 1 1; point ...". */
    static String describe(Scene scene) {
        double[] ambient = new double[3];
        StringBuilder sources = new StringBuilder();
        for (Scene.PlacedLight l : scene.capture().lights()) {
            Colour c = l.colour();
            switch (l.kind()) {
                case AMBIENT -> {
                    ambient[0] += c.r();
                    ambient[1] += c.g();
                    ambient[2] += c.b();
                }
                case DIRECTIONAL -> sources.append("; directional ").append(rgb(c.r(), c.g(), c.b()));
                case POINT -> sources.append("; point ").append(rgb(c.r(), c.g(), c.b()));
            }
        }
        return "ambient " + rgb(ambient[0], ambient[1], ambient[2]) + sources;
    }

    private static String rgb(double r, double g, double b) {
        return String.format(Locale.ROOT, "%.2f %.2f %.2f", r, g, b);
    }

    @Override
    public JComponent component() {
        return form.panel();
    }

    @Override
    public String readout(String name) {
        return form.get(name);
    }
}
