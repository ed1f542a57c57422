/**
 * <b>API.</b> The embeddable view: {@link dev.trisect.view.TrisectView}, a Swing component that
 * renders a scene on a thread of its own, with camera controls, the developer tools, frame listeners
 * and commands to put in menus; and {@link dev.trisect.view.ViewFrame}, a window around one view for
 * the quick case. The only API package that uses Swing; the look and feel is left to the program.
 */
package dev.trisect.view;
