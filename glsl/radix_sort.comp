#version 450 core
// One pass of a stable least-significant-digit radix sort of (key, value) uint pairs, on the
// 8-bit digit (key >> u_shift) & 255. Each workgroup owns a block of ML_RADIX_WORKGROUP x
// ML_RADIX_ROUNDS consecutive elements:
//   ML_RADIX_HISTOGRAM  counts the block's digits into histograms[digit * blocks + block]
//   [the host runs an exclusive prefix sum over the whole digit-major array: each (digit, block)
//    then holds where that block's elements of that digit go]
//   ML_RADIX_SCATTER    writes each element to its place. Rounds of one element per thread, in
//                       order; within a round an element's rank among equal digits comes from a
//                       bit per thread in shared memory (popcount of the lower threads' bits),
//                       so equal keys keep their order: the sort is stable.
#include "include/bindings.h"

#if ML_RADIX_WORKGROUP != 256
#error "one thread per 8-bit digit: ML_RADIX_WORKGROUP must be 256"
#endif
layout(local_size_x = ML_RADIX_WORKGROUP) in;
layout(std430, binding = ML_SSBO_RADIX_KEYS_IN) readonly buffer KeysIn { uint keysIn[]; };
layout(std430, binding = ML_SSBO_RADIX_VALUES_IN) readonly buffer ValuesIn { uint valuesIn[]; };
layout(std430, binding = ML_SSBO_RADIX_KEYS_OUT) writeonly buffer KeysOut { uint keysOut[]; };
layout(std430, binding = ML_SSBO_RADIX_VALUES_OUT) writeonly buffer ValuesOut { uint valuesOut[]; };
layout(std430, binding = ML_SSBO_RADIX_HISTOGRAMS) buffer Histograms { uint histograms[]; };

uniform uint u_count;
uniform uint u_shift;

const uint kRadix = 256u;
const uint kWords = ML_RADIX_WORKGROUP / 32u;  // match bits per digit

uint digitOf(uint key) { return (key >> u_shift) & (kRadix - 1u); }

#if defined(ML_RADIX_HISTOGRAM)
shared uint s_counts[kRadix];

void main() {
    uint t = gl_LocalInvocationID.x;
    uint block = gl_WorkGroupID.x;
    s_counts[t] = 0u;
    barrier();
    uint base = block * ML_RADIX_WORKGROUP * ML_RADIX_ROUNDS;
    for (uint r = 0u; r < ML_RADIX_ROUNDS; ++r) {
        uint i = base + r * ML_RADIX_WORKGROUP + t;
        if (i < u_count) atomicAdd(s_counts[digitOf(keysIn[i])], 1u);
    }
    barrier();
    histograms[t * gl_NumWorkGroups.x + block] = s_counts[t];
}

#elif defined(ML_RADIX_SCATTER)
shared uint s_next[kRadix];            // next destination of each digit in this block
shared uint s_match[kRadix * kWords];  // per digit, one bit per thread holding it this round

void main() {
    uint t = gl_LocalInvocationID.x;
    uint block = gl_WorkGroupID.x;
    s_next[t] = histograms[t * gl_NumWorkGroups.x + block];
    uint base = block * ML_RADIX_WORKGROUP * ML_RADIX_ROUNDS;
    for (uint r = 0u; r < ML_RADIX_ROUNDS; ++r) {
        for (uint w = 0u; w < kWords; ++w) s_match[t * kWords + w] = 0u;
        barrier();
        uint i = base + r * ML_RADIX_WORKGROUP + t;
        bool valid = i < u_count;
        uint key = valid ? keysIn[i] : 0u;
        uint digit = digitOf(key);
        if (valid) atomicOr(s_match[digit * kWords + t / 32u], 1u << (t & 31u));
        barrier();
        uint rank = 0u, total = 0u;
        if (valid) {
            for (uint w = 0u; w < kWords; ++w) {
                uint bits = s_match[digit * kWords + w];
                total += bitCount(bits);
                if (w < t / 32u) rank += bitCount(bits);
            }
            rank += bitCount(s_match[digit * kWords + t / 32u] & ((1u << (t & 31u)) - 1u));
            uint dst = s_next[digit] + rank;
            keysOut[dst] = key;
            valuesOut[dst] = valuesIn[i];
        }
        barrier();  // every thread has read s_next and s_match
        if (valid && rank + 1u == total) s_next[digit] += total;  // the digit's last thread advances it
    }
}
#endif
