#pragma once
// An allocator whose construct() without a value default-initialises the element (for
// integers: leaves it unwritten), so that resize() reserves memory without touching its
// pages. For arrays sized for the worst case and written before they are read: the CPU
// grid's cells (4 a particle, of which a scene uses a fraction) were zeroed at construction,
// 0.6 GB at 10^7 triangles on one core, for the set-up and for `tridem info`.
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace tridem {

template <class T, class Base = std::allocator<T>>
class DefaultInitAllocator : public Base {
  using Traits = std::allocator_traits<Base>;

 public:
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U, typename Traits::template rebind_alloc<U>>;
  };
  using Base::Base;

  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    Traits::construct(static_cast<Base&>(*this), p, std::forward<Args>(args)...);
  }
};

/// A vector whose resize() leaves new elements unwritten (see above).
template <class T>
using UnfilledVector = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace tridem
