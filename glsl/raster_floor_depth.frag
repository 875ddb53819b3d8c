#version 450 core
// Raster floors (renderer/raster_floors.h): depth only, no colour output.
void main() {}
