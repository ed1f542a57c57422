/**
 * <b>API.</b> Textures: {@link dev.trisect.texture.Texture} (ARGB texels, with its mipmap chain),
 * from a {@code BufferedImage} ({@code Texture.of}), an image file
 * ({@link dev.trisect.texture.TextureReader}) or made procedurally
 * ({@link dev.trisect.texture.ProceduralTextures}); and the filters every path samples with
 * ({@link dev.trisect.texture.TextureFilter}: OpenGL's nearest, bilinear and trilinear). What only the
 * renderer's pixel loops use (the filtered samplers, the level of detail, the bitmap font) is in the
 * internal package {@code dev.trisect.texture.internal}.
 */
package dev.trisect.texture;
