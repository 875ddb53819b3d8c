// An integer hash (PCG output permutation), mirrored in C++ by ml::hashToUnitFloat.
uint pcgHash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}
// In [0, 1), using the top 24 bits so the conversion to float is exact.
float hashToUnitFloat(uint v) { return float(pcgHash(v) >> 8u) * (1.0 / 16777216.0); }
