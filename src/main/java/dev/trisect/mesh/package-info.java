/**
 * <b>API.</b> Indexed triangle meshes, immutable once built: {@link dev.trisect.mesh.Mesh}, built with
 * {@link dev.trisect.mesh.MeshBuilder}, made by {@link dev.trisect.mesh.Primitives} (box, plane,
 * sphere) or read from Wavefront OBJ files by {@link dev.trisect.mesh.ObjReader}; line segments, drawn
 * after the triangles, are {@link dev.trisect.mesh.Lines}. A mesh may be
 * shared by any number of scene objects.
 */
package dev.trisect.mesh;
