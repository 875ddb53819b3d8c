#version 450 core
// Exclusive prefix sum of uints, in place, in one dispatch: a chained scan with decoupled
// look-back (Merrill and Garland, "Single-pass Parallel Prefix Scan with Decoupled Look-back",
// 2016). Each workgroup takes the next block of kBlock elements in the order workgroups start
// (a ticket, not gl_WorkGroupID), scans it, and learns the sum of everything before it from the
// blocks before: each publishes its block's total as soon as it has it and its inclusive prefix
// once it has that, and a block adds totals backwards, kWindow blocks at a time, until it meets
// an inclusive prefix. It waits only on blocks that took their tickets earlier, which have
// started and so run, so it cannot deadlock however the GPU schedules workgroups. Elements at or
// past u_count are read as 0 and never written.
//
// ML_SCAN_BLOCK_BASES: no look-back. A block reserves its total's room by one atomic add and
// writes its elements' places from there, and where it starts, its base, at data[u_count + block]:
// the blocks follow one another in whatever order they finish. For a buffer whose readers find an
// element's start from the element before it in its block, or from the base for a block's first,
// it saves the look-back's chain of waits (the glass's per-pixel counts at 2560x1440: 900 blocks).
#include "include/bindings.h"

layout(local_size_x = ML_SCAN_WORKGROUP) in;
layout(std430, binding = ML_SSBO_SCAN_DATA) buffer ScanData { uint data[]; };

struct BlockState {
    uint flag;       // (u_epoch << 2) | kAggregate or kInclusive; anything else: not yet
    uint aggregate;  // the block's own total
    uint inclusive;  // the sum of everything up to the block's end
    uint unused;
};
// coherent: the blocks' sums pass between workgroups while they run.
layout(std430, binding = ML_SSBO_SCAN_BLOCKS) coherent buffer ScanState {
    uint ticket;  // tickets handed out, over every run (wrapping)
    // ML_SCAN_BLOCK_BASES: the room reserved so far and the blocks done, both left at 0 by the
    // last block done
    uint reserved;
    uint blocksDone;
    uint unused;
    BlockState blocks[];
};
// The sum of every element, at word u_totalWord: written by the last block, where the caller
// reads it (on an H200 a 4-byte buffer copy after the scan cost 3-4 us of a 17-us scan).
layout(std430, binding = ML_SSBO_SCAN_TOTAL) writeonly buffer ScanTotal { uint scanTotal[]; };
uniform uint u_totalWord;

uniform uint u_count;
uniform uint u_epoch;  // this run's number (1 to 2^30 - 1): earlier runs' flags are not this one's
uniform uint u_firstTicket;  // the ticket this run's first workgroup takes

const uint kPerInvocation = ML_SCAN_PER_INVOCATION;
const uint kBlock = ML_SCAN_WORKGROUP * kPerInvocation;
const uint kAggregate = 1u;
const uint kInclusive = 2u;
// Earlier blocks a look-back reads at once, an invocation each: a block adds up the totals of
// the blocks still running before it, a window at a time. On an H200 a window of 8 or 256 made
// a 2560x1440 screen's scan 0.006 or 0.03 ms slower than 32 (docs/bench/nvidia-h200/scan-lookback).
const uint kWindow = 32u;

shared uint s_block;
// The block, loaded and stored a workgroup-wide row at a time; a word skipped after every 32 so
// that the invocations' runs lie in different banks.
shared uint s_elements[kBlock + kBlock / 32u];
shared uint s_sums[ML_SCAN_WORKGROUP];
shared uint s_prefix;
shared uint s_firstPending;    // in the window: the nearest block not yet summed
shared uint s_firstInclusive;  // in the window: the nearest block with its inclusive prefix
shared uint s_windowSum;

uint padded(uint i) { return i + (i >> 5); }

uint flagOf(uint status) { return (u_epoch << 2) | status; }

// Every access to another block's sums is an atomic, so that no load or store passes the flag
// that orders it.
void publish(uint block, uint status, uint value) {
    if (status == kAggregate) atomicExchange(blocks[block].aggregate, value);
    else atomicExchange(blocks[block].inclusive, value);
    memoryBarrierBuffer();  // the value before the flag that says it is there
    atomicExchange(blocks[block].flag, flagOf(status));
}

