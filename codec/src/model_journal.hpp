#pragma once
// What a trial frame changed in the adaptive models, so that a frame the
// budget refuses can be taken back without the encoder copying all of its
// models (kilobytes) before every trial: a frame codes a few dozen bits, so
// keeping each touched model's old value is much cheaper than the copy.
#include <utility>
#include <vector>

#include "adaptive_bit.hpp"

namespace fw::codec {

class ModelJournal {
 public:
  /// Keeps `model`'s value before it adapts (RangeEncoder calls this).
  void note(AdaptiveBit& model) { entries_.emplace_back(&model, model); }
  /// Puts every noted model back as it was, newest change first, and forgets them.
  void undo() {
    for (auto it = entries_.rbegin(); it != entries_.rend(); ++it) *it->first = it->second;
    entries_.clear();
  }
  /// Keeps the changes (the frame went out).
  void clear() { entries_.clear(); }
  bool empty() const { return entries_.empty(); }

 private:
  std::vector<std::pair<AdaptiveBit*, AdaptiveBit>> entries_;
};

}  // namespace fw::codec
