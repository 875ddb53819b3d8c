#version 450 core
// Depth pre-pass: depth is all this pass writes.
void main() {}
