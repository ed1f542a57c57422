/**
 * <b>API.</b> The lowest layer: what every other package may use. The user-facing input error
 * ({@link dev.trisect.base.InputException}: one line naming the file, the line and the problem) and,
 * for the command line's output, the JSON object every printed JSON line is built with (internal in
 * all but its package; due to move to an internal package).
 */
package dev.trisect.base;
