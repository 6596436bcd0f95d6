#pragma once
// Binary range encoder (FORMAT.md, "Range coder"): 32-bit range, byte-wise
// output with carry propagation (the LZMA scheme without its leading zero
// byte), and a termination that writes as few bytes as possible: the final
// value is the number with the most trailing zero bits inside the last
// interval, and trailing zero bytes are dropped because the decoder reads
// zeros past the end of a frame.
#include <cstdint>
#include <vector>

#include "adaptive_bit.hpp"
#include "model_journal.hpp"

namespace fw::codec {

class RangeEncoder {
 public:
  RangeEncoder() = default;
  /// An encoder that appends its bytes straight to `out` (finish_into),
  /// without a buffer of its own to allocate and copy, and notes every model
  /// it adapts in `journal` when one is given.
  explicit RangeEncoder(std::vector<std::uint8_t>& out, ModelJournal* journal = nullptr)
      : out_(&out), start_(out.size()), journal_(journal) {}
  // It points into itself (bytes_) or at the caller's vector: not copied.
  RangeEncoder(const RangeEncoder&) = delete;
  RangeEncoder& operator=(const RangeEncoder&) = delete;

  /// Codes `bit` (0 or 1) with `model`'s probability, then adapts the model.
  void encode(AdaptiveBit& model, int bit);
  /// Codes the low `count` bits of `value` (0 .. 24 bits), most significant
  /// first, each with probability 1/2.
  void encode_raw(std::uint32_t value, int count);
  /// Terminates the code and appends its bytes to `out`. The encoder must
  /// not be used afterwards.
  void finish(std::vector<std::uint8_t>& out);
  /// The same for an encoder made on `out`: its bytes are there already.
  void finish_into();

  /// Bits written so far, including the bytes still held for carries; an
  /// estimate within 1 byte of what finish() appends.
  std::size_t bits_so_far() const;

 private:
  void shift_low();
  void normalise();

  std::uint64_t low_ = 0;             ///< bottom of the interval; bit 32 is a pending carry
  std::uint32_t range_ = 0xFFFFFFFFu;  ///< width of the interval, >= 2^24 between symbols
  std::uint8_t cache_ = 0;            ///< last byte out of the window, still subject to a carry
  bool has_cache_ = false;
  std::uint32_t pending_ff_ = 0;      ///< 0xFF bytes after the cache, also subject to a carry
  std::vector<std::uint8_t> bytes_;
  std::vector<std::uint8_t>* out_ = &bytes_;  ///< where bytes go: bytes_, or the caller's vector
  std::size_t start_ = 0;                     ///< out_'s size before this code began
  ModelJournal* journal_ = nullptr;
};

}  // namespace fw::codec
