#include "face_options.hpp"

#include <charconv>
#include <sstream>

#include "fw/model/expressions.hpp"

namespace fw::client {
namespace {

bool parse_double(std::string_view text, double& value) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size();
}

// Splits "NAME=VALUE" with VALUE a number in [0,1].
bool split_assignment(const std::string& item, const char* flag, std::string& name, float& value, std::string& error) {
  const auto equals = item.find('=');
  double v = 0;
  if (equals == std::string::npos || !parse_double(std::string_view(item).substr(equals + 1), v) || v < 0 || v > 1) {
    error = std::string(flag) + " takes NAME=VALUE with VALUE from 0 to 1, not '" + item + "'";
    return false;
  }
  name = item.substr(0, equals);
  value = static_cast<float>(v);
  return true;
}

}  // namespace

bool apply_emotions(const std::vector<std::string>& items, codec::FaceParams& params, std::string& error) {
  for (const std::string& item : items) {
    std::string name;
    float intensity = 0;
    if (!split_assignment(item, "--emotion", name, intensity, error)) return false;
    const auto expression = model::expression_from_name(name);
    if (!expression) {
      std::ostringstream known;
      for (auto n : model::kExpressionNames) known << " " << n;
      error = "unknown emotion '" + name + "'; choose one of:" + known.str();
      return false;
    }
    model::apply_expression(*expression, intensity, params);
  }
  return true;
}

bool apply_action_units(const std::vector<std::string>& items, codec::FaceParams& params, std::string& error) {
  for (const std::string& item : items) {
    std::string name;
    float intensity = 0;
    if (!split_assignment(item, "--au", name, intensity, error)) return false;
    codec::AuSide side = codec::AuSide::both;
    if (!name.empty() && (name.back() == 'L' || name.back() == 'R')) {
      side = name.back() == 'L' ? codec::AuSide::left : codec::AuSide::right;
      name.pop_back();
    }
    double number = 0;
    const int au = parse_double(name, number) ? static_cast<int>(number) : -1;
    if (codec::au_channel(au, codec::is_bilateral(au) ? codec::AuSide::left : codec::AuSide::both) < 0) {
      error = "--au: AU '" + name + "' is not one facewire carries (1 2 4 5 6 7 9 10 12 14 15 17 20 23 24 25 26 27)";
      return false;
    }
    if (side != codec::AuSide::both && !codec::is_bilateral(au)) {
      error = "--au: AU " + name + " acts on the midline; it has no left or right";
      return false;
    }
    if (side == codec::AuSide::both) params.set_au(au, intensity);
    else params.au[static_cast<std::size_t>(codec::au_channel(au, side))] = intensity;
  }
  return true;
}

bool apply_blush(const std::vector<std::string>& items, codec::FaceParams& params, std::string& error) {
  using codec::ColourRegion;
  const auto set = [&](ColourRegion r, float v) { params.blush[static_cast<std::size_t>(r)] = v; };
  for (const std::string& item : items) {
    std::string name;
    float value = 0;
    if (!split_assignment(item, "--blush", name, value, error)) return false;
    if (name == "cheeks") {
      set(ColourRegion::cheek_left, value);
      set(ColourRegion::cheek_right, value);
      continue;
    }
    bool known = false;
    for (std::size_t r = 0; r < codec::kColourRegionCount; ++r)
      if (codec::kColourRegionNames[r] == name) set(static_cast<ColourRegion>(r), value), known = true;
    if (!known) {
      error = "--blush: unknown region '" + name + "'; choose forehead, cheek_left, cheek_right, cheeks, nose or sides";
      return false;
    }
  }
  return true;
}

bool parse_numbers(const std::string& text, std::vector<double>& values, std::string& error) {
  std::size_t start = 0;
  for (double& v : values) {
    const std::size_t comma = text.find(',', start);
    const std::string_view part = std::string_view(text).substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (!parse_double(part, v) || (comma == std::string::npos) != (&v == &values.back())) {
      error = "expected " + std::to_string(values.size()) + " numbers separated by commas, not '" + text + "'";
      return false;
    }
    start = comma + 1;
  }
  return true;
}

}  // namespace fw::client
