/**
 * <b>API.</b> Vectors, matrices, rotations and transforms, in doubles: {@link dev.trisect.math.Vec3},
 * {@link dev.trisect.math.Mat4} (with OpenGL's {@code gluLookAt} and {@code gluPerspective}),
 * {@link dev.trisect.math.Quaternion}, {@link dev.trisect.math.Transform} (translation, rotation and
 * scale, applied scale first) and {@link dev.trisect.math.Viewport} (a frame's size). World units are
 * the user's; +y is up where the built-in controls and shapes need an up.
 */
package dev.trisect.math;
