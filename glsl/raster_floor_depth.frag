#version 450 core
// Raster floors (renderer/passes/raster_floors.h): depth only, no colour output.
void main() {}
