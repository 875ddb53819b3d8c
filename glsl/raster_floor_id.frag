#version 450 core
// Raster floors (renderer/passes/raster_floors.h): what the visibility raster writes per fragment (an
// R32UI id), with no per-triangle work behind it.
layout(location = 0) out uint o_triangle;

void main() { o_triangle = 1u; }
