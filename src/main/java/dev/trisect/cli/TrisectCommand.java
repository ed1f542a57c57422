package dev.trisect.cli;

import picocli.CommandLine.Command;

/** The root command; its subcommands do the work. */
@Command(name = "trisect", mixinStandardHelpOptions = true, versionProvider = Version.class,
        description = {"Trisect: a pure-Java CPU 3D engine with tessellated perspective texturing.",
                "Without arguments, java -jar trisect.jar opens the desktop demo."},
        subcommands = {RenderCommand.class, CompareCommand.class, DiffCommand.class, ExportCommand.class,
                BenchCommand.class})
final class TrisectCommand {
}
