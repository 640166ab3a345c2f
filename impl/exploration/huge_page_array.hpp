#pragma once
// HugePageArray<T>: a fixed-size array of trivially copyable T in anonymous memory advised to
// use transparent huge pages. A robot's window spans rows a whole map-row apart; with 4 KiB
// pages every row is a TLB miss on big maps, with 2 MiB pages most are not. Allocated once.
#include <sys/mman.h>

#include <cstddef>
#include <new>
#include <type_traits>

namespace swarmcheck::impl::exploration {

template <class T>
class HugePageArray {
  static_assert(std::is_trivially_copyable_v<T>);
  static constexpr std::size_t kHugePage = std::size_t{2} << 20;

 public:
  HugePageArray() = default;
  HugePageArray(std::size_t n, const T& fill) : n_(n) {
    // Small arrays stay small: huge pages only pay off beyond a few of them.
    const std::size_t page = n * sizeof(T) >= 2 * kHugePage ? kHugePage : std::size_t{4096};
    bytes_ = (n * sizeof(T) + page - 1) / page * page;
    if (bytes_ == 0) return;
    void* p = ::mmap(nullptr, bytes_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    if (page == kHugePage) ::madvise(p, bytes_, MADV_HUGEPAGE);   // advice: without THP, plain memory
    data_ = static_cast<T*>(p);
    for (std::size_t k = 0; k < n; ++k) data_[k] = fill;
  }
  HugePageArray(const HugePageArray&) = delete;
  HugePageArray& operator=(const HugePageArray&) = delete;
  HugePageArray(HugePageArray&& o) noexcept { swap(o); }
  HugePageArray& operator=(HugePageArray&& o) noexcept {
    swap(o);
    return *this;
  }
  ~HugePageArray() {
    if (data_) ::munmap(data_, bytes_);
  }

  T& operator[](std::size_t k) { return data_[k]; }
  const T& operator[](std::size_t k) const { return data_[k]; }
  std::size_t size() const { return n_; }
  T* begin() { return data_; }
  T* end() { return data_ + n_; }

 private:
  void swap(HugePageArray& o) noexcept {
    std::swap(data_, o.data_);
    std::swap(n_, o.n_);
    std::swap(bytes_, o.bytes_);
  }
  T* data_ = nullptr;
  std::size_t n_ = 0;
  std::size_t bytes_ = 0;
};

}  // namespace swarmcheck::impl::exploration
