/**
 * The lowest layer: what every other package may use. Only the user-facing input error lives here.
 */
package dev.trisect.base;
