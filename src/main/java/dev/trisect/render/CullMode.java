package dev.trisect.render;

/** Which triangles are dropped by facing; front faces run counter-clockwise as seen by the camera. */
public enum CullMode {
    /** Drop triangles seen from behind. */
    BACK,
    /** Draw both sides. */
    NONE
}
