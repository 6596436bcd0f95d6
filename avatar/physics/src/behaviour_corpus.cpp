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

constexpr int kMaxHeadMilliradians = static_cast<int>(kMaxCorpusHeadRad * 1000.0f);
constexpr const char* kHeadKeys[3] = {"yaw", "pitch", "roll"};

int to_milliradians(float v) {
  return std::isfinite(v) ? static_cast<int>(std::lround(std::clamp(v, -kMaxCorpusHeadRad, kMaxCorpusHeadRad) * 1000.0f)) : 0;
}

// A frame as the reader keeps it: thousandths of each channel, then the
// head's yaw, pitch and roll in milliradians.
struct FrameSteps {
  std::array<int, codec::kAuChannelCount> au{};
  std::array<int, 3> head{};
};

std::array<int, 3> head_steps(const HeadPose& h) {
  return {to_milliradians(h.yaw_rad), to_milliradians(h.pitch_rad), to_milliradians(h.roll_rad)};
}

// One frame line: "." or key:value pairs separated by spaces; a key is a
// channel's number or one of kHeadKeys.
bool read_frame(std::string_view line, FrameSteps& steps, bool& head_seen, std::string& why) {
  if (line == ".") return true;
  while (!line.empty()) {
    const std::size_t end = std::min(line.find(' '), line.size());
    const std::string_view pair = line.substr(0, end);
    line.remove_prefix(std::min(end + 1, line.size()));
    if (pair.empty()) continue;
    // Appended, not concatenated: GCC 12 warns (-Wrestrict) wrongly on "..." + std::string.
    std::string shown("\"");
    shown.append(pair).append("\"");
    const std::size_t colon = pair.find(':');
    const std::string_view key = pair.substr(0, colon);
    int value = 0;
    const char* value_end = pair.data() + pair.size();
    const auto v = colon == std::string_view::npos ? std::from_chars_result{value_end, std::errc::invalid_argument}
                                                   : std::from_chars(pair.data() + colon + 1, value_end, value);
    const bool value_ok = v.ec == std::errc{} && v.ptr == value_end;
    const auto head = std::find(std::begin(kHeadKeys), std::end(kHeadKeys), key);
    if (head != std::end(kHeadKeys)) {
      if (!value_ok || value < -kMaxHeadMilliradians || value > kMaxHeadMilliradians) {
        why = shown + ": the head's " + std::string(key) + " is milliradians, -" + std::to_string(kMaxHeadMilliradians) +
              ".." + std::to_string(kMaxHeadMilliradians);
        return false;
      }
      steps.head[static_cast<std::size_t>(head - std::begin(kHeadKeys))] = value;
      head_seen = true;
      continue;
    }
    unsigned channel = 0;
    const auto c = std::from_chars(key.data(), key.data() + key.size(), channel);
    if (c.ec != std::errc{} || c.ptr != key.data() + key.size() || !value_ok) {
      why = shown + " is not channel:thousandths (or yaw:, pitch:, roll: milliradians)";
      return false;
    }
    if (channel >= codec::kAuChannelCount || value < 0 || value > kSteps) {
      why = shown + ": channels are 0.." + std::to_string(codec::kAuChannelCount - 1) +
            ", values 0.." + std::to_string(kSteps);
      return false;
    }
    steps.au[channel] = value;
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
         "# one frame a line: the channels that changed, channel:thousandths, and the head's\n"
         "# turn if it changed, yaw:, pitch:, roll: milliradians; or '.'\n";
  for (const CorpusSequence& s : corpus.sequences) {
    out << "sequence " << s.name << "\n";
    FrameSteps last;
    for (std::size_t f = 0; f < s.frames.size(); ++f) {
      const AuFrame& frame = s.frames[f];
      bool any = false;
      for (std::size_t c = 0; c < frame.size(); ++c) {
        const int v = to_steps(frame[c]);
        if (v == last.au[c]) continue;
        out << (any ? " " : "") << c << ":" << v;
        last.au[c] = v;
        any = true;
      }
      const std::array<int, 3> head = head_steps(s.head(f));
      for (std::size_t k = 0; k < head.size(); ++k) {
        if (head[k] == last.head[k]) continue;
        out << (any ? " " : "") << kHeadKeys[k] << ":" << head[k];
        last.head[k] = head[k];
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
  FrameSteps steps;
  bool head_seen = false;  // in this sequence: else it keeps no head poses
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
      read.sequences.push_back({std::string(name), {}, {}});
      steps = {};
      head_seen = false;
      continue;
    }
    if (read.sequences.empty()) return fail("a frame before the first \"sequence NAME\" line");
    if (++frames > kMaxCorpusFrames) return fail("more than " + std::to_string(kMaxCorpusFrames) + " frames");
    std::string why;
    if (!read_frame(line, steps, head_seen, why)) return fail(why);
    CorpusSequence& sequence = read.sequences.back();
    AuFrame frame;
    for (std::size_t c = 0; c < frame.size(); ++c) frame[c] = static_cast<float>(steps.au[c]) / kSteps;
    sequence.frames.push_back(frame);
    // Head poses from the first frame that names one; upright before it.
    if (head_seen) {
      sequence.heads.resize(sequence.frames.size() - 1);
      sequence.heads.push_back({steps.head[0] / 1000.0f, steps.head[1] / 1000.0f, steps.head[2] / 1000.0f, {}});
    }
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
