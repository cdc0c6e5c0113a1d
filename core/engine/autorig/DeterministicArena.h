// Allocation in increasing address order, for CGAL code whose results
// depend on the order of pointers. CGAL's mean curvature flow keeps the
// edges to collapse and the disks it checks in std::sets ordered by element
// address (Mean_curvature_flow_skeletonization.h, Detect_degeneracy.h), so
// with the heap's addresses the same mesh gave different skeletons in a
// fresh process and in a long-running studio, and a recipe did not replay
// to the same document. Inside an arena's Scope, ArenaAllocator (which
// CurveSkeleton.cpp makes CGAL_ALLOCATOR) hands out memory from one
// reserved region front to back, so the order of addresses is the order of
// allocation, the same every run. Memory is given back when the arena goes.
#pragma once

#include <cstddef>
#include <memory>
#include <new>

namespace rigmesh {

class DeterministicArena {
  public:
    // Reserves `bytes` of address space (committed only as it is used).
    // Throws std::bad_alloc when the system refuses.
    explicit DeterministicArena(std::size_t bytes);
    ~DeterministicArena();
    DeterministicArena(const DeterministicArena&) = delete;
    DeterministicArena& operator=(const DeterministicArena&) = delete;

    // Throws std::bad_alloc when the region is used up.
    void* allocate(std::size_t bytes, std::size_t alignment);
    bool owns(const void* p) const;
    std::size_t used() const { return used_; }

    // The arena this thread allocates from (null outside every Scope).
    static DeterministicArena* current();
    // Makes `arena` current on this thread for the scope's lifetime.
    class Scope {
      public:
        explicit Scope(DeterministicArena& arena);
        ~Scope();
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;

      private:
        DeterministicArena* previous_;
    };

  private:
    char* base_ = nullptr;
    std::size_t size_ = 0, used_ = 0;
};

// std::allocator inside no Scope; the current arena inside one (freeing
// arena memory is a no-op: the arena frees it all at once).
template <class T>
struct ArenaAllocator {
    using value_type = T;
    ArenaAllocator() = default;
    template <class U>
    ArenaAllocator(const ArenaAllocator<U>&) {}
    template <class U>
    struct rebind {
        using other = ArenaAllocator<U>;
    };

    T* allocate(std::size_t n) {
        if (DeterministicArena* arena = DeterministicArena::current())
            return static_cast<T*>(arena->allocate(n * sizeof(T), alignof(T)));
        return std::allocator<T>().allocate(n);
    }
    void deallocate(T* p, std::size_t n) {
        DeterministicArena* arena = DeterministicArena::current();
        if (arena && arena->owns(p))
            return;
        std::allocator<T>().deallocate(p, n);
    }
    template <class U>
    bool operator==(const ArenaAllocator<U>&) const {
        return true;
    }
};

}  // namespace rigmesh
