// The head's back and hidden sides: coloured from their own disc, never by
// stretching the photo across them, and painted smooth from the colours just
// inside the outline.
#include "fw/model/head_back.hpp"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/model/fitted_face.hpp"
#include "fw/model/head_shell.hpp"
#include "fw/model/procedural_texture.hpp"

namespace fw::model {
namespace {

std::vector<glm::vec2> own_fit(const GenericFace& face) {
  std::vector<glm::vec2> xy;
  for (const glm::vec3& p : face.skin.positions) xy.emplace_back(p);
  return xy;
}

glm::vec3 texel(const RgbaImage& image, glm::vec2 uv) {
  const std::uint8_t* px = image.at(static_cast<int>(uv.x * static_cast<float>(image.width)),
                                    static_cast<int>((1.0f - uv.y) * static_cast<float>(image.height)));
  return glm::vec3(px[0], px[1], px[2]) / 255.0f;
}

// A triangle between a vertex the photo shows and one on the disc would
// stretch everything between them in the texture across the side of the
// head: the streaks this layout exists to end.
TEST(HeadBack, NoTriangleSpansThePhotoAndTheDisc) {
  const GenericFace& generic = generic_face();
  std::vector<float> wider = generic.head.outline;
  for (float& r : wider) r *= 1.25f;
  for (const HeadShell& shell : {generic.head, fit_head_shell(generic, own_fit(generic), wider)}) {
    std::size_t on_disc = 0;
    for (const glm::uvec3& t : shell.mesh.triangles) {
      int corners = 0;
      for (int c = 0; c < 3; ++c) corners += on_head_back_patch(shell.mesh.uvs[t[c]]) ? 1 : 0;
      EXPECT_TRUE(corners == 0 || corners == 3) << "triangle " << t.x << " " << t.y << " " << t.z;
      on_disc += corners == 3 ? 1 : 0;
    }
    // The back half of the head: roughly half the shell's triangles.
    EXPECT_GT(on_disc, shell.mesh.triangles.size() / 4);
  }
}

// The disc and its margin lie where no vertex that takes the photo's colour
// samples, even on a head a quarter larger than the generic one.
TEST(HeadBack, LiesWhereNothingSeenFromTheFrontSamples) {
  const GenericFace& generic = generic_face();
  std::vector<float> wider = generic.head.outline;
  for (float& r : wider) r *= 1.25f;
  const GenericFace fitted = fit_generic_face(generic, own_fit(generic), wider);
  const float margin = kHeadBackPatch.radius * 1.25f + 0.02f;
  const auto clear = [&](glm::vec2 uv) {
    return std::abs(uv.x - kHeadBackPatch.centre.x) > margin || std::abs(uv.y - kHeadBackPatch.centre.y) > margin;
  };
  for (const glm::vec2& uv : fitted.skin.uvs) EXPECT_TRUE(clear(uv)) << uv.x << " " << uv.y;
  for (const glm::vec2& uv : fitted.head.mesh.uvs) {
    if (on_head_back_patch(uv)) continue;
    EXPECT_TRUE(clear(uv)) << uv.x << " " << uv.y;
  }
}

// Hair above, skin below, and on the crown a strand pattern of alternate
// dark and light rays: the back of the head comes out in the crown's mean
// colour without the strands, every direction meeting in it at the back
// pole, and the neck keeps the skin.
TEST(HeadBack, IsPaintedSmoothFromTheColoursInsideTheOutline) {
  const GenericFace& generic = generic_face();
  const glm::vec3 skin(0.8f, 0.6f, 0.5f), dark(0.1f, 0.08f, 0.05f), light(0.5f, 0.4f, 0.3f);
  RgbaImage texture(256, 256);
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) {
      const glm::vec2 p = generic.texture_frame.to_model(glm::vec2((x + 0.5f) / 256.0f, 1.0f - (y + 0.5f) / 256.0f));
      const glm::vec2 d = p - generic.head.centre;
      const float phi = std::atan2(d.y, d.x);
      const bool strand = static_cast<int>(std::floor(phi / (2.0f * std::numbers::pi_v<float> / 32.0f))) % 2 == 0;
      const glm::vec3 c = p.y > 0.6f ? (strand ? dark : light) : skin;
      std::uint8_t* px = texture.at(x, y);
      for (int k = 0; k < 3; ++k) px[k] = static_cast<std::uint8_t>(c[k] * 255.0f + 0.5f);
      px[3] = 255;
    }
  paint_head_back(texture, generic.texture_frame, generic.head.centre,
                  unseen_colour_radii(generic, own_fit(generic), {}));
  // The back pole: between the strands' colours (averaged in linear light,
  // so nearer the light one than their codes' mean), and no strand.
  const glm::vec3 pole = texel(texture, kHeadBackPatch.centre);
  for (int k = 0; k < 3; ++k) {
    EXPECT_GT(pole[k], dark[k] + 0.1f) << k;
    EXPECT_LT(pole[k], light[k]) << k;
  }
  for (float phi = -3.0f; phi < 3.2f; phi += 0.5f)
    EXPECT_LT(glm::length(texel(texture, head_back_uv(phi, 0.08f)) - pole), 0.03f) << phi;
  // Around the rim's upper half, neighbouring directions differ little:
  // the strands are smoothed away (without the smoothing, they stay).
  float largest_step = 0.0f;
  glm::vec3 previous = texel(texture, head_back_uv(0.6f, 0.97f));
  for (float phi = 0.62f; phi < 2.5f; phi += 0.02f) {
    const glm::vec3 c = texel(texture, head_back_uv(phi, 0.97f));
    largest_step = std::max(largest_step, glm::length(c - previous));
    previous = c;
  }
  // A texel's step along the crown's edge with the skin is up to 0.07 (the
  // disc is 14 texels across here); a strand left in would step by 0.5.
  EXPECT_LT(largest_step, 0.1f) << "a strand runs back across the head";
  // Behind the band of the ears, the sides are the crown's colour on every
  // ray above the ear lobes, though the silhouette there is skin: a head
  // turned 60 degrees shows its side back to about t = 0.33, and a side
  // in the cheeks' colour read as bald. The silhouette keeps its own.
  const float side_rays[] = {-0.3f, 0.0f, 0.5f, std::numbers::pi_v<float> - 0.5f, std::numbers::pi_v<float> + 0.3f};
  for (const float phi : side_rays) {
    EXPECT_LT(glm::length(texel(texture, head_back_uv(phi, 0.7f)) - pole), 0.03f) << phi;
    if (std::abs(std::sin(phi)) < 0.35f) {
      EXPECT_LT(glm::length(texel(texture, head_back_uv(phi, 0.99f)) - skin), 0.05f) << phi;
    }
  }
  // The neck's rays keep the skin's colour far back along the neck.
  const glm::vec3 neck = texel(texture, head_back_uv(-std::numbers::pi_v<float> / 2.0f, 0.75f));
  EXPECT_LT(glm::length(neck - skin), 0.03f);
  EXPECT_EQ(texture.at(static_cast<int>(kHeadBackPatch.centre.x * 256), 256 - 18)[3], 255) << "opaque";
}

// A procedural face carries its disc too: the back of its head is its hair.
TEST(HeadBack, ProceduralFacesHaveHairBehind) {
  Appearance look;
  look.hair = {0.1f, 0.3f, 0.6f};  // a colour nothing else on the face has
  const RgbaImage texture = make_skin_texture(generic_face(), look, 256);
  const glm::vec3 back = texel(texture, head_back_uv(std::numbers::pi_v<float> / 2.0f, 0.2f));
  EXPECT_GT(back.b, back.r + 0.2f) << "the crown's hair, not skin";
}

}  // namespace
}  // namespace fw::model
