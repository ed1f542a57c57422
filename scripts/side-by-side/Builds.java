import java.lang.reflect.InvocationTargetException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Path;
import java.util.function.LongSupplier;

/**
 * What the programs that run builds' frames (SideBySide, PerfPair, OneBuild) share: loading a build's
 * {@code Frame} (compiled against its jar by frame-for.sh) in a class loader of its own, so that two
 * builds live in one JVM, and turning a bad scene, path or argument into one line and exit status 2.
 */
final class Builds {
    private Builds() {
    }

    /** A program's work, which may fail. */
    interface Work {
        void run() throws Exception;
    }

    /**
     * Runs {@code work}, then exits with status 0; a scene, path or filter the build does not have
     * ({@code Frame.make} says which) or a bad argument prints "{@code tool}: reason" and exits with 2.
     */
    static void main(String tool, Work work) throws Exception {
        try {
            work.run();
        } catch (InvocationTargetException e) {
            System.err.println(tool + ": " + e.getCause().getMessage());
            System.exit(2);
        } catch (IllegalArgumentException e) {
            System.err.println(tool + ": " + e.getMessage());
            System.exit(2);
        }
        System.exit(0);
    }

    /** The {@code Frame} class in directory {@code classes}, with the build's {@code jar} beside it. */
    static Class<?> frameClass(String classes, String jar) throws Exception {
        URL[] urls = {Path.of(classes).toUri().toURL(), Path.of(jar).toUri().toURL()};
        return new URLClassLoader(urls, ClassLoader.getPlatformClassLoader()).loadClass("Frame");
    }

    /** {@code Frame.make(scene, path, width, height, threads)} of a build's {@code Frame} class. */
    static LongSupplier frame(Class<?> frameClass, String scene, String path, int width, int height, int threads)
            throws Exception {
        return (LongSupplier) frameClass.getMethod("make", String.class, String.class, int.class, int.class, int.class)
                .invoke(null, scene, path, width, height, threads);
    }
}
