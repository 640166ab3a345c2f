#pragma once
// CacheLineAllocator<T>: an allocator whose blocks start on a cache line and fill whole lines.
// Per-thread buffers that threads write robot by robot (a strip's candidates) must
// never share a line with another thread's: two small vectors from the same heap are often
// neighbours, and every push_back then moves the line between the cores. Measured with the
// decision ceiling (bench/exploration/decision_ceiling.hpp, 10^4 robots on 1024^2, 2 threads):
// 0.99x one thread with plain vectors, 1.9x with these.
#include <cstddef>
#include <cstdint>
#include <new>

namespace swarmcheck::impl::exploration {

inline constexpr std::size_t kCacheLine = 64;

template <class T>
struct CacheLineAllocator {
  using value_type = T;
  CacheLineAllocator() = default;
  template <class U>
  CacheLineAllocator(const CacheLineAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    return static_cast<T*>(::operator new(rounded(n), std::align_val_t{kCacheLine}));
  }
  // The unsized aligned delete: the sized one is not declared where sized deallocation is off
  // (clang before 16, which builds the fuzz targets).
  void deallocate(T* p, std::size_t) noexcept { ::operator delete(p, std::align_val_t{kCacheLine}); }

  template <class U>
  bool operator==(const CacheLineAllocator<U>&) const noexcept { return true; }

 private:
  static std::size_t rounded(std::size_t n) {
    if (n > (SIZE_MAX - kCacheLine) / sizeof(T)) throw std::bad_array_new_length();
    return (n * sizeof(T) + kCacheLine - 1) / kCacheLine * kCacheLine;
  }
};

}  // namespace swarmcheck::impl::exploration
