package dev.trisect.raster;

import dev.trisect.render.Framebuffer;
import dev.trisect.texture.Texture;

/**
 * Draws one band's commands of a {@link Commands} list, in the list's order, each by the loop of its
 * kind ({@code lp_rast}'s dispatch of a bin's commands): a {@link Commands#TRIANGLE TRIANGLE} by the
 * {@link Rasterizer}'s loop of the frame's path and filter, a {@link Commands#TREE TREE} by its
 * one-pass fill, a {@link Commands#LINE LINE} by {@link LineRaster}, a {@link Commands#QUAD QUAD} by
 * {@link QuadRaster#rows}. The kind is read once per
 * command; every loop below is the same whatever the list holds.
 *
 * <p>One instance per thread: its rasterizer holds the triangle being filled.
 */
public final class BandFill {
    private final Rasterizer rasterizer = new Rasterizer();
    /** The frame pixel index whose last writer {@link #fill} notes, or -1. */
    private int probe = -1;
    /** The index (in its list) of the last command that wrote {@link #probe}, or -1. */
    private int probeWriter = -1;

    /** The rasterizer of this thread's triangles: set its filter and span error before filling. */
    public Rasterizer rasterizer() {
        return rasterizer;
    }

    /**
     * Draws band {@code band}'s commands of {@code list} into the pixels {@code [x0, x1) x [y0, y1)},
     * which must hold that band's rows lighting.
     *
     * @param textures    texture of each material index
     * @param perspective whether screen triangles divide per pixel (or per knot), as
     *                    {@link Rasterizer#fill}'s
     * @return the number of pixels written (depth test passed; blended quads count too)
     */
    public long fill(Framebuffer frame, Commands list, int band, Texture[] textures, boolean perspective,
                     int x0, int y0, int x1, int y1) {
        if (probe >= 0) {
            return fillProbed(frame, list, band, textures, perspective, x0, y0, x1, y1);
        }
        int[] items = list.bins().items();
        long written = 0;
        for (int k = list.bins().start(band), end = list.bins().start(band + 1); k < end; k++) {
            written += draw(list.command(items[k]), frame, list, textures, perspective, x0, y0, x1, y1);
        }
        return written;
    }

    /** {@link #fill} noting which command writes the probed pixel last. */
    private long fillProbed(Framebuffer frame, Commands list, int band, Texture[] textures, boolean perspective,
                            int x0, int y0, int x1, int y1) {
        int[] items = list.bins().items();
        long written = 0;
        int[] colour = frame.colour();
        for (int k = list.bins().start(band), end = list.bins().start(band + 1); k < end; k++) {
            // The probed pixel's alpha is cleared before each command: every write sets it to 255 (and none
            // reads it), so a command wrote the pixel exactly when the alpha is back; else it is restored.
            int saved = colour[probe];
            colour[probe] = saved & 0xFFFFFF;
            written += draw(list.command(items[k]), frame, list, textures, perspective, x0, y0, x1, y1);
            if (colour[probe] >>> 24 != 0) {
                probeWriter = items[k];
            } else {
                colour[probe] = saved;
            }
        }
        return written;
    }

    /** Draws {@code command} of {@code list} by the loop of its kind; returns the pixels written. */
    private long draw(int command, Framebuffer frame, Commands list, Texture[] textures, boolean perspective,
                      int x0, int y0, int x1, int y1) {
        int ref = Commands.ref(command);
        return switch (Commands.kind(command)) {
            case Commands.TRIANGLE -> rasterizer.fillOne(frame, list.triangles(), ref, textures, perspective,
                    x0, y0, x1, y1);
            case Commands.TREE -> rasterizer.fillTree(frame, list.trees(), ref, textures, x0, y0, x1, y1);
            case Commands.LINE -> LineRaster.rows(list.segments(), ref, frame.colour(), frame.depth(), y0, y1);
            default -> list.quads().rows(ref, frame.colour(), frame.depth(), y0, y1);
        };
    }

    /**
     * Notes which command of the next {@link #fill} calls writes frame pixel {@code pixel} last (for the
     * pixel inspector: a line or a label over a triangle), or stops noting with -1. Costs one test per
     * band while nothing is noted (a noting band runs its commands through a loop of its own), none per
     * pixel.
     *
     * @param pixel index of the pixel in the frame ({@code y * width + x}), within the rows filled, or -1
     */
    public void probe(int pixel) {
        probe = pixel;
        probeWriter = -1;
    }

    /**
     * The command that wrote the probed pixel last in the {@link #fill} calls since {@link #probe}.
     *
     * @return its index in its list ({@link Commands#command}), or -1 when none wrote it
     */
    public int probeWriter() {
        return probeWriter;
    }

    /**
     * Adds 1 to {@code counts[y * width + x]} for every pixel of {@code [x0, x1) x [y0, y1)} that band
     * {@code band}'s triangle commands of {@code list} fill, ignoring depth (see
     * {@link Rasterizer#countCoverage}; a tree counts the pixels its pieces cover); lines are not
     * counted.
     *
     * @return the number of coverings counted
     */
    public long count(int[] counts, int width, Commands list, int band, int x0, int y0, int x1, int y1) {
        int[] items = list.bins().items();
        long covered = 0;
        for (int k = list.bins().start(band), end = list.bins().start(band + 1); k < end; k++) {
            int command = list.command(items[k]);
            int ref = Commands.ref(command);
            switch (Commands.kind(command)) {
                case Commands.TRIANGLE -> covered += rasterizer.countOne(counts, width, list.triangles(), ref, x0, y0,
                        x1, y1);
                case Commands.TREE -> covered += rasterizer.countTree(counts, width, list.trees(), ref, x0, y0, x1,
                        y1);
                default -> {
                }
            }
        }
        return covered;
    }
}
