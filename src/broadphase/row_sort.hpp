#pragma once
// Insertion sort of one short row of a pair list, on the host and the device alike: rows
// hold a handful of partners, and both backends must order them the same way.
#include "tridem/hd.hpp"

#include <cstdint>

namespace tridem {

template <class T, class Index>
TRIDEM_HD inline void insertion_sort(T* v, Index begin, Index end) {
  for (Index a = begin + 1; a < end; ++a) {
    const T key = v[a];
    Index b = a - 1;
    while (b >= begin && v[b] > key) {
      v[b + 1] = v[b];
      --b;
    }
    v[b + 1] = key;
  }
}

}  // namespace tridem
