package dev.trisect.devtools;

import dev.trisect.render.FrameStats;
import dev.trisect.view.internal.FrameSlot;
import dev.trisect.view.internal.ViewController;
import dev.trisect.view.internal.ViewState;
import java.util.Locale;
import javax.swing.JComponent;

/** Developer tools: frame rate, frame size and the engine's statistics of the frame on screen. */
final class StatisticsSection implements ToolSection {
    private final ViewController owner;
    private final ToolsForm form = new ToolsForm("Statistics");

    StatisticsSection(ViewController owner) {
        this.owner = owner;
        form.readouts(new String[][] {
            {"Frames per second", "Frames shown per second, over the last second"},
            {"Frame size", "Pixels rendered per frame (view size in device pixels times render scale)"},
            {"Render threads", "Threads that fill each frame"},
            {"ms transform", "Milliseconds per frame transforming vertices to clip space"},
            {"ms clip", "Milliseconds culling and clipping triangles"},
            {"ms tessellate", "Milliseconds splitting triangles into pieces and projecting them; a dash in the paths "
                    + "that split nothing, with the time they spend projecting"},
            {"ms raster", "Milliseconds clearing and filling the frame"},
            {"ms overlay", "Milliseconds drawing polygon borders, measured: they are drawn after the frame is filled"},
            {"ms total", "Milliseconds for the whole frame in the engine"},
            {"Triangles in", "Triangles in the scene"},
            {"Culled", "Triangles dropped as facing away, off screen, or without area"},
            {"Pieces filled", "Triangles filled: tessellated pieces, or clipped triangles in the other paths"},
            {"Splits", "Edge cuts made this frame"},
            {"Deepest split", "The most times an edge was halved this frame"},
            {"Caps reached", "Triangles whose splitting a depth or piece cap stopped short"},
            {"Fallback pieces", "Pieces filled per pixel instead of affinely (magenta outlines): those a cap "
                    + "stopped short of the split policy, and slivers thinner than 1/16 pixel"},
            {"Piece budget", "Most pieces this frame may have (one per triangle plus one per 16 pixels); when "
                    + "reached, the frame's depth cap is lowered and the pieces it stops are filled per pixel"},
            {"Pixels written", "Pixels that passed the depth test"}});
    }

    @Override
    public JComponent component() {
        return form.panel();
    }

    @Override
    public void refresh(ViewState.Progress progress, FrameSlot front, ViewState.Measurement m) {
        form.set("Frames per second", String.format(Locale.ROOT, "%.1f", progress.fps()));
        form.set("Render threads", Integer.toString(owner.threads()));
        if (front == null || front.stats == null) {
            return;
        }
        FrameStats st = front.stats;
        form.set("Frame size", front.width() + "x" + front.height());
        form.set("ms transform", ms(st.transformNanos()));
        form.set("ms clip", ms(st.clipNanos()));
        // A path that splits nothing only projects its triangles there: no tessellate time to show.
        form.set("ms tessellate", front.drawnRender != null && !front.drawnRender.mode().splits()
                ? "- (projecting " + ms(st.tessellateNanos()) + ")" : ms(st.tessellateNanos()));
        form.set("ms raster", ms(st.rasterNanos()));
        form.set("ms overlay", ms(st.overlayNanos() + front.overlayNanos));
        form.set("ms total", ms(st.totalNanos() + front.overlayNanos));
        form.set("Triangles in", Long.toString(st.trianglesIn()));
        form.set("Culled", Long.toString(st.culled()));
        form.set("Pieces filled", Long.toString(st.pieces()));
        form.set("Splits", Long.toString(st.splits()));
        form.set("Deepest split", Integer.toString(st.deepestSplit()));
        form.set("Caps reached", Long.toString(st.capsReached()));
        form.set("Fallback pieces", Long.toString(st.piecesFallback()));
        form.set("Piece budget", st.budgetReached()
                ? st.pieceBudget() + ", reached: depth cap " + st.budgetDepth()
                : st.pieceBudget() == 0 ? "-" : Long.toString(st.pieceBudget()));
        form.set("Pixels written", Long.toString(st.pixelsWritten()));
    }

    @Override
    public String readout(String name) {
        return form.get(name);
    }

    private static String ms(long nanos) {
        return String.format(Locale.ROOT, "%.2f", nanos / 1e6);
    }
}
