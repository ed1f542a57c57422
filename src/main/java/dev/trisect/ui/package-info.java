/**
 * <b>Internal, not part of the API</b> (the module does not export it; it may change without notice).
 * The desktop demo: a window around a {@link dev.trisect.view.TrisectView}, with
 * menus, a status bar, opening models, screenshots and the endurance check. It uses the view through
 * its public API alone, as any program may.
 */
package dev.trisect.ui;
