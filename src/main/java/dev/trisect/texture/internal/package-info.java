/**
 * <b>Internal, not part of the API</b> (not exported by the module; may change without notice). What the
 * renderer's pixel loops and developer tools need from textures: the mip levels laid out in 16-bit lanes
 * ({@code TexelLanes}) and their allocation-free bilinear and trilinear samples ({@code LaneSampler}),
 * the exact-weight reference sampler they are tested against ({@code Sampler}), OpenGL's level of detail
 * ({@code Lod}), and the bitmap font and pixel helpers of the procedural textures.
 */
package dev.trisect.texture.internal;
