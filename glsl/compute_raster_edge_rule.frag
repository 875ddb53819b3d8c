#version 450 core
// The fill-rule probe's coverage (compute_raster_edge_rule.vert).
layout(location = 0) out vec4 o_covered;
void main() { o_covered = vec4(1.0); }
