package dev.trisect.cli;

import dev.trisect.base.InputException;
import dev.trisect.content.SceneAsset;
import dev.trisect.io.OutputBatch;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/** Checks of output file names, made before any work so that a typo costs nothing. */
final class Outputs {
    private Outputs() {
    }

    /** An image output: .png or .ppm. */
    static void checkImage(String option, Path file) {
        String name = lower(file);
        if (!(name.endsWith(".png") || name.endsWith(".ppm"))) {
            throw InputException.usage(option + " " + file + ": unsupported output format (use .png or .ppm)");
        }
    }

    /** A PNG output. */
    static void checkPng(String option, Path file) {
        if (!lower(file).endsWith(".png")) {
            throw InputException.usage(option + " " + file + ": must be a .png file");
        }
    }

    /** A UV output: .pfm. */
    static void checkPfm(String option, Path file) {
        if (!lower(file).endsWith(".pfm")) {
            throw InputException.usage(option + " " + file + ": the UV output is a PFM file (use .pfm)");
        }
    }

    /**
     * Creates the directory an output goes into, if missing: an export writes several files there
     * (OBJ, MTL, textures), and asking the user to make it first gains nothing.
     *
     * @return the outermost folder made (for {@link #removeMadeFolders}), or null when the directory was there
     */
    static Path createParent(String option, Path file) {
        // Normalized, so that the folders made are named as removeMadeFolders walks them (x/./y, x/../y).
        Path parent = file.toAbsolutePath().normalize().getParent();
        if (parent == null || Files.isDirectory(parent)) {
            return null;
        }
        Path top = parent;
        while (top.getParent() != null && !Files.exists(top.getParent())) {
            top = top.getParent();
        }
        try {
            OutputBatch.createFolders(parent);
        } catch (InputException e) {
            throw new InputException(option + " " + file + ": " + e.getMessage(), e.getCause());
        }
        return top;
    }

    /**
     * Removes the folders {@link #createParent} made for {@code file}, from its parent up to {@code top},
     * as far as they are empty: a command that wrote nothing leaves no trace. Best effort: a folder
     * something else has written into since stays, and so does one that cannot be removed. A folder
     * left when creating part of the path failed, or after a signal (which runs only the shutdown
     * hook), stays too.
     *
     * @param top what {@code createParent} returned; null: nothing was made
     */
    static void removeMadeFolders(Path file, Path top) {
        if (top == null) {
            return;
        }
        for (Path folder = file.toAbsolutePath().normalize().getParent(); folder != null;
                folder = folder.getParent()) {
            try {
                Files.delete(folder);
            } catch (java.io.IOException e) {
                return;
            }
            if (folder.equals(top)) {
                return;
            }
        }
    }

    /**
     * Two outputs of one command must be different files, or one would silently replace the other.
     * Paths are compared absolute and normalized ({@code a/../x.png} is {@code x.png}).
     */
    static void checkDistinct(String option, Path file, String otherOption, Path other) {
        if (file.toAbsolutePath().normalize().equals(other.toAbsolutePath().normalize())) {
            throw InputException.usage(option + " " + file + " and " + otherOption + " " + other
                    + " are the same file; one output would replace the other");
        }
    }

    /**
     * An output must not be one of the command's input files ({@code --texture t.png --out t.png}, a
     * heat map over the image it measures): writing it would replace the model, texture or render the
     * command was given, which is lost work, not a result. Refused before anything is read or written.
     * Files are compared by name (absolute, normalized) and, when both exist, as files, so that a link
     * to the input counts as the input (outputs are written through links).
     *
     * @param input the input file, or null when there is none (its option was not given)
     * @param what  the input in words, for the message: "the --texture input"
     */
    static void checkNotInput(Path output, String what, Path input) {
        if (output == null || input == null) {
            return;
        }
        boolean same = output.toAbsolutePath().normalize().equals(input.toAbsolutePath().normalize());
        try {
            same = same || (Files.exists(output) && Files.exists(input) && Files.isSameFile(output, input));
        } catch (java.io.IOException e) {
            // Neither can be examined: nothing shows them to be one file, and reading or writing will say why.
        }
        if (same) {
            throw InputException.usage(output + " is also " + what + "; an output may not "
                    + "replace an input (write it under another name)");
        }
    }

    /**
     * An output must not replace a file the scene was read from: the OBJ's material libraries and
     * textures, known only once it is read (checked then, before any work on the frame or the export).
     */
    static void checkNotSceneInput(Path output, SceneAsset scene) {
        for (Path in : scene.inputs()) {
            checkNotInput(output, "an input of " + scene.name() + " (a material library or texture it names)", in);
        }
    }

    /** An OBJ export target: .obj, since the MTL and textures beside it take its name with other extensions. */
    static void checkObj(String option, Path file) {
        if (!lower(file).endsWith(".obj")) {
            throw InputException.usage(option + " " + file + ": must be a .obj file (the .mtl and .ppm files are "
                    + "written beside it, named after it)");
        }
    }

    private static String lower(Path file) {
        Path name = file.getFileName();
        return name == null ? "" : name.toString().toLowerCase(Locale.ROOT);
    }
}
