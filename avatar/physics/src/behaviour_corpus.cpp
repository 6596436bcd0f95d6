#include "fw/physics/behaviour_corpus.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

#include "fw/model/file_io.hpp"

namespace fw::physics {
namespace {

constexpr int kSteps = 1000;  // thousandths: finer than the codec's 1/256
constexpr std::size_t kMaxNameBytes = 64;

int to_steps(float v) { return std::isfinite(v) ? static_cast<int>(std::lround(std::clamp(v, 0.0f, 1.0f) * kSteps)) : 0; }

bool valid_name(std::string_view name) {
  return !name.empty() && name.size() <= kMaxNameBytes && std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
  });
}

// One frame line: "." or channel:value pairs separated by spaces.
bool read_frame(std::string_view line, std::array<int, codec::kAuChannelCount>& steps, std::string& why) {
  if (line == ".") return true;
  while (!line.empty()) {
    const std::size_t end = std::min(line.find(' '), line.size());
    const std::string_view pair = line.substr(0, end);
    line.remove_prefix(std::min(end + 1, line.size()));
    if (pair.empty()) continue;
    const std::size_t colon = pair.find(':');
    unsigned channel = 0;
    int value = 0;
    const char* a = pair.data();
    const char* colon_at = a + (colon == std::string_view::npos ? pair.size() : colon);
    const auto c = std::from_chars(a, colon_at, channel);
    const auto v = colon == std::string_view::npos ? std::from_chars_result{a, std::errc::invalid_argument}
                                                   : std::from_chars(colon_at + 1, a + pair.size(), value);
    // Appended, not concatenated: GCC 12 warns (-Wrestrict) wrongly on "..." + std::string.
    std::string shown("\"");
    shown.append(pair).append("\"");
    if (c.ec != std::errc{} || c.ptr != colon_at || v.ec != std::errc{} || v.ptr != a + pair.size()) {
      why = shown + " is not channel:thousandths";
      return false;
    }
    if (channel >= codec::kAuChannelCount || value < 0 || value > kSteps) {
      why = shown + ": channels are 0.." + std::to_string(codec::kAuChannelCount - 1) +
            ", values 0.." + std::to_string(kSteps);
      return false;
    }
    steps[channel] = value;
  }
  return true;
}

}  // namespace

std::size_t BehaviourCorpus::frame_count() const {
  std::size_t n = 0;
  for (const CorpusSequence& s : sequences) n += s.frames.size();
  return n;
}

std::string write_behaviour_corpus(const BehaviourCorpus& corpus) {
  std::ostringstream out;
  out << "# facewire behaviour corpus: action-unit targets at 30 Hz (FaceParams channel order),\n"
         "# one frame a line: the channels that changed, channel:thousandths, or '.'\n";
  for (const CorpusSequence& s : corpus.sequences) {
    out << "sequence " << s.name << "\n";
    std::array<int, codec::kAuChannelCount> last{};
    for (const AuFrame& frame : s.frames) {
      bool any = false;
      for (std::size_t c = 0; c < frame.size(); ++c) {
        const int v = to_steps(frame[c]);
        if (v == last[c]) continue;
        out << (any ? " " : "") << c << ":" << v;
        last[c] = v;
        any = true;
      }
      out << (any ? "\n" : ".\n");
    }
  }
  return out.str();
}

bool read_behaviour_corpus(std::string_view text, BehaviourCorpus& corpus, std::string& error) {
  if (text.size() > kMaxCorpusBytes) {
    error = "the corpus is larger than " + std::to_string(kMaxCorpusBytes) + " bytes";
    return false;
  }
  BehaviourCorpus read;
  std::array<int, codec::kAuChannelCount> steps{};
  std::size_t frames = 0, line_number = 0;
  while (!text.empty()) {
    const std::size_t end = std::min(text.find('\n'), text.size());
    std::string_view line = text.substr(0, end);
    text.remove_prefix(std::min(end + 1, text.size()));
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const auto fail = [&](const std::string& why) {
      error = "corpus line " + std::to_string(line_number) + ": " + why;
      return false;
    };
    if (line.empty() || line.front() == '#') continue;
    if (line.starts_with("sequence ")) {
      const std::string_view name = line.substr(9);
      if (!valid_name(name)) return fail("a sequence's name is 1 to 64 letters, digits, '-' or '_'");
      if (read.sequences.size() == kMaxCorpusSequences)
        return fail("more than " + std::to_string(kMaxCorpusSequences) + " sequences");
      read.sequences.push_back({std::string(name), {}});
      steps.fill(0);
      continue;
    }
    if (read.sequences.empty()) return fail("a frame before the first \"sequence NAME\" line");
    if (++frames > kMaxCorpusFrames) return fail("more than " + std::to_string(kMaxCorpusFrames) + " frames");
    std::string why;
    if (!read_frame(line, steps, why)) return fail(why);
    AuFrame frame;
    for (std::size_t c = 0; c < frame.size(); ++c) frame[c] = static_cast<float>(steps[c]) / kSteps;
    read.sequences.back().frames.push_back(frame);
  }
  for (const CorpusSequence& s : read.sequences)
    if (s.frames.empty()) {
      error = "corpus sequence " + s.name + " has no frames";
      return false;
    }
  corpus = std::move(read);
  return true;
}

bool load_behaviour_corpus(const std::string& path, BehaviourCorpus& corpus, std::string& error) {
  std::vector<std::uint8_t> bytes;
  if (!model::read_file(path, kMaxCorpusBytes, bytes, error)) return false;
  if (read_behaviour_corpus(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), corpus, error))
    return true;
  error = path + ": " + error;
  return false;
}

}  // namespace fw::physics
