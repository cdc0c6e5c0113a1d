#include "base/AllocatorTuning.h"

// Any C library header defines __GLIBC__ where the library is glibc.
#include <cstdlib>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace rigmesh {

void tuneAllocatorForEditing() {
#if defined(__GLIBC__)
    // Setting either threshold also turns off glibc's dynamic adjustment of
    // both (mallopt(3)).
    mallopt(M_MMAP_THRESHOLD, 4 << 20);
    mallopt(M_TRIM_THRESHOLD, 64 << 20);
#endif
}

}  // namespace rigmesh
