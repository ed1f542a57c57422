/**
 * <b>Internal, not part of the API</b> (not exported by the module; may change without notice): the
 * JSON lines the command line, the statistics and the soak report print ({@code JsonObject}, on
 * jackson-jr), the version line every command prints ({@code BuildVersion}), and counts with their nouns
 * ({@code Counts}).
 */
package dev.trisect.base.internal;
