/**
 * The lowest layer: what every other package may use. The user-facing input error (with the quoting
 * its one-line messages use) and the JSON object every printed JSON line is built with.
 */
package dev.trisect.base;
