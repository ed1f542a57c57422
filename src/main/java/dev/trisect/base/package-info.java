/**
 * <b>API.</b> The lowest layer: what every other package may use. The user-facing input error
 * ({@link dev.trisect.base.InputException}: one line naming the file, the line and the problem). The
 * JSON lines the command line prints are built in the internal package
 * {@code dev.trisect.base.internal}.
 */
package dev.trisect.base;
