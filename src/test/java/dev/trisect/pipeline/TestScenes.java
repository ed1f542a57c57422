package dev.trisect.pipeline;

import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.MeshBuilder;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.Camera;
import dev.trisect.texture.Texture;

/** Small scenes and a texture for pipeline tests. */
final class TestScenes {
    private TestScenes() {
    }

    /** A 64x64 texture whose texels are all different, so any texel mix-up shows in colour. */
    static Texture distinctTexels() {
        int[] px = new int[64 * 64];
        for (int i = 0; i < px.length; i++) {
            px[i] = 0xFF000000 | (i * 0x9E3779B1 >>> 8);
        }
        return new Texture("distinct", 64, 64, px);
    }

    /**
     * A floor y = 0 over x in [-20, 20], z in [-100, 5], as {@code cells x cells} quads; with a
     * 64-texel texture and one repeat per 4 units, s = 16 x and t = -16 z.
     */
    static Mesh floor(int cells) {
        MeshBuilder b = new MeshBuilder();
        Primitives.floor(b, -20, 20, -100, 5, 0, cells, cells, 4);
        return b.build();
    }

    /** A camera low over the floor, looking toward the horizon; its near plane cuts the floor. */
    static Camera floorCamera() {
        return new Camera(new Vec3(0.3, 1.5, 4), new Vec3(0, 0.4, -10), Vec3.UP, 60, 0.1, 1000);
    }

    static Framebuffer render(FrameRenderer r, Mesh mesh, Camera camera, RenderSettings s, int w, int h) {
        Framebuffer fb = new Framebuffer(w, h);
        fb.recordUv(true);
        r.render(mesh, new Texture[] {distinctTexels()}, camera.viewProjection(new Viewport(w, h)), s, fb);
        return fb;
    }
}