// Adds to s_prefix the sum of every element before the block (> 0): earlier blocks' totals, back
// to the first inclusive prefix met. Block 0 publishes only that, so the walk ends there at the
// latest. Run by every invocation (it holds barriers).
void lookBack(uint block, uint t) {
    uint end = block;  // blocks [0, end) not yet counted
    for (;;) {
        if (t == 0u) {
            s_firstPending = kWindow;
            s_firstInclusive = kWindow;
            s_windowSum = 0u;
        }
        barrier();
        uint status = 0u, value = 0u;
        if (t < min(kWindow, end)) {
            uint j = end - 1u - t;
            uint flag = atomicOr(blocks[j].flag, 0u);
            memoryBarrierBuffer();  // the flag before the values it announces
            // Both read whatever the flag: on llvmpipe (Mesa 22.3) an atomic read only in the
            // branch the flag chose returned 0 now and then (PrefixSumRunsTest.ThousandsOfBlocks...).
            uint aggregate = atomicOr(blocks[j].aggregate, 0u);
            uint inclusive = atomicOr(blocks[j].inclusive, 0u);
            status = flag == flagOf(kInclusive) ? kInclusive : flag == flagOf(kAggregate) ? kAggregate : 0u;
            value = status == kInclusive ? inclusive : aggregate;
            if (status == 0u) atomicMin(s_firstPending, t);
            if (status == kInclusive) atomicMin(s_firstInclusive, t);
        }
        barrier();
        // Counted: the blocks before the nearest not yet summed, up to and with the nearest
        // inclusive one.
        bool reachedInclusive = s_firstInclusive < s_firstPending;
        uint counted = min(min(s_firstPending, s_firstInclusive + 1u), min(kWindow, end));
        if (t < counted) atomicAdd(s_windowSum, value);
        barrier();
        if (t == 0u) s_prefix += s_windowSum;
        end -= counted;
        barrier();
        if (reachedInclusive) return;
        // Otherwise on past the window's aggregates, or the same place again where a block has
        // not summed its elements yet.
    }
}

void main() {
    uint t = gl_LocalInvocationID.x;
    if (t == 0u) s_block = atomicAdd(ticket, 1u) - u_firstTicket;
    barrier();
    uint block = s_block;
    // A dispatch past the device's limit along x goes on in y, with a few workgroups spare.
    uint lastBlock = (u_count - 1u) / kBlock;
    if (block > lastBlock) return;

    // The block through shared memory, so that each load and store of the workgroup touches
    // consecutive words; each invocation sums a run of consecutive elements from there...
    uint blockFirst = block * kBlock;
    for (uint k = 0u; k < kPerInvocation; ++k) {
        uint i = blockFirst + k * ML_SCAN_WORKGROUP + t;
        s_elements[padded(k * ML_SCAN_WORKGROUP + t)] = i < u_count ? data[i] : 0u;
    }
    barrier();
    uint run = 0u;
    for (uint k = 0u; k < kPerInvocation; ++k) run += s_elements[padded(t * kPerInvocation + k)];
    // ...and the workgroup scans the runs' sums (inclusive, Hillis and Steele).
    s_sums[t] = run;
    barrier();
    for (uint offset = 1u; offset < ML_SCAN_WORKGROUP; offset <<= 1) {
        uint before = t >= offset ? s_sums[t - offset] : 0u;
        barrier();
        s_sums[t] += before;
        barrier();
    }

    uint blockTotal = s_sums[ML_SCAN_WORKGROUP - 1u];
#if defined(ML_SCAN_BLOCK_BASES)
    if (t == 0u) {
        s_prefix = atomicAdd(reserved, blockTotal);
        data[u_count + block] = s_prefix;
        memoryBarrierBuffer();  // the reservation before the count of blocks done
        if (atomicAdd(blocksDone, 1u) == lastBlock) {
            // Every block has reserved its room: the sum is final, and the next run starts at 0.
            scanTotal[u_totalWord] = atomicExchange(reserved, 0u);
            atomicExchange(blocksDone, 0u);
        }
    }
#else
    if (t == 0u) {
        s_prefix = 0u;
        publish(block, block == 0u ? kInclusive : kAggregate, blockTotal);
    }
    if (block > 0u) {
        lookBack(block, t);
        if (t == 0u) publish(block, kInclusive, s_prefix + blockTotal);
    }
    if (t == 0u && block == lastBlock) scanTotal[u_totalWord] = s_prefix + blockTotal;
#endif
    barrier();

    uint running = s_prefix + s_sums[t] - run;
    for (uint k = 0u; k < kPerInvocation; ++k) {
        uint value = s_elements[padded(t * kPerInvocation + k)];
        s_elements[padded(t * kPerInvocation + k)] = running;
        running += value;
    }
    barrier();
    for (uint k = 0u; k < kPerInvocation; ++k) {
        uint i = blockFirst + k * ML_SCAN_WORKGROUP + t;
        if (i < u_count) data[i] = s_elements[padded(k * ML_SCAN_WORKGROUP + t)];
    }
}
