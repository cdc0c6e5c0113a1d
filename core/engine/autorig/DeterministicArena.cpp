#include "autorig/DeterministicArena.h"

#include <sys/mman.h>

namespace rigmesh {

namespace {

thread_local DeterministicArena* currentArena = nullptr;

}  // namespace

DeterministicArena::DeterministicArena(std::size_t bytes) : size_(bytes) {
    void* region = mmap(nullptr, bytes, PROT_READ | PROT_WRITE,
                        MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    if (region == MAP_FAILED)
        throw std::bad_alloc();
    base_ = static_cast<char*>(region);
}

DeterministicArena::~DeterministicArena() {
    munmap(base_, size_);
}

void* DeterministicArena::allocate(std::size_t bytes, std::size_t alignment) {
    const std::size_t start = (used_ + alignment - 1) / alignment * alignment;
    if (start + bytes > size_ || start + bytes < start)
        throw std::bad_alloc();
    used_ = start + bytes;
    return base_ + start;
}

bool DeterministicArena::owns(const void* p) const {
    const char* c = static_cast<const char*>(p);
    return c >= base_ && c < base_ + size_;
}

DeterministicArena* DeterministicArena::current() {
    return currentArena;
}

DeterministicArena::Scope::Scope(DeterministicArena& arena) : previous_(currentArena) {
    currentArena = &arena;
}

DeterministicArena::Scope::~Scope() {
    currentArena = previous_;
}

}  // namespace rigmesh
