#include "range_encoder.hpp"

#include <cassert>

namespace fw::codec {

void RangeEncoder::shift_low() {
  if (low_ < 0xFF000000u || low_ > 0xFFFFFFFFu) {
    const auto carry = static_cast<std::uint8_t>(low_ >> 32);
    if (has_cache_) out_->push_back(static_cast<std::uint8_t>(cache_ + carry));
    // Without a cache the value is below 1.0 and no carry can reach here.
    for (; pending_ff_ > 0; --pending_ff_) out_->push_back(static_cast<std::uint8_t>(0xFF + carry));
    cache_ = static_cast<std::uint8_t>((low_ >> 24) & 0xFF);
    has_cache_ = true;
  } else {
    ++pending_ff_;  // 0xFF: a later carry would turn it into 0x00, so hold it
  }
  low_ = (low_ & 0x00FFFFFFu) << 8;
}

void RangeEncoder::normalise() {
  while (range_ < (1u << 24)) {
    range_ <<= 8;
    shift_low();
  }
}

void RangeEncoder::encode(AdaptiveBit& model, int bit) {
  const std::uint32_t bound = (range_ >> kProbabilityBits) * model.p0;
  if (bit == 0) {
    range_ = bound;
  } else {
    low_ += bound;
    range_ -= bound;
  }
  if (journal_ != nullptr) journal_->note(model);
  model.update(bit);
  normalise();
}

void RangeEncoder::encode_raw(std::uint32_t value, int count) {
  assert(count >= 0 && count <= 24);
  for (int i = count - 1; i >= 0; --i) {
    const std::uint32_t half = range_ >> 1;
    if ((value >> i) & 1u) {
      low_ += half;
      range_ -= half;
    } else {
      range_ = half;
    }
    normalise();
  }
}

void RangeEncoder::finish(std::vector<std::uint8_t>& out) {
  assert(out_ == &bytes_);
  finish_into();
  out.insert(out.end(), bytes_.begin(), bytes_.end());
  bytes_.clear();
}

void RangeEncoder::finish_into() {
  // Any value in [low, low + range) decodes the same symbols; take the one
  // with the most trailing zero bits so that its tail is zero bytes to drop.
  const std::uint64_t last = low_ + range_ - 1;
  for (int k = 32; k >= 0; --k) {
    const std::uint64_t mask = (std::uint64_t{1} << k) - 1;
    const std::uint64_t value = (low_ + mask) & ~mask;
    if (value <= last) {
      low_ = value;
      break;
    }
  }
  for (int i = 0; i < 5; ++i) shift_low();  // the cache, held 0xFFs and the 4 window bytes
  while (out_->size() > start_ && out_->back() == 0) out_->pop_back();
}

std::size_t RangeEncoder::bits_so_far() const {
  // Emitted bytes + held bytes, plus the bits the interval width has consumed
  // inside the 32-bit window (32 - log2(range)).
  int window_bits = 0;
  for (std::uint32_t r = range_; r < 0x80000000u; r <<= 1) ++window_bits;
  return 8 * (out_->size() - start_ + (has_cache_ ? 1 : 0) + pending_ff_) + static_cast<std::size_t>(window_bits);
}

}  // namespace fw::codec
