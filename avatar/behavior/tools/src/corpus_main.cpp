// facewire-corpus: records the behaviour corpus of avatar/physics/corpus/,
// the action-unit targets and head turns a room's behaviour gives the
// physics face, on which facewire-correctives fits the corrective basis.
// Two parts, made
// from different seeds, expressions and lines, so that one can be fitted
// on and the other held out:
//   - each primary expression a person asks for (BehaviorRoom::express) at
//     two intensities, its onset and offset as the behaviour shapes them,
//     in a room of two whose autonomy runs meanwhile;
//   - conversations: three faces chatting, the lines nudging their moods,
//     each face's spontaneous displays, mimicry and listening.
// Deterministic: the same build writes the same files.
#include <cstdio>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "fw/behavior/behavior_room.hpp"
#include "fw/model/file_io.hpp"
#include "fw/physics/behaviour_corpus.hpp"

namespace {

using fw::behavior::BehaviorRoom;
using fw::physics::BehaviourCorpus;
using fw::physics::CorpusSequence;

constexpr int kTickHz = 30;
constexpr const char* kPrimaries[] = {"joy", "sadness", "anger", "fear", "surprise", "disgust"};

// What the room gives a face's physics this tick: its targets, and its
// head's turn, which loads its tissue (speech's articulation is shown as the
// track has it, not through the tissue: articulation.hpp).
void record(const BehaviorRoom& room, fw::behavior::FaceId id, CorpusSequence& s) {
  s.frames.push_back(room.face(id).au);
  s.heads.push_back(fw::model::head_pose(room.face(id)));
}

BehaviorRoom room_of(int faces, std::uint64_t seed) {
  fw::behavior::BehaviorRoomOptions options;
  options.seed = seed;
  options.tick_hz = kTickHz;
  BehaviorRoom room(options);
  for (int i = 1; i <= faces; ++i) room.add(static_cast<fw::behavior::FaceId>(i), "face-" + std::to_string(i));
  return room;
}

// A primary expression asked of face 1 after a second of the room's own
// behaviour, held `hold_s`, recorded until two seconds after it ends.
CorpusSequence expression(std::string_view emotion, float intensity, double hold_s, std::uint64_t seed) {
  BehaviorRoom room = room_of(2, seed);
  CorpusSequence s{std::string(emotion) + "-" + std::to_string(static_cast<int>(intensity * 100)), {}, {}};
  const int ticks = static_cast<int>((1.0 + hold_s + 2.0) * kTickHz);
  for (int t = 0; t < ticks; ++t) {
    if (t == kTickHz) room.express(1, emotion, intensity, hold_s);
    room.tick();
    record(room, 1, s);
  }
  return s;
}

// Three faces chatting for `seconds`: every `interval_s` the next face says
// the next line. One sequence per face.
std::vector<CorpusSequence> conversation(const std::vector<std::string>& lines, double seconds, double interval_s,
                                         std::uint64_t seed, const std::string& name) {
  constexpr int kFaces = 3;
  BehaviorRoom room = room_of(kFaces, seed);
  std::vector<CorpusSequence> out(kFaces);
  for (int f = 0; f < kFaces; ++f) out[static_cast<std::size_t>(f)].name = name + "-face" + std::to_string(f + 1);
  const int ticks = static_cast<int>(seconds * kTickHz), every = static_cast<int>(interval_s * kTickHz);
  for (int t = 0, said = 0; t < ticks; ++t) {
    if (t % every == every / 2) {
      room.chat(static_cast<fw::behavior::FaceId>(1 + said % kFaces), lines[static_cast<std::size_t>(said) % lines.size()]);
      ++said;
    }
    room.tick();
    for (int f = 0; f < kFaces; ++f) record(room, static_cast<fw::behavior::FaceId>(f + 1), out[static_cast<std::size_t>(f)]);
  }
  return out;
}

BehaviourCorpus fitting_part() {
  BehaviourCorpus corpus;
  std::uint64_t seed = 101;
  for (float intensity : {1.0f, 0.5f})
    for (const char* e : kPrimaries) corpus.sequences.push_back(expression(e, intensity, 1.5, seed++));
  const std::vector<std::string> lines = {
      "hahaha that is great, really great :)", "oh no, that is so sad", "what?! no way!",
      "ugh, that is disgusting", "i am so angry about this", "hello everyone, nice to see you",
      "hmm, i am not sure", "that scares me a bit", "wow, really? amazing!", "well, fine, whatever"};
  for (auto& s : conversation(lines, 60.0, 2.5, 7, "conversation-a")) corpus.sequences.push_back(std::move(s));
  return corpus;
}

BehaviourCorpus held_out_part() {
  BehaviourCorpus corpus;
  std::uint64_t seed = 901;
  for (const char* e : kPrimaries) corpus.sequences.push_back(expression(e, 0.75f, 1.0, seed++));
  const std::vector<std::string> lines = {
      "lol you are hilarious :D", "i miss them so much", "seriously?! how could they",
      "eww, gross", "good morning, how are you all", "this makes me furious", "oh, a surprise party!",
      "i am afraid it will not work"};
  for (auto& s : conversation(lines, 30.0, 3.0, 19, "conversation-b")) corpus.sequences.push_back(std::move(s));
  return corpus;
}

bool write(const std::string& path, const BehaviourCorpus& corpus) {
  const std::string text = fw::physics::write_behaviour_corpus(corpus);
  std::string error;
  if (fw::model::write_file_atomically(path, text, error)) {
    std::cout << "wrote " << path << ": " << corpus.sequences.size() << " sequences, " << corpus.frame_count()
              << " frames\n";
    return true;
  }
  std::cerr << "facewire-corpus: " << error << "\n";
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Record the behaviour corpus the physics face's corrective basis is fitted on"};
  std::string directory;
  app.add_option("-o,--output", directory, "directory to write fitting.txt and held_out.txt into")->required();
  CLI11_PARSE(app, argc, argv);
  return write(directory + "/fitting.txt", fitting_part()) && write(directory + "/held_out.txt", held_out_part()) ? 0 : 1;
}
