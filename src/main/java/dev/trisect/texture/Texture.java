package dev.trisect.texture;

import java.awt.image.BufferedImage;
import java.util.Objects;

/**
 * A texture image: {@code width x height} ARGB texels in an {@code int[]}, row-major with image row 0
 * at the top (as image files store it). UV (0, 0) is the bottom-left texel's corner and (1, 1) the
 * top-right one (OBJ and OpenGL).
 *
 * <p>Sampling is nearest with repeat, exactly as OpenGL's {@code GL_NEAREST} + {@code GL_REPEAT}: in
 * texel coordinates {@code (s, t) = (u * width, v * height)}, the column is
 * {@code floorMod(floor(s), width)}, the row from the bottom {@code floorMod(floor(t), height)}.
 * The rasterizer inlines the same arithmetic; {@link #texelIndex} is the reference for it.
 *
 * <p>Bilinear and trilinear sampling ({@link TextureFilter}) read the levels of {@link #mipChain()},
 * which is built once, on its first use (a texture only ever sampled nearest — a lit copy of one, say —
 * never pays for it), and laid out for the filtered pixel loops on their first use.
 */
public final class Texture {
    /** Largest width or height accepted, in texels. */
    public static final int MAX_SIDE = 16384;

    private final String name;
    private final int width;
    private final int height;
    private final int[] argb;
    /** {@link #mipChain()}, built on first use; null before. */
    private volatile MipChain mipChain;
    /** Held while {@link #mipChain} is built, so that it is built once whatever the threads asking. */
    private final Object mipLock = new Object();
    /** {@link #alpha()}, found on first use; null before. */
    private volatile Alpha alpha;

    /** What a texture's alpha holds, which decides how a surface showing it is written. */
    public enum Alpha {
        /** Every texel's alpha is 255. */
        OPAQUE,
        /** Every texel's alpha is 0 or 255, not all 255: a cut-out, drawn where alpha is at least 0.5. */
        BINARY,
        /** Some texel's alpha is neither 0 nor 255: blended by alpha. */
        PARTIAL
    }

    /**
     * @param name   where the texture came from (a file name or a procedural name), for messages
     * @param width  width in texels, 1..{@link #MAX_SIDE}
     * @param height height in texels, 1..{@link #MAX_SIDE}
     * @param argb   {@code width * height} texels, row 0 at the top; kept, not copied, so it must not change
     *               afterwards: the mipmap levels and the filtered samplers' copy are made from it on
     *               first use, so a later change would show with some filters and frames and not others
     * @throws NullPointerException     when {@code name} or {@code argb} is null
     * @throws IllegalArgumentException for a size outside 1..{@link #MAX_SIDE} or a texel count not
     *                                  {@code width * height}
     */
    public Texture(String name, int width, int height, int[] argb) {
        Objects.requireNonNull(name, "texture name is null");
        if (width < 1 || height < 1 || width > MAX_SIDE || height > MAX_SIDE) {
            throw new IllegalArgumentException(name + ": texture size " + width + "x" + height
                    + " is outside 1.." + MAX_SIDE);
        }
        Objects.requireNonNull(argb, () -> name + ": texels are null");
        if (argb.length != width * height) {
            throw new IllegalArgumentException(name + ": expected " + width * height + " texels, got " + argb.length);
        }
        this.name = name;
        this.width = width;
        this.height = height;
        this.argb = argb;
    }

    /**
     * A texture holding a copy of {@code image}'s pixels, as non-premultiplied ARGB (grey images as
     * stored: see {@link TextureReader}). Image row 0 is the top row, so UV (0, 0) is the image's
     * bottom-left corner, as in OpenGL and OBJ files.
     *
     * @param image any {@code BufferedImage}, 1..{@link #MAX_SIDE} pixels a side
     * @return a texture of the image's pixels, row 0 at the top
     * @throws NullPointerException     when {@code image} is null
     * @throws IllegalArgumentException when it is larger than {@link #MAX_SIDE} a side
     */
    public static Texture of(BufferedImage image) {
        Objects.requireNonNull(image, "image is null");
        String name = "image " + image.getWidth() + "x" + image.getHeight();
        if (image.getWidth() > MAX_SIDE || image.getHeight() > MAX_SIDE) {
            throw new IllegalArgumentException(name + " is larger than " + MAX_SIDE + " pixels a side");
        }
        return new Texture(name, image.getWidth(), image.getHeight(), ImageConversion.toArgb(image));
    }

    /**
     * A texture of one colour, for meshes without one.
     *
     * @param name a name for messages and statistics
     * @param argb the colour, 0xAARRGGBB
     * @return a 1x1 texture of that colour
     * @throws NullPointerException when {@code name} is null
     */
    public static Texture solid(String name, int argb) {
        return new Texture(name, 1, 1, new int[] {argb});
    }

    /**
     * Where the texture came from, for messages.
     *
     * @return the name given at creation (a file name for read textures)
     */
    public String name() {
        return name;
    }

    /**
     * Width in texels.
     *
     * @return width, texels
     */
    public int width() {
        return width;
    }

    /**
     * Height in texels.
     *
     * @return height, texels
     */
    public int height() {
        return height;
    }

    /**
     * The texels, ARGB, row 0 at the top. Handed out without a copy for the rasterizer: read-only.
     *
     * @return the ARGB texels, row-major, row 0 at the top: read-only
     */
    public int[] argb() {
        return argb;
    }

    /**
     * What the texels' alpha holds: all opaque, only 0 or 255, or partial. Found by one look at every
     * texel on the first call, then kept (the texels must not change: see the constructor).
     *
     * @return the texture's kind of alpha
     */
    public Alpha alpha() {
        Alpha a = alpha;
        if (a == null) {
            a = Alpha.OPAQUE;
            for (int texel : argb) {
                int v = texel >>> 24;
                if (v != 255) {
                    if (v != 0) {
                        a = Alpha.PARTIAL;
                        break;
                    }
                    a = Alpha.BINARY;
                }
            }
            alpha = a;
        }
        return a;
    }

    /**
     * The mipmap levels, level 0 being {@link #argb()} itself; built on the first call (by whichever
     * thread makes it), then kept.
     *
     * @return the mipmap levels
     */
    public MipChain mipChain() {
        MipChain m = mipChain;
        if (m == null) {
            synchronized (mipLock) {
                m = mipChain;
                if (m == null) {
                    m = new MipChain(width, height, argb);
                    mipChain = m;
                }
            }
        }
        return m;
    }

    /**
     * Index into {@link #argb()} of the texel that nearest sampling with repeat picks at the given
     * texel coordinates.
     *
     * @param s texel coordinate {@code u * width} (texels; any value, negative included)
     * @param t texel coordinate {@code v * height} (texels, from the bottom)
     * @return the index into {@link #argb()} of the texel sampled
     */
    public int texelIndex(double s, double t) {
        int column = Math.floorMod((int) Math.floor(s), width);
        int rowFromBottom = Math.floorMod((int) Math.floor(t), height);
        return (height - 1 - rowFromBottom) * width + column;
    }

    /**
     * The ARGB texel that nearest sampling with repeat picks at UV (u, v).
     *
     * @param u texture coordinate, any value (repeats)
     * @param v texture coordinate, from the bottom, any value (repeats)
     * @return the ARGB texel
     */
    public int sampleUv(double u, double v) {
        return argb[texelIndex(u * width, v * height)];
    }
}
