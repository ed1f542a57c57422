package dev.trisect.io;

import dev.trisect.mesh.Lines;
import dev.trisect.mesh.Mesh;
import dev.trisect.texture.Texture;
import java.io.BufferedWriter;
import java.io.IOException;
import java.io.Writer;
import java.io.OutputStreamWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;

/**
 * Writes a mesh as Wavefront OBJ with an MTL file and one file per texture, shared by the materials
 * that use it (binary PPM, or PAM with tuple type RGB_ALPHA for a texture with alpha below 255
 * anywhere, so that a cut-out or translucent texture reads back as it was), so that other renderers
 * (OpenGL through tools/glref, say) can draw exactly the same triangles.
 * Triangles are written in order, so triangle indices are preserved, each corner as {@code v},
 * {@code v/vt}, {@code v/vt/vn} or {@code v//vn} after what it has; the mesh's normals as {@code vn}
 * (a corner without one is written without, and a reader takes the face normal there, as Trisect does).
 * Lines, if any, follow as {@code l} polylines (consecutive segments of one colour sharing an end
 * joined), in order, their points after the mesh's positions, each colour a material
 * {@code line-RRGGBB} with that {@code Kd} (reading the files back gives the same segments and colours).
 */
public final class ObjWriter {
    private ObjWriter() {
    }

    /**
     * @param obj      the OBJ file to write; the MTL and textures go beside it, named after it
     * @param mesh     positions, UVs and normals, written as floats exactly (shortest round-trip decimal)
     * @param textures one per material
     * @return each material's texture file (materials sharing a texture share its file, written once)
     * @throws dev.trisect.base.InputException when a file cannot be written; then none of them is
     *                                         (they are written as one {@link OutputBatch})
     */
    public static List<Path> write(Path obj, Mesh mesh, List<Texture> textures) {
        return write(obj, mesh, textures, Lines.EMPTY);
    }

    /**
     * As {@link #write(Path, Mesh, List)}, with lines after the triangles.
     *
     * @param lines the segments, in the mesh's space
     */
    public static List<Path> write(Path obj, Mesh mesh, List<Texture> textures, Lines lines) {
        try (OutputBatch batch = new OutputBatch()) {
            List<Path> maps = write(batch, obj, mesh, textures, lines);
            batch.commit();
            return maps;
        }
    }

    /**
     * As {@link #write(Path, Mesh, List)}, as part of {@code batch}: the files appear only when the batch
     * is committed.
     */
    public static List<Path> write(OutputBatch batch, Path obj, Mesh mesh, List<Texture> textures) {
        return write(batch, obj, mesh, textures, Lines.EMPTY);
    }

    /**
     * As {@link #write(OutputBatch, Path, Mesh, List)}, with lines after the triangles.
     *
     * @param lines the segments, in the mesh's space
     */
    public static List<Path> write(OutputBatch batch, Path obj, Mesh mesh, List<Texture> textures, Lines lines) {
        List<Path> files = files(obj, mesh, textures);
        Path mtl = files.get(1);
        Path[] maps = files.subList(2, files.size()).toArray(Path[]::new);
        java.util.Set<Path> written = new java.util.HashSet<>();
        for (int m = 0; m < maps.length; m++) {
            Texture t = textures.get(m);
            if (written.add(maps[m])) {
                ImageFiles.write(batch, maps[m], t.width(), t.height(), t.argb());
            }
        }
        writeText(batch, mtl, w -> {
            for (int m = 0; m < maps.length; m++) {
                w.write("newmtl " + mesh.materialNames().get(m) + "\nmap_Kd " + maps[m].getFileName() + "\n");
            }
            java.util.Set<Integer> colours = new java.util.LinkedHashSet<>();
            for (int c : lines.colours()) {
                if (colours.add(c)) {
                    // k/255 in floats reads back to the same byte: round(255 * k) == c's channel.
                    w.write("newmtl " + lineMaterial(mesh, c) + "\nKd " + (c >> 16 & 255) / 255f + " "
                            + (c >> 8 & 255) / 255f + " " + (c & 255) / 255f + "\n");
                }
            }
        });
        writeText(batch, obj, w -> {
            w.write("# written by Trisect\nmtllib " + mtl.getFileName() + "\n");
            float[] p = mesh.positions();
            for (int i = 0; i < p.length; i += 3) {
                w.write("v " + p[i] + " " + p[i + 1] + " " + p[i + 2] + "\n");
            }
            float[] uv = mesh.uvs();
            for (int i = 0; i < uv.length; i += 2) {
                w.write("vt " + uv[i] + " " + uv[i + 1] + "\n");
            }
            float[] n = mesh.normals();
            for (int i = 0; i < n.length; i += 3) {
                w.write("vn " + n[i] + " " + n[i + 1] + " " + n[i + 2] + "\n");
            }
            int[] cp = mesh.cornerPositions();
            int[] cu = mesh.cornerUvs();
            int[] cn = mesh.cornerNormals();
            int[] mat = mesh.triangleMaterials();
            int current = -1;
            StringBuilder line = new StringBuilder(64);
            for (int t = 0; t < mesh.triangleCount(); t++) {
                if (mat[t] != current) {
                    current = mat[t];
                    w.write("usemtl " + mesh.materialNames().get(current) + "\n");
                }
                line.setLength(0);
                line.append('f');
                for (int k = 3 * t; k < 3 * t + 3; k++) {
                    line.append(' ').append(cp[k] + 1);
                    if (cu[k] >= 0 || cn[k] >= 0) {
                        line.append('/');
                    }
                    if (cu[k] >= 0) {
                        line.append(cu[k] + 1);
                    }
                    if (cn[k] >= 0) {
                        line.append('/').append(cn[k] + 1);
                    }
                }
                w.write(line.append('\n').toString());
            }
            writeLines(w, mesh, lines);
        });
        return List.of(maps);
    }

