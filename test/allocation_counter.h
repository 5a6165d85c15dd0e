#pragma once
/// \file
/// \brief Counts heap allocations in a test binary: include it in exactly one source file of the binary (it
///        replaces the global operator new and delete). Allocations are counted while g_counting is set.
#include <cstddef>
#include <cstdlib>
#include <new>

namespace {
bool g_counting = false;   ///< count while true
long g_allocations = 0;    ///< operator new calls while counting
}  // namespace

void* operator new(std::size_t size) {
  if (g_counting) ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
