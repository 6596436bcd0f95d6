#include "fw/script/facs.hpp"

#include <array>
#include <utility>

#include "fw/codec/face_params.hpp"

namespace fw::script {
namespace {

constexpr std::array<std::pair<int, std::string_view>, 58> kNames = {{
    {1, "inner brow raiser"},   {2, "outer brow raiser"},     {4, "brow lowerer"},        {5, "upper lid raiser"},
    {6, "cheek raiser"},        {7, "lid tightener"},         {8, "lips toward each other"},
    {9, "nose wrinkler"},       {10, "upper lip raiser"},     {11, "nasolabial deepener"},
    {12, "lip corner puller"},  {13, "sharp lip puller"},     {14, "dimpler"},            {15, "lip corner depressor"},
    {16, "lower lip depressor"}, {17, "chin raiser"},         {18, "lip pucker"},         {19, "tongue show"},
    {20, "lip stretcher"},      {21, "neck tightener"},       {22, "lip funneler"},       {23, "lip tightener"},
    {24, "lip pressor"},        {25, "lips part"},            {26, "jaw drop"},           {27, "mouth stretch"},
    {28, "lip suck"},           {29, "jaw thrust"},           {30, "jaw sideways"},       {31, "jaw clencher"},
    {32, "lip bite"},           {33, "cheek blow"},           {34, "cheek puff"},         {35, "cheek suck"},
    {36, "tongue bulge"},       {37, "lip wipe"},             {38, "nostril dilator"},    {39, "nostril compressor"},
    {41, "lid droop"},          {42, "slit"},                 {43, "eyes closed"},        {44, "squint"},
    {45, "blink"},              {46, "wink"},                 {51, "head turn left"},     {52, "head turn right"},
    {53, "head up"},            {54, "head down"},            {55, "head tilt left"},     {56, "head tilt right"},
    {57, "head forward"},       {58, "head back"},            {61, "eyes turn left"},     {62, "eyes turn right"},
    {63, "eyes up"},            {64, "eyes down"},            {65, "walleye"},            {66, "cross-eye"},
}};

}  // namespace

std::string_view facs_action_unit_name(long long number) {
  for (const auto& [au, name] : kNames)
    if (au == number) return name;
  return {};
}

bool is_facs_action_unit(long long number) { return !facs_action_unit_name(number).empty(); }

bool is_carried_by_faces(long long au) {
  for (auto carried : codec::kActionUnits)
    if (carried == au) return true;
  return false;
}

std::string carried_action_units_text() {
  std::string out;
  for (auto au : codec::kActionUnits) out += (out.empty() ? "" : ", ") + std::to_string(au);
  return out;
}

std::string_view facs_ranges_text() { return "1-2, 4-39, 41-46, 51-58 and 61-66"; }

}  // namespace fw::script
