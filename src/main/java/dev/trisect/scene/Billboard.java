package dev.trisect.scene;

import dev.trisect.math.Vec3;
import dev.trisect.texture.Texture;
import java.util.Objects;

/**
 * A texture that always faces the camera: a rectangle parallel to the image plane, centred on a point
 * of its object (moved by the object's transform and its groups), sized in world units or in pixels
 * (markers, sprites, icons). Immutable; give an object its billboards with
 * {@link SceneObject#setBillboards}.
 *
 * <pre>{@code
 * SceneObject markers = SceneObject.billboards(List.of(
 *         Billboard.world(flag, new Vec3(0, 2, 0), 0.5, 0.5),       // 0.5 m square, shrinks with distance
 *         Billboard.pixels(pin, new Vec3(3, 0, 1), 24, 24).onTop())); // 24 px always, over everything
 * }</pre>
 *
 * <p>Its texture's alpha decides how it is drawn: a texture whose alphas are all 0 or 255 is
 * alpha-tested (drawn where alpha is at least 0.5, writing depth, as {@code GL_ALPHA_TEST}), one with
 * any other alpha is blended over what is behind it ({@code src·a + dst·(1 − a)}, no depth write).
 * It is depth-tested against the scene at its centre's depth (the whole rectangle lies at that depth),
 * unless {@link #onTop()}. Sampling is nearest, the texture's left and right edges on the rectangle's.
 * With the scene's fog ({@link Scene#setFog}), its colour is blended towards the fog by its centre's eye
 * depth before the alpha test and blend, as OpenGL fogs every fragment (on top or not); unlike
 * {@link Label}s and {@link ScreenText}, which are not fogged.
 * Billboards are drawn after the scene's triangles and lines, farthest first (see docs/conventions.md,
 * "Billboards and text").
 */
public final class Billboard {
    private final Texture texture;
    private final Vec3 at;
    private final double width;
    private final double height;
    private final boolean pixels;
    private final boolean onTop;
    private final boolean blended;

    private Billboard(Texture texture, Vec3 at, double width, double height, boolean pixels, boolean onTop,
                      boolean blended) {
        this.texture = texture;
        this.at = at;
        this.width = width;
        this.height = height;
        this.pixels = pixels;
        this.onTop = onTop;
        this.blended = blended;
    }

    /**
     * A billboard sized in world units: it looks as large as a square of that size facing the camera
     * at its centre would.
     *
     * @param texture the texture
     * @param at      its centre, in its object's space
     * @param width   world units across
     * @param height  world units down
     * @return the billboard
     * @throws NullPointerException     when {@code texture} or {@code at} is null
     * @throws IllegalArgumentException when a size is not positive and finite, or {@code at} is not finite
     */
    public static Billboard world(Texture texture, Vec3 at, double width, double height) {
        return of(texture, at, width, height, false);
    }

    /**
     * A billboard of a fixed size on screen, whatever its distance: pixels of a picture, or a view's
     * logical pixels (on a high-density screen, its scale times as many device pixels).
     *
     * @param texture the texture
     * @param at      its centre, in its object's space
     * @param width   pixels across
     * @param height  pixels down
     * @return the billboard
     * @throws NullPointerException     when {@code texture} or {@code at} is null
     * @throws IllegalArgumentException when a size is below 1, or {@code at} is not finite
     */
    public static Billboard pixels(Texture texture, Vec3 at, int width, int height) {
        if (width < 1 || height < 1) {
            throw new IllegalArgumentException("billboard size must be at least 1x1 pixels, got " + width + "x"
                    + height);
        }
        return of(texture, at, width, height, true);
    }

    private static Billboard of(Texture texture, Vec3 at, double width, double height, boolean pixels) {
        Objects.requireNonNull(texture, "texture is null");
        Objects.requireNonNull(at, "position is null");
        if (!at.isFinite()) {
            throw new IllegalArgumentException("a billboard's position must be finite, not " + at);
        }
        if (!(width > 0 && height > 0 && Double.isFinite(width) && Double.isFinite(height))) {
            throw new IllegalArgumentException("billboard size must be positive and finite, got " + width + " x "
                    + height);
        }
        return new Billboard(texture, at, width, height, pixels, false, texture.alpha() == Texture.Alpha.PARTIAL);
    }

    /**
     * This billboard drawn over everything, neither depth-tested nor writing depth.
     *
     * @return a copy drawn on top
     */
    public Billboard onTop() {
        return new Billboard(texture, at, width, height, pixels, true, blended);
    }

    /**
     * The texture.
     *
     * @return the texture
     */
    public Texture texture() {
        return texture;
    }

    /**
     * Its centre, in its object's space.
     *
     * @return the centre
     */
    public Vec3 at() {
        return at;
    }

    /**
     * Width: world units, or pixels when {@link #sizedInPixels()}.
     *
     * @return the width
     */
    public double width() {
        return width;
    }

    /**
     * Height: world units, or pixels when {@link #sizedInPixels()}.
     *
     * @return the height
     */
    public double height() {
        return height;
    }

    /**
     * Whether the size is in pixels rather than world units.
     *
     * @return true for {@link #pixels}
     */
    public boolean sizedInPixels() {
        return pixels;
    }

    /**
     * Whether it is drawn over everything.
     *
     * @return true after {@link #onTop()}
     */
    public boolean isOnTop() {
        return onTop;
    }

    /**
     * Whether it is blended (its texture has alphas other than 0 and 255) rather than alpha-tested.
     *
     * @return true when blended
     */
    public boolean isBlended() {
        return blended;
    }

    /**
     * Whether {@code o} is a billboard of the same texture (the same {@code Texture} object), point, size,
     * sizing and placing: set again, an equal billboard is no change to its object.
     *
     * @param o another object
     * @return true for an equal billboard
     */
    @Override
    public boolean equals(Object o) {
        return o instanceof Billboard b && texture == b.texture && at.equals(b.at) && width == b.width
                && height == b.height && pixels == b.pixels && onTop == b.onTop;
    }

    /**
     * A hash of the values {@link #equals} compares.
     *
     * @return the hash
     */
    @Override
    public int hashCode() {
        return Objects.hash(System.identityHashCode(texture), at, width, height, pixels, onTop);
    }
}
