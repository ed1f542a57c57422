package dev.trisect.base.internal;

/**
 * The version line every command prints for {@code --version}, shared by the command line and the
 * demo (which may not use each other's packages).
 */
public final class BuildVersion {
    private BuildVersion() {
    }

    /**
     * {@code trisect 0.1.0-SNAPSHOT}: the Implementation-Version of the jar's manifest, or "development
     * build" when run from classes, which have no manifest.
     */
    public static String line() {
        String v = BuildVersion.class.getPackage().getImplementationVersion();
        return "trisect " + (v == null ? "development build" : v);
    }
}
