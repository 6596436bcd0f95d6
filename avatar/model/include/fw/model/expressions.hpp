#pragma once
// Facial expressions as action-unit combinations (documented in
// avatar/model/EXPRESSIONS.md): the six primaries plus cunning and teasing.
#include <optional>
#include <string_view>
#include <vector>

#include "fw/codec/face_params.hpp"

namespace fw::model {

enum class Expression { joy, sadness, anger, fear, surprise, disgust, cunning, teasing, count };
inline constexpr std::size_t kExpressionCount = static_cast<std::size_t>(Expression::count);
inline constexpr std::string_view kExpressionNames[kExpressionCount] = {
    "joy", "sadness", "anger", "fear", "surprise", "disgust", "cunning", "teasing"};

struct ExpressionComponent {
  int au;               ///< FACS number
  codec::AuSide side;   ///< both for symmetric use
  float intensity;      ///< at expression intensity 1
};

struct ExpressionDefinition {
  std::vector<ExpressionComponent> action_units;
  float lid_closure = 0;  ///< both lids, at expression intensity 1
};

const ExpressionDefinition& expression_definition(Expression e);
std::optional<Expression> expression_from_name(std::string_view name);

/// Adds expression `e` at `intensity` (0..1) to `params`: each component's
/// AU intensity is raised to at least its share (expressions blend by max).
void apply_expression(Expression e, float intensity, codec::FaceParams& params);

}  // namespace fw::model
