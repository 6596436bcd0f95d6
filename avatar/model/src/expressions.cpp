#include "fw/model/expressions.hpp"

#include <algorithm>
#include <array>

namespace fw::model {
namespace {

using codec::AuSide;
constexpr AuSide kBoth = AuSide::both;

// Motion cues (Expressive Textures, table in 3.2) realised with FACS units;
// anger follows the syntax-directed paper's sentence (AU 2, 4, 5, 7, 15, 17,
// 20, 23, 26, its intensities halved from its 0-2 scale; AU 42 is not carried).
const std::array<ExpressionDefinition, kExpressionCount> kDefinitions = {{
    // joy: mouth corners up, cheeks raised, eyes narrowed, lips a little apart
    {{{6, kBoth, 0.7f}, {12, kBoth, 1.0f}, {7, kBoth, 0.2f}, {25, kBoth, 0.3f}}},
    // sadness (melancholy): inner brows up, mouth corners down, chin raised
    {{{1, kBoth, 0.9f}, {4, kBoth, 0.35f}, {15, kBoth, 0.8f}, {17, kBoth, 0.4f}}, 0.15f},
    // anger: inner brows down, outer up, eyes wide and tight, lips pressed
    {{{2, kBoth, 0.5f}, {4, kBoth, 1.0f}, {5, kBoth, 0.6f}, {7, kBoth, 0.5f}, {15, kBoth, 0.6f}, {17, kBoth, 0.6f},
      {20, kBoth, 0.4f}, {23, kBoth, 0.15f}, {26, kBoth, 0.2f}}},
    // fear: inner brows up and drawn together, eyes wide, mouth stretched and open a little
    {{{1, kBoth, 0.8f}, {2, kBoth, 0.5f}, {4, kBoth, 0.4f}, {5, kBoth, 0.9f}, {20, kBoth, 0.7f}, {25, kBoth, 0.5f},
      {26, kBoth, 0.3f}}},
    // surprise: brows slide up, eyes wide open, jaw drops
    {{{1, kBoth, 0.9f}, {2, kBoth, 0.9f}, {5, kBoth, 0.8f}, {25, kBoth, 0.6f}, {26, kBoth, 0.8f}}},
    // disgust: nose wrinkled, upper lip raised, brows lowered, eyes narrowed
    {{{9, kBoth, 0.9f}, {10, kBoth, 0.7f}, {4, kBoth, 0.4f}, {7, kBoth, 0.3f}, {15, kBoth, 0.3f}, {17, kBoth, 0.3f}}},
    // cunning: lids nearly closed, mouth corners raised slightly
    {{{7, kBoth, 0.6f}, {12, kBoth, 0.35f}}, 0.45f},
    // teasing: a one-sided smile with a raised brow on the other side
    {{{12, AuSide::left, 0.85f}, {6, AuSide::left, 0.3f}, {14, AuSide::left, 0.3f}, {2, AuSide::right, 0.6f}}},
}};

void raise(codec::FaceParams& params, int channel, float value) {
  if (channel < 0) return;
  float& v = params.au[static_cast<std::size_t>(channel)];
  v = std::max(v, std::clamp(value, 0.0f, 1.0f));
}

}  // namespace

const ExpressionDefinition& expression_definition(Expression e) { return kDefinitions[static_cast<std::size_t>(e)]; }

std::optional<Expression> expression_from_name(std::string_view name) {
  for (std::size_t i = 0; i < kExpressionCount; ++i)
    if (kExpressionNames[i] == name) return static_cast<Expression>(i);
  return std::nullopt;
}

void apply_expression(Expression e, float intensity, codec::FaceParams& params) {
  intensity = std::clamp(intensity, 0.0f, 1.0f);
  const ExpressionDefinition& d = expression_definition(e);
  for (const ExpressionComponent& c : d.action_units) {
    if (!codec::is_bilateral(c.au)) {
      raise(params, codec::au_channel(c.au, AuSide::both), c.intensity * intensity);
      continue;
    }
    for (AuSide side : {AuSide::left, AuSide::right})
      if (c.side == kBoth || c.side == side) raise(params, codec::au_channel(c.au, side), c.intensity * intensity);
  }
  params.lid_left = std::max(params.lid_left, d.lid_closure * intensity);
  params.lid_right = std::max(params.lid_right, d.lid_closure * intensity);
}

}  // namespace fw::model
