#include "fw/script/script_builder.hpp"

namespace fw::script {

void ScriptBuilder::begin_sentence() {
  animation.reset();
  au_definition.reset();
  emotion.reset();
  vascular_expression.reset();
  sizes_ = {meaning.animations.size(), meaning.au_definitions.size(), meaning.vascular_expressions.size(),
            meaning.emotions.size()};
}

void ScriptBuilder::discard_sentence() {
  meaning.animations.resize(sizes_[0]);
  meaning.au_definitions.resize(sizes_[1]);
  meaning.vascular_expressions.resize(sizes_[2]);
  meaning.emotions.resize(sizes_[3]);
  animation.reset();
  au_definition.reset();
  emotion.reset();
  vascular_expression.reset();
}

std::string ScriptBuilder::unfinished() const {
  const char* what = nullptr;
  const char* closer = nullptr;
  if (animation) what = "an expression sentence", closer = "end_animation";
  else if (au_definition) what = "an AU definition", closer = "end_au_definition";
  else if (emotion) what = "an emotion", closer = "end_emotion";
  else if (vascular_expression) what = "a vascular expression", closer = "end_vascular_expression";
  if (!what) return {};
  return std::string("the sentence ended with ") + what + " still open and it was dropped; the grammar should bind " +
         closer + " to the production that ends the sentence";
}

}  // namespace fw::script
