package dev.trisect.cli;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.List;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/**
 * Jazzer fuzz target: the command line's option converters. The first byte picks a converter, the rest
 * (UTF-8, malformed sequences replaced) is the option's value. Every value must convert or be refused
 * with a {@link TypeConversionException} whose message is one line (the command line turns it into a
 * usage error, exit status 2). Seeds are in
 * {@code src/test/resources/dev/trisect/cli/ConvertersFuzzTestInputs}.
 */
class ConvertersFuzzTest {
    private static final List<ITypeConverter<?>> CONVERTERS = List.of(new Converters.SizeConverter(),
            new Converters.Vec3Converter(), new Converters.PositiveConverter(), new Converters.ColourConverter(),
            new Converters.ModeConverter(), new Converters.SplitConverter(), new Converters.SplitPointConverter(),
            new Converters.CullConverter(), new Converters.FilterConverter(),
            new Converters.FramePiecesConverter());

    @FuzzTest(maxDuration = "5m")
    void everyValueConvertsOrIsAOneLineUsageError(byte[] input) throws Exception {
        if (input.length == 0) {
            return;
        }
        ITypeConverter<?> converter = CONVERTERS.get((input[0] & 0xFF) % CONVERTERS.size());
        String value = new String(Arrays.copyOfRange(input, 1, input.length), StandardCharsets.UTF_8);
        try {
            assertNotNull(converter.convert(value));
        } catch (TypeConversionException e) {
            assertFalse(e.getMessage() == null || e.getMessage().contains("\n"), String.valueOf(e.getMessage()));
        }
    }

    /**
     * Magnitudes in options: three values separated by NUL bytes, taken as {@code --eye}, {@code --target}
     * and {@code --up}. Each converts or is refused as above; three points then make a camera whose view
     * matrix is a rotation (rows of unit length, at right angles) and a translation, or are refused with
     * a one-line {@link IllegalArgumentException}, at any magnitude from 4.9e-324 to 1.8e308.
     */
    @FuzzTest(maxDuration = "5m")
    void threePointsMakeAValidCameraOrAOneLineRefusal(byte[] input) throws Exception {
        String[] parts = new String(input, StandardCharsets.UTF_8).split("\0", -1);
        if (parts.length != 3) {
            return;
        }
        Converters.Vec3Converter converter = new Converters.Vec3Converter();
        dev.trisect.math.Vec3[] points = new dev.trisect.math.Vec3[3];
        for (int i = 0; i < 3; i++) {
            try {
                points[i] = converter.convert(parts[i]);
            } catch (TypeConversionException e) {
                assertFalse(e.getMessage() == null || e.getMessage().contains("\n"), String.valueOf(e.getMessage()));
                return;
            }
        }
        dev.trisect.scene.Camera camera;
        try {
            camera = new dev.trisect.scene.Camera(points[0], points[1], points[2], 60, 0.1, 1000);
        } catch (IllegalArgumentException e) {
            assertFalse(e.getMessage() == null || e.getMessage().contains("\n"), String.valueOf(e.getMessage()));
            return;
        }
        dev.trisect.math.Mat4 view = camera.view();
        for (int r = 0; r < 3; r++) {
            for (int q = 0; q < 3; q++) {
                double dot = 0;
                for (int k = 0; k < 3; k++) {
                    dot += view.get(r, k) * view.get(q, k);
                }
                double expected = r == q ? 1 : 0;
                if (!(Math.abs(dot - expected) < 1e-9)) {
                    throw new AssertionError("view rows " + r + "," + q + " dot " + dot + " for eye " + points[0]
                            + " target " + points[1] + " up " + points[2]);
                }
            }
        }
    }
}
