#version 450 core
// The compute raster's fill-rule probe (renderer/passes/compute_raster.cpp): in a 4x4 viewport, a
// rectangle from x = 1 to 2 and y = 1.5 to 2.5 in window coordinates, whose bottom and top edges
// run through the centres of rows 1 and 2. Which row it covers tells which edge the GPU owns.
const vec2 kCorners[6] = vec2[](vec2(-0.5, -0.25), vec2(0.0, -0.25), vec2(0.0, 0.25), vec2(-0.5, -0.25), vec2(0.0, 0.25),
                                vec2(-0.5, 0.25));
void main() { gl_Position = vec4(kCorners[gl_VertexID], 0.0, 1.0); }
