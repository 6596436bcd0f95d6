#pragma once
// Asks the memory for a whole object at once, ahead of its use. A server
// holds an encoder per avatar per subscriber and a client a decoder per
// avatar; thousands of their states fit no cache, and a frame reads a few
// dozen scattered lines of one, each a wait of its own when found one at a
// time. Asked for together they arrive together, as the memory streams
// them: with 10,000 states, an encoder's frame takes a tenth less time and
// a decoder's about a third less (facewire-bench fanout's sizes).
#include <cstddef>

namespace fw::codec {

/// Prefetches, for writing, the cache lines of `object`.
template <class T>
void prefetch_whole(const T& object) {
  constexpr std::size_t kCacheLine = 64;
  const char* bytes = reinterpret_cast<const char*>(&object);
  for (std::size_t i = 0; i < sizeof(T); i += kCacheLine) __builtin_prefetch(bytes + i, 1);
}

}  // namespace fw::codec
