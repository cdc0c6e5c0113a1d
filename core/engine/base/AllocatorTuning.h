// The process's malloc set for interactive editing: the same few large
// blocks (CHOLMOD's and Eigen's factors, a part's arrays) are allocated and
// freed on every stroke, cut and preview rebuild. glibc maps each block of
// at least its mmap threshold afresh from the kernel and unmaps it when
// freed, so every call pays the page faults of fresh memory again; by
// default it raises that threshold to the largest such block freed so far,
// which makes the cost depend on what ran before (docs/ARCHITECTURE.md,
// "Sketch to part, session 14": camel_body 17.1 or 19.4 ms for the same
// work). A fixed threshold of 4 MiB, and freed memory returned to the
// kernel only above 64 MiB at the heap's top, keep such blocks in the heap.
// Called first thing in the studio's, the command line's and every
// benchmark's main(), so the benchmarks measure what the studio runs.
#pragma once

namespace rigmesh {

// A no-op where the C library is not glibc.
void tuneAllocatorForEditing();

}  // namespace rigmesh
