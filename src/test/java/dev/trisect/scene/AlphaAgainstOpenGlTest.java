package dev.trisect.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Vec3;
import dev.trisect.render.CullMode;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureReader;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Texture alpha against OpenGL: the held scene of scripts/alpha-scene.py (five quads that do not overlap
 * one another, one RGBA texture) drawn with a cut-out texture (alpha 0 or 255, so the material is
 * alpha-tested) and with a ramp of alpha (so it is blended), from two cameras, in every path, and
 * compared with what Mesa's llvmpipe drew with {@code GLREF_ALPHA=test} and {@code GLREF_ALPHA=blend}
 * (PNGs kept by scripts/alpha-references.sh, which regenerates them with glref). Of the pixels either
 * covers (not the black background), at least 99.5 % must agree within 2/255 in every channel in the
 * per-pixel path (measured: 100 %, 99.63 %, 100 %, 100 %). The other paths place a texel within their
 * bound of where perspective puts it, and neighbouring texels here differ by 3 (a ramp), so they agree
 * less (tessellated 82.7–85.9 %, spans 89.2–96.3 %, affine 9–28 %).
 */
class AlphaAgainstOpenGlTest {
    private static final int W = 320;
    private static final int H = 240;

    @ParameterizedTest(name = "{0}, {3}")
    @CsvSource({
        "front, '0,1,5', '0,0.8,0', test, ALPHA_TEST",
        "front, '0,1,5', '0,0.8,0', blend, BLEND",
        "side, '3,2,4', '-0.5,0.6,0', test, ALPHA_TEST",
        "side, '3,2,4', '-0.5,0.6,0', blend, BLEND",
    })
    void alphaTestedAndBlendedPixelsAreOpenGlsWithin2(String name, String eye, String target, String alpha,
                                                      Material.AlphaMode mode) throws Exception {
        Path dir = Path.of(getClass().getResource("/dev/trisect/alpha/panes.obj").toURI()).getParent();
        Texture texture = TextureReader.read(dir.resolve(alpha + ".pam"));
        SceneObject panes = SceneObject.load(dir.resolve("panes.obj"));
        panes.setMaterial(Material.of(texture));
        assertEquals(mode, panes.materials().get(0).alphaMode());
        Scene scene = new Scene();
        scene.add(panes);
        Camera camera = new Camera(vec(eye), vec(target), Vec3.UP, 60, 0.1, 100);
        BufferedImage gl = ImageIO.read(dir.resolve(name + "-" + alpha + ".png").toFile());
        for (RenderMode path : RenderMode.values()) {
            Framebuffer f = new Framebuffer(W, H);
            try (SceneRenderer r = new SceneRenderer(2)) {
                r.render(scene, camera, RenderSettings.defaults().withMode(path).withCull(CullMode.NONE), f);
            }
            int covered = 0;
            int agree = 0;
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    int ours = f.colour()[y * W + x] & 0xFFFFFF;
                    int theirs = gl.getRGB(x, y) & 0xFFFFFF;
                    if (ours == 0 && theirs == 0) {
                        continue;
                    }
                    covered++;
                    agree += within(ours, theirs, 2) ? 1 : 0;
                }
            }
            assertTrue(covered > 3000, name + " " + alpha + ": " + covered + " pixels covered");
            // The per-pixel path is OpenGL's to the texel; the others place texels within their bound, and a
            // texel's neighbour differs from it by more than 2 here (a ramp of 3 a texel): floors against
            // regressions, set under the measured 82.7 % (tessellated) and 89.2 % (spans).
            double least = switch (path) {
                case PERSPECTIVE -> 0.995;
                case TESSELLATED -> 0.80;
                case SPANS -> 0.87;
                case AFFINE -> 0;
            };
            assertTrue(agree >= least * covered, String.format("%s %s, %s: %d of %d covered pixels (%.3f %%) within "
                    + "2/255 of OpenGL's", name, alpha, path, agree, covered, 100.0 * agree / covered));
        }
    }

    private static boolean within(int a, int b, int d) {
        for (int shift = 0; shift < 24; shift += 8) {
            if (Math.abs(((a >> shift) & 0xFF) - ((b >> shift) & 0xFF)) > d) {
                return false;
            }
        }
        return true;
    }

    private static Vec3 vec(String s) {
        String[] p = s.split(",");
        return new Vec3(Double.parseDouble(p[0]), Double.parseDouble(p[1]), Double.parseDouble(p[2]));
    }
}
