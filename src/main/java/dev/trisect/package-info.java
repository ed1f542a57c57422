/**
 * <b>Internal, not part of the API</b> (the module does not export it; it may change without notice).
 * The launcher of the runnable jar ({@code Trisect}): the demo without arguments, the command line
 * otherwise.
 */
package dev.trisect;
