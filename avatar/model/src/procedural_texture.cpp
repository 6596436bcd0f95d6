#include "fw/model/procedural_texture.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <span>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "fw/model/head_back.hpp"
#include "fw/model/head_shell.hpp"

namespace fw::model {
namespace {

namespace lm = landmarks;

glm::vec2 landmark(int i) { return landmark_template()[static_cast<std::size_t>(i)]; }

// Deterministic value noise in [0,1]: the same face always gets the same skin.
float hash(int x, int y) {
  std::uint32_t h = static_cast<std::uint32_t>(x) * 374761393u + static_cast<std::uint32_t>(y) * 668265263u;
  h = (h ^ (h >> 13)) * 1274126177u;
  return static_cast<float>((h ^ (h >> 16)) & 0xffffu) / 65535.0f;
}

float value_noise(glm::vec2 p) {
  const glm::vec2 i = glm::floor(p);
  const glm::vec2 f = p - i;
  const glm::vec2 s = f * f * (3.0f - 2.0f * f);
  const int x = static_cast<int>(i.x), y = static_cast<int>(i.y);
  const float a = hash(x, y), b = hash(x + 1, y), c = hash(x, y + 1), d = hash(x + 1, y + 1);
  return glm::mix(glm::mix(a, b, s.x), glm::mix(c, d, s.x), s.y);
}

float distance_to_segment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
  const glm::vec2 ab = b - a;
  const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
  return glm::length(p - (a + t * ab));
}

// Distance to the polyline through landmarks [begin, end), with the position
// along it in [0,1] (for features that taper).
float distance_to_polyline(glm::vec2 p, int begin, int end, float* along = nullptr) {
  float best = 1e9f;
  for (int i = begin; i + 1 < end; ++i) {
    const float d = distance_to_segment(p, landmark(i), landmark(i + 1));
    if (d < best) {
      best = d;
      if (along) *along = static_cast<float>(i - begin) / static_cast<float>(end - begin - 1);
    }
  }
  return best;
}

bool inside(glm::vec2 p, int begin, int end) {
  bool in = false;
  for (int i = begin, j = end - 1; i < end; j = i++) {
    const glm::vec2 a = landmark(i), b = landmark(j);
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

// 1 well inside a feature of soft width `edge`, 0 outside.
float soft_inside(float distance_outside, float edge) {
  return std::clamp(0.5f - distance_outside / edge, 0.0f, 1.0f);
}

void put(RgbaImage& image, int x, int y, glm::vec3 rgb, float alpha) {
  std::uint8_t* px = image.at(x, y);
  const glm::vec3 c = glm::clamp(rgb, 0.0f, 1.0f) * 255.0f + 0.5f;
  px[0] = static_cast<std::uint8_t>(c.r);
  px[1] = static_cast<std::uint8_t>(c.g);
  px[2] = static_cast<std::uint8_t>(c.b);
  px[3] = static_cast<std::uint8_t>(std::clamp(alpha, 0.0f, 1.0f) * 255.0f + 0.5f);
}

// A soft bump of height 1 at `centre`, falling off over `radii`.
float blob(glm::vec2 p, glm::vec2 centre, glm::vec2 radii) {
  const glm::vec2 d = (p - centre) / radii;
  return std::exp(-glm::dot(d, d));
}

// The light a face's relief keeps from its own hollows, painted into the
// skin as a portrait painter or a game's baked ambient occlusion would: the
// mesh is low-polygon, and without it a procedural face reads as a flat
// mask (eye sockets, the sides and underside of the nose, the crease of the
// upper lid, the fold from nose to mouth, the hollow under the lower lip).
// A factor on the skin's colour: under 1 in a hollow, a little over 1 where
// a ridge (cheekbone, nose tip) catches the light.
float relief_shade(glm::vec2 p) {
  const float ax = std::abs(p.x);  // the face is symmetric
  const glm::vec2 q(ax, p.y);
  float shade = 1.0f;
  // The eye socket: the hollow between brow and upper lid, deepest toward
  // the nose, and the lighter one under the lower lid.
  shade -= 0.16f * blob(q, {0.42f, 0.16f}, {0.26f, 0.09f});
  shade -= 0.06f * blob(q, {0.47f, -0.13f}, {0.22f, 0.07f});
  // The upper lid's crease, a thin line parallel to the lid's upper edge.
  const float lid_top = 0.075f * std::sqrt(std::max(0.0f, 1.0f - ((ax - 0.49f) / 0.23f) * ((ax - 0.49f) / 0.23f)));
  if (ax > 0.26f && ax < 0.72f)
    shade -= 0.14f * std::exp(-std::pow((p.y - (lid_top + 0.055f)) / 0.018f, 2.0f));
  // The nose: its sides in shadow, its underside darker, its tip and the
  // bridge a little lit.
  shade -= 0.12f * blob(q, {0.17f, -0.42f}, {0.06f, 0.25f});
  shade -= 0.2f * blob(q, {0.07f, -0.8f}, {0.12f, 0.035f});
  shade += 0.06f * blob(q, {0.0f, -0.56f}, {0.07f, 0.08f});
  shade += 0.025f * blob(q, {0.0f, -0.2f}, {0.05f, 0.2f});
  // The fold from the nose's wing toward the mouth's corner, faint.
  const float fold = distance_to_segment(q, {0.3f, -0.74f}, {0.5f, -1.08f});
  shade -= 0.07f * std::exp(-(fold / 0.035f) * (fold / 0.035f));
  // The hollow under the lower lip, and the cheekbones catching the light.
  shade -= 0.12f * blob(q, {0.0f, -1.38f}, {0.2f, 0.05f});
  shade += 0.03f * blob(q, {0.68f, -0.3f}, {0.2f, 0.12f});
  return shade;
}

glm::vec3 skin_colour(glm::vec2 p, const Appearance& look) {
  glm::vec3 c = look.skin * (0.96f + 0.035f * value_noise(p * 24.0f) + 0.05f * value_noise(p * 6.0f));
  // Warmer cheeks and nose tip, darker toward the ears and under the jaw.
  // The warmth is faint and wide: a strong, narrow one read as two pink
  // discs painted on, as if the face blushed all the time (a blush is the
  // vascular layer's, when something causes it).
  const glm::vec3 flush(0.035f, -0.012f, -0.008f);
  c += flush * std::exp(-glm::dot(p - glm::vec2(-0.7f, -0.55f), p - glm::vec2(-0.7f, -0.55f)) / 0.14f);
  c += flush * std::exp(-glm::dot(p - glm::vec2(0.7f, -0.55f), p - glm::vec2(0.7f, -0.55f)) / 0.14f);
  c += flush * 0.7f * std::exp(-glm::dot(p - glm::vec2(0.0f, -0.58f), p - glm::vec2(0.0f, -0.58f)) / 0.03f);
  c *= 1.0f - 0.22f * std::clamp((std::abs(p.x) - 0.95f) / 0.45f, 0.0f, 1.0f);
  c *= 1.0f - 0.2f * std::clamp((-1.75f - p.y) / 0.3f, 0.0f, 1.0f);
  return c * relief_shade(p);
}

// Hair above the hairline (an arc like the mesh outline, a little lower so
// hair frames the forehead) with strands of noise.
float hair_cover(glm::vec2 p) {
  const float across = std::clamp(p.x / 1.18f, -1.0f, 1.0f);
  const float hairline_y = 0.22f + std::sqrt(1.0f - across * across);
  const float strands = 0.06f * (value_noise(glm::vec2(p.x * 30.0f, p.y * 3.0f)) - 0.5f);
  float cover = soft_inside(hairline_y + strands - p.y, 0.05f);
  // Hair at the temples, beyond the face outline above the ears. It thins
  // out downward over a long, sloping edge (lower toward the back of the
  // head, as hair falls behind the ear): a short level one read as a hard
  // horizontal step at the temples, and the strands break it up.
  const float behind = std::max(0.0f, std::abs(p.x) - 1.1f);
  const float temple = soft_inside(1.1f - std::abs(p.x), 0.1f) *
                       std::clamp((p.y + 0.25f + 2.5f * behind + 2.0f * strands) / 0.6f, 0.0f, 1.0f);
  cover = std::max(cover, temple);
  return cover;
}

// Where each feature can colour a texel: its landmarks' bounding box grown
// by the farthest reach of its soft edge. Outside, the feature's cover is
// exactly 0, so skipping it there changes no texel; inside the box the
// distances are worked out as before. (The demo faces are drawn whenever a
// server starts, and the distances to every polyline at every texel were
// most of that time.)
struct Box {
  glm::vec2 low, high;
  bool contains(glm::vec2 p) const { return p.x >= low.x && p.y >= low.y && p.x <= high.x && p.y <= high.y; }
};

Box box_around(int begin, int end, float reach) {
  Box box{landmark(begin), landmark(begin)};
  for (int i = begin + 1; i < end; ++i) {
    box.low = glm::min(box.low, landmark(i));
    box.high = glm::max(box.high, landmark(i));
  }
  box.low -= reach;
  box.high += reach;
  return box;
}

struct FeatureBoxes {
  // Lips reach 0.01 past their outline (soft edge 0.02), brows 0.0575 from
  // their line (half width 0.045, soft edge 0.025) drawn 0.015 lower, lashes
  // 0.018 from the lid. Each box adds a margin on top.
  Box lips = box_around(lm::kOuterLipBegin, lm::kOuterLipEnd, 0.03f);
  Box brow_right = box_around(lm::kBrowRightBegin, lm::kBrowRightEnd, 0.1f);
  Box brow_left = box_around(lm::kBrowLeftBegin, lm::kBrowLeftEnd, 0.1f);
  Box eye_right = box_around(lm::kEyeRightBegin, lm::kEyeRightEnd, 0.04f);
  Box eye_left = box_around(lm::kEyeLeftBegin, lm::kEyeLeftEnd, 0.04f);
};

glm::vec3 face_colour(glm::vec2 p, const Appearance& look, const FeatureBoxes& boxes) {
  glm::vec3 c = skin_colour(p, look);

  // Lips, a little darker at their inner line, with a soft outer edge.
  if (boxes.lips.contains(p)) {
    const float to_lip_edge = std::min(distance_to_polyline(p, lm::kOuterLipBegin, lm::kOuterLipEnd),
                                       distance_to_segment(p, landmark(lm::kOuterLipEnd - 1), landmark(lm::kOuterLipBegin)));
    const float lip_cover =
        soft_inside(inside(p, lm::kOuterLipBegin, lm::kOuterLipEnd) ? -to_lip_edge : to_lip_edge, 0.02f);
    if (lip_cover > 0.0f) {
      const float inner = distance_to_polyline(p, lm::kInnerLipBegin, lm::kInnerLipEnd);
      // The upper lip faces down and away from the light, the lower one up
      // toward it (a soft sheen along its middle).
      const bool upper = p.y > landmark(62).y;
      const float facing = upper ? 0.82f : 1.0f + 0.08f * blob(p, {0.0f, -1.2f}, {0.18f, 0.03f});
      c = glm::mix(c, look.lips * facing * (0.75f + 0.25f * std::min(1.0f, inner / 0.05f)), 0.85f * lip_cover);
    }
  }
  // Brows, thick at the inner end and tapering outward, with hair texture.
  struct Brow { int begin, end; bool inner_first; const Box& box; };
  for (const Brow brow : {Brow{lm::kBrowRightBegin, lm::kBrowRightEnd, false, boxes.brow_right},
                          Brow{lm::kBrowLeftBegin, lm::kBrowLeftEnd, true, boxes.brow_left}}) {
    const auto& [begin, end, inner_first, box] = brow;
    if (!box.contains(p)) continue;
    float along = 0;
    const float d = distance_to_polyline(p + glm::vec2(0.0f, -0.015f), begin, end, &along);
    const float from_inner = inner_first ? along : 1.0f - along;
    const float half_width = 0.045f - 0.025f * from_inner;
    const float cover = soft_inside(d - half_width, 0.025f) * (0.7f + 0.3f * value_noise(p * 90.0f));
    c = glm::mix(c, look.hair * 0.8f, cover);
  }
  // Lashes: a dark line along each upper lid, a lighter one along the lower.
  for (const int begin : {lm::kEyeRightBegin, lm::kEyeLeftBegin}) {
    if (!(begin == lm::kEyeRightBegin ? boxes.eye_right : boxes.eye_left).contains(p)) continue;
    // The upper lashes thicken toward the outer corner, as real ones do
    // (and as an eye's outline is drawn to read at a distance): a thin even
    // line made the eyes look small.
    float along = 0.0f;
    const float upper = distance_to_polyline(p, begin, begin + 4, &along);
    const float from_outer = begin == lm::kEyeRightBegin ? along : 1.0f - along;
    const float lash_width = 0.02f - 0.01f * from_outer;
    c = glm::mix(c, glm::vec3(0.08f, 0.06f, 0.05f), soft_inside(upper - lash_width, 0.012f));
    const glm::vec2 lower[] = {landmark(begin + 3), landmark(begin + 4), landmark(begin + 5), landmark(begin)};
    float d_lower = 1e9f;
    for (int i = 0; i < 3; ++i) d_lower = std::min(d_lower, distance_to_segment(p, lower[i], lower[i + 1]));
    c = glm::mix(c, c * 0.6f, soft_inside(d_lower - 0.006f, 0.01f));
  }
  // Nostrils.
  for (const float sign : {-1.0f, 1.0f}) {
    const glm::vec2 d = (p - glm::vec2(sign * 0.11f, -0.71f)) / glm::vec2(0.055f, 0.028f);
    c = glm::mix(c, c * 0.35f, soft_inside(glm::length(d) - 1.0f, 0.6f));
  }
  return glm::mix(c, look.hair, hair_cover(p));
}

}  // namespace

RgbaImage make_skin_texture(const GenericFace& face, const Appearance& look, int size, bool eye_holes) {
  assert(size >= 16);
  RgbaImage image(size, size);
  const FeatureBoxes boxes;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::vec2 uv((static_cast<float>(x) + 0.5f) / static_cast<float>(size),
                         1.0f - (static_cast<float>(y) + 0.5f) / static_cast<float>(size));
      const glm::vec2 p = face.texture_frame.to_model(uv);
      const bool in_eye = (boxes.eye_right.contains(p) && inside(p, lm::kEyeRightBegin, lm::kEyeRightEnd)) ||
                          (boxes.eye_left.contains(p) && inside(p, lm::kEyeLeftBegin, lm::kEyeLeftEnd));
      if (in_eye && !eye_holes) {
        // A closed lid: skin, with the lash line where the lids meet.
        const float lash = std::abs(p.y - (landmark(lm::kEyeRightBegin).y - 0.03f));
        put(image, x, y, glm::mix(skin_colour(p, look) * 0.92f, glm::vec3(0.1f), soft_inside(lash - 0.008f, 0.01f)), 1.0f);
        continue;
      }
      put(image, x, y, face_colour(p, look, boxes), in_eye ? 0.0f : 1.0f);
    }
  // The generic face is its own fit, with the generic outline.
  std::vector<glm::vec2> own_xy;
  for (const glm::vec3& p : face.skin.positions) own_xy.emplace_back(p);
  paint_head_back(image, face.texture_frame, face.head.centre, unseen_colour_radii(face, own_xy, {}));
  return image;
}

RgbaImage make_eye_texture(const EyeLayer& eye, const Appearance& look, int size, const IrisPattern& pattern) {
  constexpr float kIrisRadiusMm = 5.85f, kPupilRadiusMm = 1.9f;
  const float iris_angle = std::asin(std::min(1.0f, kIrisRadiusMm / kMillimetresPerUnit / eye.radius));
  const float pupil_angle = std::asin(std::min(1.0f, kPupilRadiusMm / kMillimetresPerUnit / eye.radius));
  RgbaImage image(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::vec2 d((static_cast<float>(x) + 0.5f) / static_cast<float>(size) - 0.5f,
                        0.5f - (static_cast<float>(y) + 0.5f) / static_cast<float>(size));
      const float angle = glm::length(d) * 2.0f * eye.cap_angle_rad;
      const float around = std::atan2(d.y, d.x);
      // The white darkens toward the corners, where the lids shade it.
      const glm::vec3 sclera = look.sclera * (1.0f - 0.25f * std::clamp(angle / 1.4f, 0.0f, 1.0f));
      glm::vec3 iris;
      if (pattern) {
        iris = pattern(std::min(1.0f, angle / iris_angle), around);
      } else {
        const float streaks = 0.8f + 0.35f * value_noise(glm::vec2(around * 12.0f, angle * 40.0f));
        iris = look.iris * streaks * (0.75f + 0.35f * angle / iris_angle);
        iris = glm::mix(iris, look.iris * 0.35f, std::clamp((angle / iris_angle - 0.85f) / 0.15f, 0.0f, 1.0f));
      }
      glm::vec3 c = glm::mix(iris, sclera, std::clamp((angle - iris_angle) / 0.03f + 0.5f, 0.0f, 1.0f));
      c = glm::mix(glm::vec3(0.03f), c, std::clamp((angle - pupil_angle) / 0.02f + 0.5f, 0.0f, 1.0f));
      put(image, x, y, c, 1.0f);
    }
  return image;
}

RgbaImage make_mouth_texture(int width, int height) {
  RgbaImage image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float u = (static_cast<float>(x) + 0.5f) / static_cast<float>(width);
      const float v = 1.0f - (static_cast<float>(y) + 0.5f) / static_cast<float>(height);
      const float centre = 1.0f - std::abs(u - 0.5f) * 2.0f;
      glm::vec3 c = glm::vec3(0.22f, 0.06f, 0.06f) * (0.35f + 0.65f * centre);
      // Teeth: a pale band a little below the closed lips' line. A camera at
      // eye level sees through the closed slit to the cavity just below it,
      // which stays dark; lips that part uncover the band.
      if (v > 0.36f && v < 0.47f && std::abs(u - 0.5f) < 0.3f) {
        const float gap = std::abs(std::fmod(u * 14.0f, 1.0f) - 0.5f);
        c = glm::mix(c, glm::vec3(0.85f, 0.82f, 0.74f) * (0.6f + 0.4f * centre), gap < 0.44f ? 0.9f : 0.3f);
      }
      // Tongue: a rounded shape low in the cavity.
      const glm::vec2 t((u - 0.5f) / 0.28f, (v - 0.2f) / 0.22f);
      c = glm::mix(c, glm::vec3(0.62f, 0.27f, 0.28f) * (0.5f + 0.5f * centre), soft_inside(glm::length(t) - 1.0f, 0.3f));
      put(image, x, y, c, 1.0f);
    }
  return image;
}

}  // namespace fw::model
