/**
 * Trisect, a pure-Java, CPU-only 3D engine. The module exports its API packages alone; the others are
 * internal (the renderer's stages, the developer tools, the command line and the demo) and may change
 * without notice. {@code java.desktop} is required transitively, since the API hands out
 * {@code BufferedImage}s and the view is a Swing component.
 *
 * <p>picocli (the command line), FlatLaf (the demo's look) and XChart (the benchmarks' charts) serve the
 * application only: {@code requires static}, optional in the pom, absent from a program that uses the
 * library. The runnable jar ({@code target/trisect.jar}) runs from the class path and carries no
 * module descriptor.
 */
module dev.trisect {
    requires transitive java.desktop;
    requires java.management;
    requires com.fasterxml.jackson.jr.ob;
    requires com.twelvemonkeys.imageio.tga;
    requires static info.picocli;
    requires static com.formdev.flatlaf;
    requires static org.knowm.xchart;

    exports dev.trisect.base;
    exports dev.trisect.math;
    exports dev.trisect.mesh;
    exports dev.trisect.texture;
    exports dev.trisect.render;
    exports dev.trisect.scene;
    exports dev.trisect.view;

    // picocli reads and sets the commands' annotated fields by reflection.
    opens dev.trisect to info.picocli;
    opens dev.trisect.cli to info.picocli;
    opens dev.trisect.ui to info.picocli;
}
