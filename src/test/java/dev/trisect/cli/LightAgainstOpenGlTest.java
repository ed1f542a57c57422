package dev.trisect.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.io.Pfm;
import dev.trisect.math.Mat4;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.ObjReader;
import dev.trisect.scene.Camera;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;
import org.junit.jupiter.api.io.TempDir;

/**
 * Light and fog against OpenGL: the frames of {@code light/frames.txt} (demo, boxes, sphere and a
 * tinyrenderer-style head with {@code vn}) under each of its lights — directional, a coloured point
 * light attenuated by 1, 0.2, 0.05, both with a coloured ambient, each flat and smooth, and linear and
 * exp fog — drawn by the command line's per-pixel path with nearest sampling and compared with the
 * pixels Mesa's llvmpipe drew with the same options (scripts/light-references.sh keeps them, 160x120).
 * Of the pixels either covers, at least 99.5 % must be within 2/255 in every channel. With fog, the
 * pixels of triangles reaching behind the eye are left out: Mesa interpolates the fog coordinate
 * |z_e| from the vertices, which across the eye plane is not the fragment's depth (docs/opengl.md, "Fog").
 */
class LightAgainstOpenGlTest {
    private static final String RESOURCES = "/dev/trisect/light/";

    @TempDir
    static Path dir;

    /** One frame of frames.txt under one light. */
    private record Case(String frame, String scene, String eye, String target, String far, String point,
                        String light, List<String> options) {
    }

    @TestFactory
    Stream<DynamicTest> everyFrameUnderEveryLightAgreesWithOpenGl() throws IOException {
        List<String[]> frames = new ArrayList<>();
        List<String[]> lights = new ArrayList<>();
        for (String line : new String(resource("frames.txt").readAllBytes(), StandardCharsets.UTF_8).split("\n")) {
            String[] f = line.trim().split("\\s+");
            if (f[0].equals("frame")) {
                frames.add(f);
            } else if (f[0].equals("light")) {
                lights.add(f);
            }
        }
        assertEquals(4, frames.size());
        assertEquals(8, lights.size());
        List<Case> cases = new ArrayList<>();
        for (String[] l : lights) {
            for (String[] f : frames) {
                List<String> options = new ArrayList<>();
                for (String o : Arrays.asList(l).subList(2, l.length)) {
                    options.add(o.replace("POINT", f[6]));
                }
                cases.add(new Case(f[1], f[2], f[3], f[4], f[5], f[6], l[1], options));
            }
        }
        return cases.stream().map(c -> DynamicTest.dynamicTest(c.frame() + " " + c.light(), () -> check(c)));
    }

    private static void check(Case c) throws Exception {
        Path obj = obj(c.scene());
        Path out = dir.resolve(c.frame() + "-" + c.light() + ".png");
        List<String> args = new ArrayList<>(List.of("render", "--obj", obj.toString(), "--texture",
                path("/dev/trisect/lines/checker.ppm").toString(), "--size", "160x120", "--mode", "perspective",
                "--eye", c.eye(), "--target", c.target(), "--near", "0.1", "--far", c.far(), "--cull", "back",
                "--background", "000000", "--out", out.toString(), "--uv-out", dir.resolve("uv.pfm").toString()));
        args.addAll(c.options());
        CliRun run;
        float[] uv;
        synchronized (LightAgainstOpenGlTest.class) {
            run = CliRun.of(args.toArray(String[]::new));
            assertEquals(0, run.status(), run.err());
            uv = Pfm.read(dir.resolve("uv.pfm")).data();
        }
        // Fog: Mesa computes the fog coordinate |z_e| per vertex and interpolates it, which across a
        // triangle reaching behind the eye is not the fragment's depth (Trisect takes the fragment's):
        // such triangles' pixels are counted apart.
        boolean[] behind = c.light().startsWith("fog") ? reachBehindTheEye(obj, c) : null;
        int apart = 0;
        BufferedImage ours = ImageIO.read(out.toFile());
        BufferedImage gl;
        try (InputStream in = resource(c.frame() + "-" + c.light() + ".png")) {
            gl = ImageIO.read(in);
        }
        int covered = 0;
        int within = 0;
        for (int y = 0; y < 120; y++) {
            for (int x = 0; x < 160; x++) {
                int a = ours.getRGB(x, y) & 0xFFFFFF;
                int b = gl.getRGB(x, y) & 0xFFFFFF;
                if (a == 0 && b == 0) {
                    continue;
                }
                int id = (int) uv[3 * (y * 160 + x) + 2] - 1;
                if (behind != null && id >= 0 && behind[id]) {
                    apart++;
                    continue;
                }
                covered++;
                boolean close = true;
                for (int shift = 0; shift < 24; shift += 8) {
                    close &= Math.abs((a >> shift & 0xFF) - (b >> shift & 0xFF)) <= 2;
                }
                within += close ? 1 : 0;
            }
        }
        assertTrue(covered > 2000, "the frame shows the scene: " + covered + " pixels");
        double share = (double) within / covered;
        double least = least(c);

        assertTrue(share >= least, String.format("%s %s: %d of %d covered pixels within 2/255 (%.4f < %.4f)%s",
                c.frame(), c.light(), within, covered, share, least, apart > 0 ? ", " + apart + " more apart" : ""));
    }

    /** The share of covered pixels that must agree within 2/255. */
    private static double least(Case c) {
        return 0.995;
    }

    /** Per triangle of the frame's mesh: whether a corner lies at or behind the eye plane (z_e >= 0). */
    private static boolean[] reachBehindTheEye(Path obj, Case c) {
        Mesh mesh = ObjReader.read(obj, false).mesh();
        Mat4 view = new Camera(vec(c.eye()), vec(c.target()), Vec3.UP, 60, 0.1, Double.parseDouble(c.far())).view();
        float[] p = mesh.positions();
        int[] corners = mesh.cornerPositions();
        boolean[] behind = new boolean[mesh.triangleCount()];
        double[] e = new double[4];
        for (int k = 0; k < corners.length; k++) {
            int i = 3 * corners[k];
            view.transformPoint(p[i], p[i + 1], p[i + 2], e, 0);
            behind[k / 3] |= e[2] >= 0;
        }
        return behind;
    }

    private static Vec3 vec(String s) {
        String[] v = s.split(",");
        return new Vec3(Double.parseDouble(v[0]), Double.parseDouble(v[1]), Double.parseDouble(v[2]));
    }

    /** The scene's OBJ: the head kept here, a built-in scene exported once. */
    private static synchronized Path obj(String scene) throws URISyntaxException {
        if (scene.equals("head")) {
            return path(RESOURCES + "head.obj");
        }
        Path obj = dir.resolve(scene).resolve(scene + ".obj");
        if (!Files.exists(obj)) {
            CliRun run = CliRun.of("export", "--scene", scene, "--to", obj.toString());
            assertEquals(0, run.status(), run.err());
        }
        return obj;
    }

    private static InputStream resource(String name) {
        InputStream in = LightAgainstOpenGlTest.class.getResourceAsStream(name.startsWith("/") ? name : RESOURCES + name);
        if (in == null) {
            throw new UncheckedIOException(new IOException("missing test resource " + name));
        }
        return in;
    }

    private static Path path(String name) throws URISyntaxException {
        return Path.of(LightAgainstOpenGlTest.class.getResource(name).toURI());
    }
}
