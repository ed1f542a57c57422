/**
 * <b>API.</b> Textures: {@link dev.trisect.texture.Texture} (ARGB texels, with its mipmap chain),
 * from a {@code BufferedImage} ({@code Texture.of}), an image file
 * ({@link dev.trisect.texture.TextureReader}) or made procedurally
 * ({@link dev.trisect.texture.ProceduralTextures}); and the filters every path samples with
 * ({@link dev.trisect.texture.TextureFilter}: OpenGL's nearest, bilinear and trilinear). Some classes
 * here serve the renderer's pixel loops and are not meant for programs (the samplers, the level of
 * detail, the bitmap font); they are due to move to an internal package.
 */
package dev.trisect.texture;
