#pragma once
// The data that flows from tokens through productions into the semantic
// routines: an integer, a real number, a piece of text, or nothing.
#include <cstdint>
#include <string>

#include "fw/script/diagnostic.hpp"

namespace fw::script {

enum class ValueKind : unsigned char { none, integer, real, text };

/// Sets of value kinds, as bit masks: what a nonterminal can give, what a
/// routine parameter accepts.
using ValueKinds = unsigned char;
constexpr ValueKinds kinds_of(ValueKind kind) { return static_cast<ValueKinds>(1u << static_cast<unsigned>(kind)); }
inline constexpr ValueKinds kDataKinds = kinds_of(ValueKind::integer) | kinds_of(ValueKind::real) | kinds_of(ValueKind::text);

struct SemanticValue {
  ValueKind kind = ValueKind::none;
  std::int64_t integer = 0;
  double real = 0.0;
  std::string text;
  SourcePosition position;  ///< where the value was written

  /// The value as a number: an integer converts; anything else is 0.
  double number() const { return kind == ValueKind::integer ? static_cast<double>(integer) : real; }

  static SemanticValue of_integer(std::int64_t v, SourcePosition at) {
    SemanticValue value;
    value.kind = ValueKind::integer;
    value.integer = v;
    value.position = at;
    return value;
  }
  static SemanticValue of_real(double v, SourcePosition at) {
    SemanticValue value;
    value.kind = ValueKind::real;
    value.real = v;
    value.position = at;
    return value;
  }
  static SemanticValue of_text(std::string v, SourcePosition at) {
    SemanticValue value;
    value.kind = ValueKind::text;
    value.text = std::move(v);
    value.position = at;
    return value;
  }
  static SemanticValue nothing(SourcePosition at) {
    SemanticValue value;
    value.position = at;
    return value;
  }
};

}  // namespace fw::script
