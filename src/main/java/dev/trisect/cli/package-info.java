/**
 * <b>Internal, not part of the API</b> (the module does not export it; it may change without notice).
 * The command line ({@code render}, {@code compare}, {@code diff}, {@code export},
 * {@code bench}), on picocli: each command parses its options into the settings of the API packages,
 * draws through {@code pipeline}, and writes its outputs all or nothing; bad input ends with one line
 * and a non-zero status (docs/cli.md).
 */
package dev.trisect.cli;
