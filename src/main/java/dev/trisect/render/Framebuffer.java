package dev.trisect.render;

import java.awt.image.BufferedImage;

/**
 * The frame being drawn: ARGB colour, a depth buffer and, when asked for, the UV output and the
 * triangle ids.
 *
 * <p>All arrays are row-major, row 0 at the top, pixel (x, y) at index {@code y * width + x}.
 * Depth holds {@code 1/w} (w the view depth), which is linear in screen space and larger for nearer
 * surfaces; it is cleared to 0 (infinitely far), and a fragment passes when its {@code 1/w} is
 * strictly larger — the same order as OpenGL's {@code GL_LESS} on window z. The UV output holds three
 * doubles a pixel: texel coordinates s = u * width and t = v * height before wrapping, and the input
 * triangle's index + 1 (0 where nothing was drawn). Doubles, not the floats of the UV file, because
 * the exact displacement maps them back to the screen: where one texel covers hundreds of pixels and
 * s is in the thousands, a float's rounding of s alone moves the point by tenths of a pixel. The file
 * ({@code render --uv-out}) still stores floats, rounded when written. The ids ({@link #ids()}) are
 * the UV output's third channel alone, as ints: 4 bytes a pixel instead of 24, for a program that
 * only asks which triangle each pixel shows.
 */
public final class Framebuffer {
    private final int width;
    private final int height;
    private final int[] colour;
    private final float[] depth;
    private double[] uv;
    private int[] ids;
    /** Whether {@link #recordIds} asked for the ids (the UV output brings them too). */
    private boolean idsWanted;
    /** Calls of {@link #clearRows} so far: see {@link #clearCount()}. */
    private final java.util.concurrent.atomic.AtomicLong clears = new java.util.concurrent.atomic.AtomicLong();

    /**
     * @param width  pixels, &gt;= 1
     * @param height pixels, &gt;= 1
     */
    public Framebuffer(int width, int height) {
        if (width < 1 || height < 1 || (long) width * height > Integer.MAX_VALUE / 3) {
            throw new IllegalArgumentException("frame size " + width + "x" + height + " is not usable");
        }
        this.width = width;
        this.height = height;
        this.colour = new int[width * height];
        this.depth = new float[width * height];
    }

    /**
     * Width in pixels.
     *
     * @return the width, pixels
     */
    public int width() {
        return width;
    }

    /**
     * Height in pixels.
     *
     * @return the height, pixels
     */
    public int height() {
        return height;
    }

    /**
     * ARGB pixels, row 0 at the top; wrap it in a {@code DataBufferInt} to show it without copying.
     *
     * @return the colour buffer, {@code width * height} ARGB values, live (not a copy)
     */
    public int[] colour() {
        return colour;
    }

    /**
     * Depth as 1/w per pixel (view-space units^-1), 0 = nothing drawn.
     *
     * @return the depth buffer, {@code width * height} values of 1/w, live
     */
    public float[] depth() {
        return depth;
    }

    /**
     * The UV output (3 doubles a pixel: s, t in texels, id), or null when it is not being recorded.
     *
     * @return the UV output, {@code 3 * width * height} values, live; or null
     */
    public double[] uv() {
        return uv;
    }

    /**
     * Starts or stops recording the UV output; the buffer is kept once made.
     *
     * @param on true to record from the next frame on, false to stop
     */
    public void recordUv(boolean on) {
        if (on && uv == null) {
            uv = new double[3 * width * height];
        } else if (!on) {
            uv = null;
        }
        keepIds();
    }

    /**
     * The triangle ids: per pixel the index + 1 of the triangle drawn there (the frame triangle, as
     * the UV output's third channel), 0 where nothing was drawn; recorded while {@link #recordIds}
     * or {@link #recordUv} is on. A blended fragment writes none (the id stays the surface's behind).
     *
     * @return the ids, {@code width * height} values, live; or null when not recorded
     */
    public int[] ids() {
        return ids;
    }

    /**
     * Starts or stops recording the triangle ids alone ({@link #ids()}); the UV output records them
     * too while it is on. The buffer is kept once made.
     *
     * @param on true to record from the next frame on, false to stop (unless the UV output is on)
     */
    public void recordIds(boolean on) {
        idsWanted = on;
        keepIds();
    }

    /** The ids buffer made or dropped as the UV output and {@link #recordIds} ask. */
    private void keepIds() {
        if ((idsWanted || uv != null) && ids == null) {
            ids = new int[width * height];
        } else if (!idsWanted && uv == null) {
            ids = null;
        }
    }

    /**
     * Clears rows {@code [y0, y1)} of every buffer: colour to {@code background} (opaque), depth to
     * 0, UV output and ids to 0.
     *
     * @param y0         first row cleared, 0 at the top
     * @param y1         the row after the last one cleared
     * @param background colour, 0xRRGGBB
     */
    public void clearRows(int y0, int y1, int background) {
        clears.incrementAndGet();
        int from = y0 * width;
        int to = y1 * width;
        java.util.Arrays.fill(colour, from, to, background | 0xFF000000);
        java.util.Arrays.fill(depth, from, to, 0f);
        if (uv != null) {
            java.util.Arrays.fill(uv, 3 * from, 3 * to, 0.0);
        }
        if (ids != null) {
            java.util.Arrays.fill(ids, from, to, 0);
        }
    }

    /**
     * How many times rows of this framebuffer have been cleared ({@link #clearRows}). Drawing a frame
     * clears the framebuffer first, so code that keeps a reference to one can tell from a changed
     * count that something has been drawn into it since (as {@code SceneRenderer.pick} does before
     * reading a frame's UV output). Writes into the arrays themselves are not counted, and a count
     * read while another thread draws into the framebuffer may already include that drawing.
     *
     * @return the count, from 0
     */
    public long clearCount() {
        return clears.get();
    }

    /**
     * A copy of the colour buffer as an image ({@code TYPE_INT_RGB}), for {@code ImageIO.write} or
     * drawing; later frames drawn into this framebuffer do not change it.
     *
     * @return the copy
     */
    public BufferedImage toImage() {
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        image.setRGB(0, 0, width, height, colour, 0, width);
        return image;
    }

    /**
     * Reads rows {@code [y0, y1)} of the colour and depth buffers in order, one value per cache
     * line, to bring them into the cache before scattered access (the hardware fetches ahead on such
     * a walk, and not on a scattered one).
     *
     * @param y0 first row read, 0 at the top
     * @param y1 the row after the last one read
     * @return a sum of what was read, for the caller to keep (so that the reads are not optimised away)
     */
    public int touchRows(int y0, int y1) {
        int sum = 0;
        // 16 four-byte values to a 64-byte line.
        for (int i = y0 * width, end = y1 * width; i < end; i += 16) {
            sum += colour[i] + Float.floatToRawIntBits(depth[i]);
        }
        return sum;
    }
}