    /** The lines' points after the mesh's positions, then their segments as polylines. */
    private static void writeLines(Writer w, Mesh mesh, Lines lines) throws IOException {
        if (lines.isEmpty()) {
            return;
        }
        float[] p = lines.points();
        for (int i = 0; i < p.length; i += 3) {
            w.write("v " + p[i] + " " + p[i + 1] + " " + p[i + 2] + "\n");
        }
        int base = mesh.positionCount() + 1;
        int[] ends = lines.segments();
        int[] colours = lines.colours();
        int current = -1;
        StringBuilder line = new StringBuilder(64);
        for (int s = 0; s < colours.length; s++) {
            boolean joined = s > 0 && colours[s] == colours[s - 1] && ends[2 * s] == ends[2 * s - 1];
            if (!joined) {
                if (line.length() > 0) {
                    w.write(line.append('\n').toString());
                    line.setLength(0);
                }
                if (colours[s] != current) {
                    current = colours[s];
                    w.write("usemtl " + lineMaterial(mesh, current) + "\n");
                }
                line.append("l ").append(ends[2 * s] + base);
            }
            line.append(' ').append(ends[2 * s + 1] + base);
        }
        w.write(line.append('\n').toString());
    }

    /** The material of lines of colour {@code rgb}: {@code line-RRGGBB}, unless the mesh has that name. */
    private static String lineMaterial(Mesh mesh, int rgb) {
        String name = String.format("line-%06X", rgb);
        return mesh.materialNames().contains(name) ? "trisect-" + name : name;
    }

    /**
     * The files {@link #write} writes for {@code obj}, known before writing (so that a command can check
     * them against its inputs first): the OBJ, its MTL beside it, then each material's texture file, in the
     * mesh's material order, named after the OBJ and the material: {@code .pam} for a texture with
     * alpha ({@link Texture#alpha()} not {@code OPAQUE}), else {@code .ppm}. Materials that share one
     * {@link Texture} (the same object) share the file of the first of them, written once.
     *
     * @param obj      the OBJ file to write
     * @param mesh     the mesh, for its material names
     * @param textures one per material
     * @return the OBJ, the MTL and the textures, absolute
     */
    public static List<Path> files(Path obj, Mesh mesh, List<Texture> textures) {
        Path dir = obj.toAbsolutePath().getParent();
        String base = obj.getFileName().toString().replaceFirst("\\.[^.]*$", "");
        List<Path> files = new java.util.ArrayList<>(List.of(obj.toAbsolutePath(), dir.resolve(base + ".mtl")));
        java.util.Set<String> taken = new java.util.HashSet<>();
        // Materials that share one texture share its file: a model whose 200 materials all name one
        // 4096x4096 map wrote 200 copies of it, 10 GB.
        java.util.Map<Texture, Path> shared = new java.util.IdentityHashMap<>();
        for (int m = 0; m < mesh.materialNames().size(); m++) {
            Texture t = textures.get(m);
            Path file = shared.get(t);
            if (file == null) {
                String extension = t.alpha() == Texture.Alpha.OPAQUE ? ".ppm" : ".pam";
                file = dir.resolve(unique(base + "-" + safe(mesh.materialNames().get(m)), taken) + extension);
                shared.put(t, file);
            }
            files.add(file);
        }
        return files;
    }

    /**
     * {@code name}, or with "-2", "-3", ... added when cleaning made two materials' names the same
     * ("a.b" and "a_b" both give "a_b"); compared ignoring case, for file systems that do.
     */
    private static String unique(String name, java.util.Set<String> taken) {
        String candidate = name;
        for (int n = 2; !taken.add(candidate.toLowerCase(java.util.Locale.ROOT)); n++) {
            candidate = name + "-" + n;
        }
        return candidate;
    }

    private static String safe(String name) {
        return name.replaceAll("[^A-Za-z0-9_-]", "_");
    }

    private interface Body {
        void write(Writer w) throws IOException;
    }

    /** Writes a UTF-8 text file as part of {@code batch}. */
    private static void writeText(OutputBatch batch, Path file, Body body) {
        batch.write(file, out -> {
            Writer w = new BufferedWriter(new OutputStreamWriter(out, StandardCharsets.UTF_8));
            body.write(w);
            w.flush();
        });
    }
}
