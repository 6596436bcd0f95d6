#include "package_assembly_golden.hpp"

#include <cstdint>
#include <string>
#include <vector>

#include "package_assembler.hpp"

namespace fw::test::web_golden {
namespace {

using Quality = codec::PackageChunk::Quality;

// Runs the steps through one assembler, each add with its outcome.
class Run {
 public:
  explicit Run(std::string what) { json_["what"] = std::move(what); }

  Run& add(std::uint32_t avatar, Quality quality, std::uint32_t total, std::uint32_t offset,
           std::vector<std::uint8_t> data) {
    codec::PackageChunk chunk;
    chunk.avatar = avatar;
    chunk.quality = quality;
    chunk.total_bytes = total;
    chunk.offset = offset;
    chunk.data = data;
    std::string error;
    const auto done = assembler_.add(chunk, error);
    steps_.push_back({{"add",
                       {{"avatar", avatar},
                        {"quality", static_cast<int>(quality)},
                        {"total_bytes", total},
                        {"offset", offset},
                        {"data", data}}},
                      {"done", done ? nlohmann::json(done->bytes) : nlohmann::json(nullptr)},
                      {"done_avatar", done ? nlohmann::json(done->avatar) : nlohmann::json(nullptr)},
                      {"done_quality", done ? nlohmann::json(static_cast<int>(done->quality)) : nlohmann::json(nullptr)},
                      {"refused", !error.empty()}});
    return *this;
  }
  Run& forget(std::uint32_t avatar) {
    assembler_.forget(avatar);
    steps_.push_back({{"forget", avatar}});
    return *this;
  }
  nlohmann::json json() const {
    nlohmann::json out = json_;
    out["steps"] = steps_;
    return out;
  }

 private:
  client::PackageAssembler assembler_;
  nlohmann::json json_;
  nlohmann::json steps_ = nlohmann::json::array();
};

constexpr Quality kPreview = Quality::preview;
constexpr Quality kFull = Quality::full;

}  // namespace

nlohmann::json package_assembly_golden() {
  std::vector<Run> runs;
  runs.push_back(Run("three chunks in order")
                     .add(3, kPreview, 10, 0, {1, 2, 3, 4})
                     .add(3, kPreview, 10, 4, {5, 6, 7, 8})
                     .add(3, kPreview, 10, 8, {9, 10}));
  runs.push_back(Run("one chunk, then the same avatar's full package").add(3, kPreview, 3, 0, {7, 8, 9}).add(3, kFull, 2, 0, {1, 2}));
  runs.push_back(Run("two avatars and two qualities interleaved")
                     .add(1, kPreview, 4, 0, {1, 1})
                     .add(2, kPreview, 4, 0, {2, 2})
                     .add(1, kFull, 3, 0, {9})
                     .add(2, kPreview, 4, 2, {2, 2})
                     .add(1, kPreview, 4, 2, {1, 1})
                     .add(1, kFull, 3, 1, {9, 9}));
  runs.push_back(Run("the middle of a package whose start was missed")
                     .add(4, kPreview, 8, 4, {1, 2})
                     .add(4, kPreview, 8, 6, {3, 4})
                     .add(4, kPreview, 8, 0, {5, 6, 7, 8, 9, 10, 11, 12}));
  runs.push_back(Run("a gap drops the package; its rest is ignored until a new start")
                     .add(5, kFull, 12, 0, {1, 2, 3, 4})
                     .add(5, kFull, 12, 8, {9, 10, 11, 12})
                     .add(5, kFull, 12, 4, {5, 6, 7, 8})
                     .add(5, kFull, 2, 0, {1, 2}));
  runs.push_back(Run("a new start restarts the package")
                     .add(6, kPreview, 6, 0, {1, 2, 3})
                     .add(6, kPreview, 4, 0, {4, 3})
                     .add(6, kPreview, 4, 2, {2, 1}));
  runs.push_back(Run("another size midway is refused")
                     .add(7, kPreview, 6, 0, {1, 2, 3})
                     .add(7, kPreview, 7, 3, {4, 5, 6, 7})
                     .add(7, kPreview, 6, 3, {4, 5, 6}));
  runs.push_back(Run("past its end is refused")
                     .add(8, kPreview, 5, 0, {1, 2, 3, 4, 5, 6})
                     .add(8, kPreview, 5, 0, {1, 2, 3})
                     .add(8, kPreview, 5, 3, {4, 5, 6})
                     .add(8, kPreview, 5, 0, {1, 2, 3, 4, 5}));
  runs.push_back(Run("announced empty or larger than a package may be")
                     .add(9, kPreview, 0, 0, {})
                     .add(9, kPreview, client::kMaxAssembledBytes + 1, 0, {1})
                     .add(9, kFull, client::kMaxAssembledBytes, 0, {1, 2})
                     .add(9, kFull, client::kMaxAssembledBytes, 2, {3}));
  runs.push_back(Run("a refused announcement drops what was pending")
                     .add(10, kPreview, 4, 0, {1, 2})
                     .add(10, kPreview, 0, 2, {})
                     .add(10, kPreview, 4, 2, {3, 4}));
  runs.push_back(Run("empty chunks").add(11, kFull, 2, 0, {}).add(11, kFull, 2, 0, {}).add(11, kFull, 2, 0, {5, 6}));
  runs.push_back(Run("an avatar forgotten midway; others kept")
                     .add(12, kPreview, 4, 0, {1, 2})
                     .add(13, kPreview, 4, 0, {1, 2})
                     .add(12, kFull, 2, 0, {1})
                     .forget(12)
                     .add(12, kPreview, 4, 2, {3, 4})
                     .add(12, kFull, 2, 1, {2})
                     .add(13, kPreview, 4, 2, {3, 4}));
  nlohmann::json out;
  out["about"] =
      "client/room/package_assembler.cpp (PackageAssembler::add, forget), written by tests/web/golden; "
      "web/room/package_assembly.js must complete and refuse the same chunks (refusals' words are its own)";
  out["max_assembled_bytes"] = client::kMaxAssembledBytes;
  nlohmann::json list = nlohmann::json::array();
  for (const Run& run : runs) list.push_back(run.json());
  out["runs"] = list;
  return out;
}

}  // namespace fw::test::web_golden
