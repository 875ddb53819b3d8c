// The part of the screen the glass's capture keeps a word per pixel for
// (renderer/passes/glass_fragments.h): the whole screen tiles around the transparent ranges'
// projected bounds. Its rasters are scissored to it, so no fragment falls outside.
uniform uvec4 u_glassWindow;  // xy: its first pixel (a multiple of ML_SCREEN_TILE), zw: its size in pixels

uint glassWindowPixels() { return u_glassWindow.z * u_glassWindow.w; }

// Pixel p's word (p inside the window): row by row across the window.
uint glassPixel(ivec2 p) {
    uvec2 q = uvec2(p) - u_glassWindow.xy;
    return q.y * u_glassWindow.z + q.x;
}
