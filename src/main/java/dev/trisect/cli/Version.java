package dev.trisect.cli;

import dev.trisect.base.internal.BuildVersion;
import picocli.CommandLine.IVersionProvider;

/** The version from the jar's manifest, or "development" when run from classes ({@link BuildVersion}). */
final class Version implements IVersionProvider {
    @Override
    public String[] getVersion() {
        return new String[] {BuildVersion.line()};
    }
}
