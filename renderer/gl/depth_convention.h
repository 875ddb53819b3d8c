// The depth convention every pass shares: reversed depth. Window depth is 1 at the near plane
// and 0 at the far plane and where nothing is drawn, GL's clip depth spans [0, 1]
// (glClipControl, set where each context loads its functions), and a nearer surface has the
// greater depth. Perspective depth goes as near / distance and a float's steps shrink towards 0,
// so depth keeps about 24 bits of relative precision at every distance; with 1 at the far plane
// a step near 1 was 2.4 mm at 20 m under Sponza's near plane of 0.01, surfaces a few millimetres
// apart tied, and two rasters that round depth differently (the hardware's and the compute
// raster's) kept different surfaces there. The shaders' side: glsl/include/window_depth.glsl.
#pragma once

#include "renderer/gl/gl_api.h"

namespace ml::depth {

inline constexpr float kClear = 0.0f;          // the far plane, and the background
inline constexpr GLenum kNearer = GL_GREATER;  // the depth test that keeps the nearest surface

// Clears framebuffer fbo's depth to the background and turns on the test that keeps the nearest
// surface, with depth writes: what every pass that rasters the scene's depth starts with.
inline void beginNearestDepth(GLuint fbo) {
    glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &kClear);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(kNearer);
    glDepthMask(GL_TRUE);
}

// Clip depth in [0, 1], origin lower left: call once the context's functions are loaded.
inline void useReversedDepth() { glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE); }

}  // namespace ml::depth
