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
}
