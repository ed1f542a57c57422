package dev.trisect.scene;

import dev.trisect.math.Vec3;
import dev.trisect.texture.Texture;

/**
 * What a pixel of a drawn frame shows: see {@link SceneRenderer#pick} (which surfaces are picked).
 *
 * @param object   the object drawn at the pixel
 * @param triangle the triangle of the object's mesh, 0-based
 * @param point    the point of that triangle on the ray through the pixel's centre, world space (exact:
 *                 the ray met with the triangle's plane)
 * @param u        the texture coordinate u at {@code point} (exact; (0, 0) is the texture's bottom-left)
 * @param v        the texture coordinate v at {@code point}
 * @param texture  the texture the triangle was drawn with
 * @param texelX   the column of the texel at ({@code u}, {@code v}) — nearest, with repeat, on the full
 *                 size level: the texel the per-pixel perspective path shows there with nearest
 *                 sampling (the other paths may show one beside it, within their error bound; the
 *                 developer tools' pixel inspector tells the one the path drew) — 0 at the left
 * @param texelY   its row, 0 at the top of the texture image
 * @param x        the pixel's column in the frame, 0 at the left (a view's frame has its device pixels
 *                 times its render scale: not the mouse's coordinates unless both are 1)
 * @param y        the pixel's row in the frame, 0 at the top
 */
public record Pick(SceneObject object, int triangle, Vec3 point, double u, double v, Texture texture,
                   int texelX, int texelY, int x, int y) {
}
