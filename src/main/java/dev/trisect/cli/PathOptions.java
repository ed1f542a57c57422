package dev.trisect.cli;

import dev.trisect.base.InputException;
import dev.trisect.render.BorderStyle;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.SplitPoint;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import dev.trisect.texture.TextureFilter;
import picocli.CommandLine.Option;

/** Which texturing path and how it splits. Shared by the commands. */
final class PathOptions {
    @Option(names = "--mode", paramLabel = "perspective|affine|tessellated|spans",
            converter = Converters.ModeConverter.class, defaultValue = "tessellated",
            description = "Texturing path: per-pixel perspective, affine, tessellated pieces filled affinely, or spans "
                    + "(exact knots along each row, affine between them, spaced for --max-error) "
                    + "(default: ${DEFAULT-VALUE}).")
    RenderMode mode;

    @Option(names = "--split", paramLabel = "edge|error", converter = Converters.SplitConverter.class,
            defaultValue = "edge",
            description = "Tessellated split policy: longest screen edge, or worst affine error (default: edge).")
    SplitPolicy split;

    @Option(names = "--max-edge", paramLabel = "PX", converter = Converters.PositiveConverter.class,
            defaultValue = "32", description = "Edge policy: longest piece edge on screen, pixels (default: ${DEFAULT-VALUE}).")
    double maxEdge;

    @Option(names = "--max-error", paramLabel = "PX", converter = Converters.PositiveConverter.class,
            defaultValue = "0.5",
            description = "Error policy's threshold, and the span path's knot spacing (both set to this): largest "
                    + "affine displacement allowed, pixels (default: ${DEFAULT-VALUE}).")
    double maxError;

    @Option(names = "--split-point", paramLabel = "screen|geometric|midpoint", converter = Converters.SplitPointConverter.class,
            defaultValue = "screen",
            description = "Where an edge is cut: the point that projects to its screen midpoint (halves its screen "
                    + "length, so the bound falls at every level), the point at the geometric mean of its ends' "
                    + "depths, or its 3D midpoint (default: ${DEFAULT-VALUE}).")
    SplitPoint splitPoint;

    @Option(names = "--max-depth", paramLabel = "N", defaultValue = "16",
            description = "Times an edge may be halved, 0..30 (default: ${DEFAULT-VALUE}).")
    int maxDepth;

    @Option(names = "--max-pieces", paramLabel = "N", defaultValue = "65536",
            description = "Most pieces one triangle may become, at least 1 (default: ${DEFAULT-VALUE}).")
    int maxPieces;

    @Option(names = "--max-frame-pieces", paramLabel = "N|auto", converter = Converters.FramePiecesConverter.class,
            defaultValue = "auto",
            description = "Most pieces a whole frame may have, at least 1; a frame that would have more gets a "
                    + "lower depth cap and fills the pieces it stops short per pixel (default: auto, one piece per "
                    + "triangle plus one per " + TessellationSettings.PIXELS_PER_PIECE + " pixels of the frame).")
    int maxFramePieces;

    @Option(names = "--filter", paramLabel = "nearest|bilinear|trilinear",
            converter = Converters.FilterConverter.class, defaultValue = "nearest",
            description = "Texture filter in every path, as OpenGL's GL_NEAREST, GL_LINEAR or GL_LINEAR_MIPMAP_LINEAR "
                    + "with GL_REPEAT (default: ${DEFAULT-VALUE}).")
    TextureFilter filter;

    @Option(names = "--borders", description = "Draw the outline of every piece filled (default: off).")
    boolean borders;

    @Option(names = "--border-colour", paramLabel = "yellow|depth|bound",
            description = "Outline colour with --borders: yellow; by split depth (cyan unsplit to red at --max-depth); "
                    + "or by the piece's error bound over --max-error (green, yellow at it, red above). Fallback "
                    + "pieces are magenta in each (default: yellow).")
    String borderColour;

    @Option(names = "--border-fade", description = "With --borders: outline small pieces translucent, by the radius "
            + "of their inscribed circle, so that the texture still shows where pieces crowd near the horizon "
            + "(default: off).")
    boolean borderFade;

    /** The outline style, checked. */
    BorderStyle borderStyle() {
        // An outline option without the outlines would change nothing: say so rather than ignore it.
        if (!borders && (borderColour != null || borderFade)) {
            throw InputException.usage((borderColour != null ? "--border-colour" : "--border-fade")
                    + " needs --borders");
        }
        String colour = borderColour == null ? "yellow" : borderColour;
        for (BorderStyle.Colouring c : BorderStyle.Colouring.values()) {
            // Case ignored, as for every named value (--mode, --filter, --split).
            if (c.id().equalsIgnoreCase(colour)) {
                return new BorderStyle(c, borderFade);
            }
        }
        throw InputException.usage("--border-colour must be yellow, depth or bound, got '" + borderColour + "'");
    }

    /** The split settings, checked. */
    TessellationSettings tessellation() {
        if (maxDepth < 0 || maxDepth > 30) {
            throw InputException.usage("--max-depth must be between 0 and 30, got " + maxDepth);
        }
        if (maxPieces < 1) {
            throw InputException.usage("--max-pieces must be at least 1, got " + maxPieces);
        }
        return new TessellationSettings(split, maxEdge, maxError, maxDepth, maxPieces, splitPoint, maxFramePieces);
    }

    /** Render settings for this path with the frame's culling and background. */
    RenderSettings settings(FrameOptions frame) {
        return new RenderSettings(mode, tessellation(), frame.cull, frame.background(), borders, filter,
                borderStyle(), maxError);
    }
}
