#pragma once
// The golden vectors of the codec (tests/vectors/codec): how each one is
// made (inputs, encoder options, what the transport does to the frames)
// and how a decoder plays it. make_vectors writes them; vectors_test checks
// that the committed files still encode byte for byte and decode value for
// value; the JavaScript decoder's tests (tests/codec/js) decode the same
// files. A change to any vector is a change of format version (FORMAT.md).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fw/codec/codec.hpp"

namespace fw::codec::vectors {

/// What happens to the stream of one vector, tick by tick.
struct VectorSpec {
  std::string name;
  std::string description;
  EncoderOptions options;
  bool room = false;                       ///< room frames carrying several avatars
  std::vector<std::vector<FaceParams>> inputs;  ///< [avatar][tick]
  std::vector<int> joins_at;               ///< [avatar]: tick of its first face (room vectors)
  std::map<int, double> target_changes;    ///< tick -> new target, every avatar
  std::vector<int> dropped_frames;         ///< indexes (in sending order) of frames the transport loses
  std::vector<int> duplicated_frames;      ///< ... and of frames it delivers twice
  bool resync = false;                     ///< a decoder that needs a key frame asks for one ...
  int resync_delay_ticks = 1;              ///< ... which the encoder hears this many ticks later
};

/// The vectors, built from the synthetic scene (deterministic).
std::vector<VectorSpec> vector_specs();

/// One delivered message of a vector stream.
struct Message {
  int tick = 0;
  std::vector<std::uint8_t> bytes;
};

/// Encodes `spec` as the server and transport would: the stream header,
/// then one message per sent frame (or room frame), with drops and
/// duplicates applied and resync requests answered.
std::vector<Message> encode_vector(const VectorSpec& spec);

/// Decodes a message list as a client would. For each tick: the errors of
/// that tick's messages, and every avatar's 53 field integers.
struct Decoded {
  std::vector<std::vector<std::string>> errors;   ///< [message] error names (one per avatar entry)
  std::vector<std::vector<QuantisedParams>> shown;  ///< [tick][avatar]
  std::vector<FaceParams> final_faces;            ///< [avatar] at the last tick
};
Decoded decode_vector(const VectorSpec& spec, const std::vector<Message>& messages);

/// The vector file pair: `<name>.fwc` (the messages, each as a LEB128
/// length and its bytes, with the tick of each message in the JSON) and
/// `<name>.json` (inputs, options, ticks, errors, expected values).
nlohmann::json to_json(const VectorSpec& spec, const std::vector<Message>& messages, const Decoded& decoded);
std::vector<std::uint8_t> to_stream_file(const std::vector<Message>& messages);
/// Splits a stream file; false if it is malformed.
bool from_stream_file(const std::vector<std::uint8_t>& file, std::vector<std::vector<std::uint8_t>>& messages);

/// The error-code vector: single messages and the code each must give.
nlohmann::json error_cases();

std::string error_name(DecodeError error);

}  // namespace fw::codec::vectors
