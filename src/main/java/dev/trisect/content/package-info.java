/**
 * <b>Internal, not part of the API</b> (the module does not export it; it may change without notice).
 * The built-in scenes and the OBJ scenes the command line, the benchmarks and the demo
 * draw: a {@code SceneAsset} (one mesh, a texture per material, a camera, a name), made by
 * {@code DemoScenes} or loaded by {@code SceneLoader}.
 */
package dev.trisect.content;
