// A four-face room holding a scripted conversation (three rounds of twelve
// turns, tests/data/conversations/lunch_talk.tsv), measured as the studies
// measured people (the table of conversation_gaze.hpp and face_scan.hpp): how much listeners look at the
// speaker and the speaker at its listeners, how long utterances begin,
// how long mutual gaze lasts, how large saccades are, how heads move.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fw/behavior/behavior_room.hpp"
#include "fw/speech/phoneme_timing.hpp"
#include "fw/speech/speech_track.hpp"
#include "test_paths.hpp"

namespace fw::behavior {
namespace {

constexpr float kRadiansPerDegree = 0.017453293f;

// The script (committed test data): who speaks, the pause after the
// previous line, the line. Each line is said with its espeak-ng lip-sync
// track, so utterances last what the server's do.
struct Line {
  FaceId speaker;
  double pause_s;
  std::string text;
};
std::vector<Line> script() {
  std::ifstream in(test::source_dir() + "/tests/data/conversations/lunch_talk.tsv");
  std::vector<Line> out;
  std::string row;
  while (std::getline(in, row)) {
    if (row.empty() || row[0] == '#') continue;
    const std::size_t a = row.find('\t'), b = row.find('\t', a + 1);
    if (a == std::string::npos || b == std::string::npos) continue;
    out.push_back({static_cast<FaceId>(std::stoi(row.substr(0, a))), std::stod(row.substr(a + 1, b - a - 1)), row.substr(b + 1)});
  }
  return out;
}

// The line's lip-sync track, as the server makes it (server/simulation/spoken_lines.cpp).
AuTrack mouth_track(const std::string& text) {
  speech::PhonemeTiming timing;
  std::string error;
  EXPECT_TRUE(speech::time_phonemes(text, "en", speech::SpeechLimits{}, timing, error)) << error;
  const speech::SpeechTrack track = speech::speech_track(timing);
  AuTrack mouth;
  for (std::size_t i = 0; i < track.keys.size(); ++i) mouth.times_s.push_back(static_cast<double>(i) * speech::SpeechTrack::kKeyStepS);
  mouth.poses.assign(track.keys.begin(), track.keys.end());
  return mouth;
}

struct Recording {
  std::vector<std::map<FaceId, std::optional<FaceId>>> looking_at;  // per tick
  std::vector<std::map<FaceId, YawPitch>> gaze;
  std::vector<std::map<FaceId, float>> head_yaw;
  std::vector<std::optional<FaceId>> speaker;  // who speaks at each tick
  std::vector<double> utterance_starts;
  std::vector<double> utterance_lengths;
  std::vector<FaceId> utterance_speakers;
  double dt = 0;
};

Recording record(std::uint64_t seed) {
  BehaviorRoomOptions o;
  o.seed = seed;
  o.seats = 4;
  BehaviorRoom room(o);
  for (FaceId id = 1; id <= 4; ++id) room.add(id, "face" + std::to_string(id));
  Recording r;
  r.dt = room.dt_s();
  const std::vector<Line> lines = script();
  EXPECT_EQ(lines.size(), 36u);
  std::size_t next = 0;
  double quiet_since = 3;  // the room settles before the first line
  for (int i = 0; next < lines.size() || i * r.dt < quiet_since + 3; ++i) {
    const double now = i * r.dt;
    bool anyone = false;
    for (FaceId id = 1; id <= 4; ++id) anyone = anyone || room.speaking(id);
    if (anyone) quiet_since = now;
    if (!anyone && next < lines.size() && now >= quiet_since + lines[next].pause_s) {
      const AuTrack mouth = mouth_track(lines[next].text);
      room.chat(lines[next].speaker, lines[next].text, &mouth);
      r.utterance_starts.push_back(now);
      r.utterance_lengths.push_back(mouth.times_s.empty() ? 0 : mouth.times_s.back());
      r.utterance_speakers.push_back(lines[next].speaker);
      ++next;
    }
    room.tick();
    std::map<FaceId, std::optional<FaceId>> at;
    std::map<FaceId, YawPitch> gaze;
    std::map<FaceId, float> head;
    std::optional<FaceId> speaking;
    for (FaceId id = 1; id <= 4; ++id) {
      at[id] = room.snapshot(id).looking_at;
      gaze[id] = room.gaze(id);
      head[id] = room.snapshot(id).head_yaw_rad;
      if (room.speaking(id)) speaking = id;
    }
    r.looking_at.push_back(at);
    r.gaze.push_back(gaze);
    r.head_yaw.push_back(head);
    r.speaker.push_back(speaking);
  }
  return r;
}

// The share of `v` for which `in` holds.
template <typename Predicate>
double share_of(const std::vector<double>& v, Predicate in) {
  return static_cast<double>(std::count_if(v.begin(), v.end(), in)) / static_cast<double>(std::max<std::size_t>(1, v.size()));
}

double median_of(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// The counts of several recorded rooms, pooled as a study pools its
// sessions before it reports a share.
struct Pooled {
  double listener_at_speaker = 0, listener_ticks = 0, speaker_at_listener = 0, speaker_ticks = 0;
  int long_lines = 0, begin_away = 0, big_moves = 0, bell = 0;
  int turns_watched = 0, turns_in_unison = 0;  ///< new speakers met by two listeners or more
  std::vector<double> mutual, amplitudes, reactions;
};

// Records the room of `seed`, prints its measures and adds its counts to `pooled`.
void measure_room(std::uint64_t seed, Pooled& pooled) {
  const Recording r = record(seed);
  std::printf("seed %llu: ", static_cast<unsigned long long>(seed));

  // Listeners at the speaker, the speaker at a listener, over the utterances.
  double listener_at_speaker = 0, listener_ticks = 0, speaker_at_listener = 0, speaker_ticks = 0;
  for (std::size_t t = 0; t < r.speaker.size(); ++t) {
    if (!r.speaker[t]) continue;
    const FaceId s = *r.speaker[t];
    for (FaceId id = 1; id <= 4; ++id) {
      if (id == s) {
        speaker_ticks += 1;
        speaker_at_listener += r.looking_at[t].at(id).has_value() ? 1 : 0;
      } else {
        listener_ticks += 1;
        listener_at_speaker += r.looking_at[t].at(id) == s ? 1 : 0;
      }
    }
  }
  const double listeners = listener_at_speaker / listener_ticks, speakers = speaker_at_listener / speaker_ticks;

  // Utterances over 2 s that begin with the speaker looking away: in their
  // first half second the speaker's gaze rests on no face most of the time.
  int long_lines = 0, begin_away = 0;
  for (std::size_t u = 0; u < r.utterance_starts.size(); ++u) {
    if (r.utterance_lengths[u] <= 2.0) continue;
    ++long_lines;
    const auto first = static_cast<std::size_t>(r.utterance_starts[u] / r.dt);
    int away = 0, ticks = 0;
    for (std::size_t t = first + 1; t < first + static_cast<std::size_t>(0.5 / r.dt) && t < r.looking_at.size(); ++t, ++ticks)
      away += r.looking_at[t].at(r.utterance_speakers[u]).has_value() ? 0 : 1;
    begin_away += 2 * away > ticks ? 1 : 0;
  }

  // Mutual gaze episodes: two faces looking at each other. As an eye
  // tracker counts looks (fixations of at least 100 ms; Salvucci & Goldberg
  // 2000), a look is not broken by a gap shorter than that (a saccade
  // between features of the face), and a gaze passing over a face during a
  // saccade, for less than that, is no look.
  const std::size_t bridge = static_cast<std::size_t>(0.1 / r.dt);
  const auto looks = [&](FaceId a, FaceId b) {
    std::vector<bool> on(r.looking_at.size());
    for (std::size_t t = 0; t < on.size(); ++t) on[t] = r.looking_at[t].at(a) == b;
    for (std::size_t t = 1; t < on.size(); ++t) {
      if (on[t] || !on[t - 1]) continue;
      std::size_t gap = t;
      while (gap < on.size() && !on[gap] && gap - t < bridge) ++gap;
      if (gap < on.size() && on[gap]) std::fill(on.begin() + static_cast<std::ptrdiff_t>(t), on.begin() + static_cast<std::ptrdiff_t>(gap), true);
    }
    for (std::size_t t = 0; t < on.size();) {
      std::size_t end = t;
      while (end < on.size() && on[end]) ++end;
      if (end > t && end - t < bridge) std::fill(on.begin() + static_cast<std::ptrdiff_t>(t), on.begin() + static_cast<std::ptrdiff_t>(end), false);
      t = end + 1;
    }
    return on;
  };
  std::vector<double> mutual;
  for (FaceId a = 1; a <= 4; ++a)
    for (FaceId b = a + 1; b <= 4; ++b) {
      const std::vector<bool> ab = looks(a, b), ba = looks(b, a);
      int run = 0;
      for (std::size_t t = 0; t <= ab.size(); ++t) {
        if (t < ab.size() && ab[t] && ba[t]) {
          ++run;
        } else if (run > 0) {
          mutual.push_back(run * r.dt);
          run = 0;
        }
      }
    }

  // Reaction to a new speaker: for each listener not already looking at
  // it, how long after the line begins the gaze shift that brings its
  // eyes there (within 2 s) starts: its first tick of motion.
  // Listeners in unison: every such listener of a line starts in one tick.
  const auto gaze_speed = [&](std::size_t t, FaceId id) {
    const YawPitch a = r.gaze[t - 1].at(id), b = r.gaze[t].at(id);
    return std::hypot(b.yaw_rad - a.yaw_rad, b.pitch_rad - a.pitch_rad) / r.dt;
  };
  std::vector<double> reactions;
  int turns_watched = 0, turns_in_unison = 0;
  for (std::size_t u = 0; u < r.utterance_starts.size(); ++u) {
    const auto first = static_cast<std::size_t>(r.utterance_starts[u] / r.dt);
    const FaceId speaker = r.utterance_speakers[u];
    std::vector<std::size_t> onsets;
    for (FaceId id = 1; id <= 4; ++id) {
      if (id == speaker || first == 0 || r.looking_at[first].at(id) == speaker) continue;
      std::size_t arrive = first;
      while (arrive < r.looking_at.size() && arrive < first + static_cast<std::size_t>(2 / r.dt) &&
             r.looking_at[arrive].at(id) != speaker)
        ++arrive;
      if (arrive >= r.looking_at.size() || r.looking_at[arrive].at(id) != speaker) continue;
      std::size_t onset = arrive;
      while (onset > first && gaze_speed(onset, id) > 30 * kRadiansPerDegree) --onset;
      onsets.push_back(onset);
      reactions.push_back(static_cast<double>(onset + 1 - first) * r.dt);  // its first tick of motion
    }
    if (onsets.size() < 2) continue;
    ++turns_watched;
    turns_in_unison += std::all_of(onsets.begin(), onsets.end(), [&](std::size_t o) { return o == onsets.front(); }) ? 1 : 0;
  }

  // Saccades: runs of ticks in which gaze moves faster than 30 deg/s; the
  // amplitude is where the run ends against where it began.
  std::vector<double> amplitudes;
  for (FaceId id = 1; id <= 4; ++id) {
    std::size_t start = 0;
    bool moving = false;
    for (std::size_t t = 1; t < r.gaze.size(); ++t) {
      const YawPitch a = r.gaze[t - 1].at(id), b = r.gaze[t].at(id);
      const bool fast = std::hypot(b.yaw_rad - a.yaw_rad, b.pitch_rad - a.pitch_rad) / r.dt > 30 * kRadiansPerDegree;
      if (fast && !moving) start = t - 1;
      if (!fast && moving) {
        const YawPitch s = r.gaze[start].at(id), e = r.gaze[t - 1].at(id);
        amplitudes.push_back(std::hypot(e.yaw_rad - s.yaw_rad, e.pitch_rad - s.pitch_rad) / kRadiansPerDegree);
      }
      moving = fast;
    }
  }
  const double small = share_of(amplitudes, [](double a) { return a < 12; });

  // Head moves over 10 degrees: runs of head-yaw velocity above 5 deg/s;
  // where in the run its speed peaks.
  int big_moves = 0, bell = 0;
  for (FaceId id = 1; id <= 4; ++id) {
    std::size_t start = 0;
    bool moving = false;
    for (std::size_t t = 1; t < r.head_yaw.size(); ++t) {
      const bool fast = std::abs(r.head_yaw[t].at(id) - r.head_yaw[t - 1].at(id)) / r.dt > 5 * kRadiansPerDegree;
      if (fast && !moving) start = t;
      if (!fast && moving) {
        const std::size_t end = t - 1;
        if (std::abs(r.head_yaw[end].at(id) - r.head_yaw[start - 1].at(id)) > 10 * kRadiansPerDegree && end > start) {
          ++big_moves;
          std::size_t peak = start;
          for (std::size_t k = start; k <= end; ++k)
            if (std::abs(r.head_yaw[k].at(id) - r.head_yaw[k - 1].at(id)) >
                std::abs(r.head_yaw[peak].at(id) - r.head_yaw[peak - 1].at(id)))
              peak = k;
          const double at = static_cast<double>(peak - start + 1) / static_cast<double>(end - start + 2);
          bell += at >= 0.25 && at <= 0.75 ? 1 : 0;
        }
      }
      moving = fast;
    }
  }

  {
    int under[5] = {0, 0, 0, 0, 0};
    for (double m : mutual) under[m < 0.1 ? 0 : m < 0.5 ? 1 : m < 1 ? 2 : m < 3 ? 3 : 4]++;
    std::printf("mutual: <0.1 %d, <0.5 %d, <1 %d, <3 %d, more %d\n", under[0], under[1], under[2], under[3], under[4]);
  }
  std::printf("listeners at the speaker %.0f %% (75 %%), speaker at a listener %.0f %% (41 %%), long utterances "
              "begun looking away %d of %d (> 70 %%), mutual gaze median %.2f s over %zu episodes (1-3 s), "
              "saccades under 12 deg %.0f %% of %zu (76 %% under 10), head moves peaking mid-move %d of %d\n",
              100 * listeners, 100 * speakers, begin_away, long_lines, median_of(mutual), mutual.size(), 100 * small,
              amplitudes.size(), bell, big_moves);
  pooled.listener_at_speaker += listener_at_speaker;
  pooled.listener_ticks += listener_ticks;
  pooled.speaker_at_listener += speaker_at_listener;
  pooled.speaker_ticks += speaker_ticks;
  pooled.long_lines += long_lines;
  pooled.begin_away += begin_away;
  pooled.big_moves += big_moves;
  pooled.bell += bell;
  pooled.mutual.insert(pooled.mutual.end(), mutual.begin(), mutual.end());
  pooled.reactions.insert(pooled.reactions.end(), reactions.begin(), reactions.end());
  pooled.turns_watched += turns_watched;
  pooled.turns_in_unison += turns_in_unison;
  pooled.amplitudes.insert(pooled.amplitudes.end(), amplitudes.begin(), amplitudes.end());
}

TEST(Conversation, GazeAndHeadsMoveAsPeoplesDo) {
  Pooled p;
  for (const std::uint64_t seed : {1u, 2u, 3u}) measure_room(seed, p);
  const double listeners = p.listener_at_speaker / p.listener_ticks, speakers = p.speaker_at_listener / p.speaker_ticks;
  const double small = share_of(p.amplitudes, [](double a) { return a < 12; });
  std::printf("pooled: listeners at the speaker %.0f %%, speaker at a listener %.0f %%, long utterances begun looking "
              "away %d of %d, mutual gaze median %.2f s over %zu episodes, saccades under 12 deg %.0f %% of %zu, head "
              "moves peaking mid-move %d of %d\n",
              100 * listeners, 100 * speakers, p.begin_away, p.long_lines, median_of(p.mutual), p.mutual.size(),
              100 * small, p.amplitudes.size(), p.bell, p.big_moves);
  std::printf("pooled: mutual gaze episodes of 1-3 s %.0f %%, saccades under 10 deg %.0f %%\n",
              100 * share_of(p.mutual, [](double m) { return m >= 1 && m <= 3; }),
              100 * share_of(p.amplitudes, [](double a) { return a < 10; }));
  std::printf("pooled: a new speaker met after a median %.2f s by %zu listeners; %d of %d turns met in unison\n",
              median_of(p.reactions), p.reactions.size(), p.turns_in_unison, p.turns_watched);
  EXPECT_GE(listeners, 0.60);
  EXPECT_LE(listeners, 0.90);
  EXPECT_GE(speakers, 0.25);
  EXPECT_LE(speakers, 0.60);
  ASSERT_GT(p.long_lines, 15);
  EXPECT_GE(p.begin_away, 0.6 * p.long_lines);
  // Mutual gaze in episodes of about 1-3 s (Argyle & Ingham 1972: mean
  // 1.18 s; Rogers et al. 2018: about 2.2 s).
  EXPECT_GE(median_of(p.mutual), 1.0);
  EXPECT_LE(median_of(p.mutual), 3.0);
  EXPECT_GE(small, 0.60);
  // A saccade's latency, 150-250 ms (Carpenter 1988), each listener its own.
  ASSERT_GT(p.reactions.size(), 30u);
  EXPECT_GE(median_of(p.reactions), 0.15);
  EXPECT_LE(median_of(p.reactions), 0.30);
  ASSERT_GT(p.turns_watched, 10);
  EXPECT_LE(p.turns_in_unison, p.turns_watched / 2);
  ASSERT_GT(p.big_moves, 15);
  EXPECT_GE(p.bell, 0.8 * p.big_moves);
}


}  // namespace
}  // namespace fw::behavior
