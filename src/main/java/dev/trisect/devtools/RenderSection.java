package dev.trisect.devtools;

import dev.trisect.content.AssetScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.view.internal.ViewController;
import dev.trisect.view.internal.ViewSettings;
import dev.trisect.view.internal.ViewState;

import java.awt.Toolkit;
import java.awt.datatransfer.StringSelection;
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JSlider;

/** Developer tools: render scale, and the command line that reproduces the measured frame. */
final class RenderSection implements ToolSection {
    private final ToolsForm form = new ToolsForm("Render");
    private boolean syncing;
    private final JSlider renderScale = new JSlider(25, 100, 100);
    private final NumberField renderScaleValue;

    RenderSection(ViewController owner) {
        renderScaleValue = new NumberField("Render scale", "%", 25, 100,
                v -> owner.update(s -> s.withRenderScale(Math.round(v) / 100.0)), owner::message).decimals(0);
        renderScale.setToolTipText("Render at this share of the view's device pixels and scale up (faster when lower)");
        ToolsForm.listen(renderScale, () -> syncing, this::showValue,
                v -> owner.update(s -> s.withRenderScale(v / 100.0)));
        form.row(ToolsForm.label("Render scale", renderScale.getToolTipText()), renderScaleValue);
        form.row(renderScale);
        JButton copy = new JButton("Copy compare command");
        copy.setToolTipText("Copy the command line that measures the last compared frame with trisect compare");
        copy.addActionListener(e -> {
            ViewState.Measurement m = owner.state().measurement();
            if (m == null) {
                owner.message("Nothing measured yet: tick \"Measure against the per-pixel path\" first.");
                return;
            }
            SceneAsset asset = AssetScenes.assetOf(owner.state().scene()).orElse(null);
            if (asset == null) {
                owner.message("The command line draws built-in scenes and OBJ files; this scene was made by the "
                        + "program, so there is no command that reproduces it.");
                return;
            }
            String why = CliArgs.unreproducible(m);
            if (why != null) {
                owner.message("No command line draws the measured frame's light: " + why + ".");
                return;
            }
            String cmd = CliArgs.compareCommand(asset, m);
            Toolkit.getDefaultToolkit().getSystemClipboard().setContents(new StringSelection(cmd), null);
            owner.message("Copied the compare command of the measured frame; run it from the repository root "
                    + "after mvn -q package -DskipTests.");
        });
        form.row(copy);
    }

    @Override
    public JComponent component() {
        return form.panel();
    }

    @Override
    public void sync(ViewSettings s) {
        syncing = true;
        try {
            renderScale.setValue((int) Math.round(s.renderScale() * 100));
            renderScaleValue.show(Math.round(s.renderScale() * 100));
        } finally {
            syncing = false;
        }
    }

    private void showValue() {
        if (!syncing) {
            renderScaleValue.show(renderScale.getValue());
        }
    }
}
