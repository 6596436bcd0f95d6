#include "fw/photo/prepare_avatar.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <opencv2/imgproc.hpp>

#include "decode_photo.hpp"
#include "eye_from_photo.hpp"
#include "eye_layers.hpp"
#include "face_alignment.hpp"
#include "face_finder.hpp"
#include "fill_beyond_matte.hpp"
#include "head_alpha.hpp"
#include "head_matte.hpp"
#include "head_pose_fit.hpp"
#include "image_conversion.hpp"
#include "image_inspection.hpp"
#include "mesh_fitting.hpp"
#include "lips_at_rest.hpp"
#include "mouth_layer.hpp"
#include "neck_shadow.hpp"
#include "outline_band.hpp"
#include "package_encoding.hpp"
#include "photo_expression.hpp"
#include "pose_checks.hpp"
#include "skin_tone.hpp"
#include "texture_extraction.hpp"
#include "fw/model/fitted_face.hpp"
#include "fw/model/head_back.hpp"
#include "fw/model/head_shell.hpp"
#include "fw/model/procedural_texture.hpp"
#include "fw/model/vascular_masks.hpp"

namespace fw::photo {
namespace {

// A face only the fallback detector finds is tilted back at least this far.
constexpr float kMinFallbackPitchDeg = 12.0f;

constexpr int kMaskSize = 64;     // vascular masks are smooth: 3.8 units over 64 px is plenty
constexpr int kEyeTextureSize = 96;  // the iris about 20 px across: as sharp as a good photo's
constexpr int kPreviewSize = 48;
constexpr int kLosslessWebp = 101;  // OpenCV: WebP quality above 100 means lossless

std::optional<PreparedAvatar> fail(PrepError& error, PrepErrorCode code, std::string message) {
  error = {code, std::move(message)};
  return std::nullopt;
}

// The face without the rim or much hair: a thumbnail that reads at 48 px.
cv::Mat make_preview(const cv::Mat& texture, const model::TextureFrame& frame) {
  const cv::Point2f top_left = model_to_texture_px({-1.3f, 1.3f}, frame, texture.cols);
  const cv::Point2f bottom_right = model_to_texture_px({1.3f, -1.95f}, frame, texture.cols);
  const cv::Rect crop = cv::Rect(top_left, bottom_right) & cv::Rect(0, 0, texture.cols, texture.rows);
  cv::Mat preview;
  cv::resize(texture(crop), preview, cv::Size(kPreviewSize, kPreviewSize), 0, 0, cv::INTER_AREA);
  return preview;
}

// The head's back and hidden sides (model/head_back.hpp), from the colours
// just inside the person's outline (at `colour_radius` on each ray).
void paint_unseen_head(cv::Mat& bgra, const model::GenericFace& generic, std::span<const float> colour_radius) {
  model::RgbaImage rgba = to_rgba_image(bgra);
  model::paint_head_back(rgba, generic.texture_frame, generic.head.centre, colour_radius);
  const cv::Mat painted(rgba.height, rgba.width, CV_8UC4, rgba.pixels.data());
  cv::cvtColor(painted, bgra, cv::COLOR_RGBA2BGRA);
}

}  // namespace

AvatarPreparer::AvatarPreparer(std::unique_ptr<FaceFinder> finder) : finder_(std::move(finder)) {}
AvatarPreparer::~AvatarPreparer() = default;

std::unique_ptr<AvatarPreparer> AvatarPreparer::create(const std::optional<std::filesystem::path>& landmark_model,
                                                       PrepError& error) {
  auto finder = FaceFinder::load(landmark_model, error);
  if (!finder) return nullptr;
  return std::unique_ptr<AvatarPreparer>(new AvatarPreparer(std::move(finder)));
}

bool AvatarPreparer::check_photo(std::span<const std::uint8_t> photo, PrepError& error, std::size_t max_pixels) {
  return inspect_photo(photo, error, max_pixels).has_value();
}

std::optional<PreparedAvatar> AvatarPreparer::prepare(std::span<const std::uint8_t> bytes, const PrepOptions& options,
                                                      PrepError& error) {
  return prepare(bytes, {}, options, error);
}

std::optional<PreparedAvatar> AvatarPreparer::prepare(std::span<const std::uint8_t> bytes,
                                                      std::span<const std::uint8_t> colour_bytes,
                                                      const PrepOptions& options, PrepError& error) {
  if (options.quality < 1 || options.quality > 100)
    return fail(error, PrepErrorCode::bad_option, "quality must be 1..100");
  if (options.texture_size < 128 || options.texture_size > 512)
    return fail(error, PrepErrorCode::bad_option, "texture size must be 128..512 pixels");
  const auto header = inspect_photo(bytes, error);
  if (!header) return std::nullopt;
  const auto photo = decode_photo(bytes, *header, error);
  if (!photo) return std::nullopt;
  std::optional<cv::Mat> repainted;
  if (!colour_bytes.empty()) {
    const auto colour_header = inspect_photo(colour_bytes, error);
    if (!colour_header || !(repainted = decode_photo(colour_bytes, *colour_header, error))) return std::nullopt;
    if (repainted->size() != photo->size())
      return fail(error, PrepErrorCode::bad_option, "the colour source must be the photo's size, upright");
  }
  const cv::Mat& colour_photo = repainted ? *repainted : *photo;

  PreparedAvatar result;
  PrepReport& report = result.report;
  report.photo_width = photo->cols;
  report.photo_height = photo->rows;
  cv::Mat gray;
  cv::cvtColor(*photo, gray, cv::COLOR_BGR2GRAY);
  const std::vector<FoundFace> faces = finder_->detect(gray);
  report.faces_found = static_cast<int>(faces.size());
  const std::string no_face_advice =
      "no face found, even with the photo turned; take one facing the camera in good light, with the whole face "
      "showing and at least about 100 px wide (a selfie at arm's length is right)";
  if (faces.empty()) return fail(error, PrepErrorCode::no_face, no_face_advice);
  if (options.face_index < 0 || options.face_index >= report.faces_found)
    return fail(error, PrepErrorCode::face_index_out_of_range,
                "the photo has " + std::to_string(report.faces_found) + " face(s); the face index must be 0.." +
                    std::to_string(report.faces_found - 1));
  if (report.faces_found > 1)
    report.warnings.push_back("found " + std::to_string(report.faces_found) + " faces; using " +
                              (options.face_index == 0 ? std::string("the largest")
                                                       : "number " + std::to_string(options.face_index) + " by size") +
                              " (choose another with --face-index 0.." + std::to_string(report.faces_found - 1) + ")");
  report.face_index = options.face_index;
  const FoundFace& face = faces[static_cast<std::size_t>(options.face_index)];
  const cv::Rect& box = face.box;
  if (face.turn_deg != 0.0)
    report.warnings.push_back("the face was found with the photo turned " +
                              std::to_string(static_cast<int>(face.turn_deg)) + " degrees");

  const PhotoLandmarks photo_landmarks = finder_->landmarks(gray, face);
  const Alignment alignment = align_by_eyes(photo_landmarks);
  ModelLandmarks landmarks{};
  for (std::size_t i = 0; i < landmarks.size(); ++i) landmarks[i] = alignment.to_model(photo_landmarks[i]);
  std::copy(photo_landmarks.begin(), photo_landmarks.end(), report.photo_landmarks.begin());
  report.inter_ocular_px = alignment.inter_ocular_px;
  report.roll_deg = alignment.roll_rad * 180.0f / std::numbers::pi_v<float>;
  report.yaw_deg = estimate_yaw_deg(landmarks);
  const model::GenericFace& generic = model::generic_face();
  // The head as it would face the camera: its pose taken out of the
  // landmarks, and later out of the texture.
  const PoseFit pose_fit = fit_head_pose(generic, landmarks);
  report.head_yaw_deg = pose_fit.pose.yaw_deg;
  report.head_pitch_deg = pose_fit.pose.pitch_deg;
  // Only the second detector saw this face, so it should be one tilted back
  // past what dlib's detector knows. Landmarks that say it is level are the
  // predictor lost on it, not a level face.
  if (face.by_fallback && pose_fit.pose.pitch_deg < kMinFallbackPitchDeg)
    return fail(error, PrepErrorCode::no_face, no_face_advice);
  if (auto problem = check_face(box, photo_landmarks, photo->size(), landmarks, pose_fit.pose.pitch_deg)) {
    error = *problem;
    return std::nullopt;
  }
  const ModelLandmarks& frontal = pose_fit.frontal;
  // The avatar is built on the person's neutral face: the physics adds every
  // expression to it, so a smile in the photo must not stay in the texture.
  const PhotoExpression expression = estimate_expression(generic, frontal);
  report.photo_expression = expression.au;
  const ModelLandmarks& neutral = expression.neutral;
  std::string fit_note;
  const MeshFit fit = fit_mesh(generic, neutral, fit_note);
  if (!fit_note.empty()) report.warnings.push_back(fit_note);

  const model::TextureFrame& frame = generic.texture_frame;
  const int size = options.texture_size;
  const cv::Mat photo_texture = extract_texture(*photo, alignment, pose_fit, frame, size);
  // The photo's parted lips filled and the line where closed lips meet
  // drawn, on the neutral face (lips_at_rest).
  const auto to_neutral_at_rest = [&](const cv::Mat& t) {
    cv::Mat at_rest = neutralise_texture(fill_mouth_opening(t, frontal, frame), frame, frontal, neutral);
    draw_lip_line(at_rest, frontal, neutral, frame);
    return at_rest;
  };
  const cv::Mat texture = to_neutral_at_rest(photo_texture);
  const auto to_neutral = [&](const cv::Mat& t) { return neutralise_texture(t, frame, frontal, neutral); };
  // What the package shows; what is measured (the matte, the skin tone, the
  // iris) comes from `texture`.
  const cv::Mat colour_photo_texture =
      repainted ? extract_texture(colour_photo, alignment, pose_fit, frame, size) : photo_texture;
  const cv::Mat colour_texture = repainted ? to_neutral_at_rest(colour_photo_texture) : texture;
  const auto eyes = eye_polygons_px(neutral, frame, size);
  // The person cut from the background: what the matte leaves out takes the
  // person's colours, and the alpha shows the head out to its outline.
  const PhotoAtTexels at_texels = photo_at_texels(*photo, alignment, pose_fit, frame, size);
  const cv::Mat seen = to_neutral(at_texels.seen);
  const cv::Mat matte = head_matte(seen, to_neutral(at_texels.in_photo), neutral, frame);
  const std::vector<float> outline = head_outline(matte, generic.head, frame);
  std::vector<glm::vec2> fitted_rim;
  for (const std::uint32_t v : model::face_rim_loop(generic.skin)) fitted_rim.push_back(fit.fitted_xy[v]);
  const cv::Mat colour_seen =
      repainted ? to_neutral(photo_at_texels(colour_photo, alignment, pose_fit, frame, size).seen) : seen;
  cv::Mat face_texture = fill_beyond_matte(mirror_only_within(colour_texture, colour_seen, matte), matte,
                                           head_alpha(matte, outline, fitted_rim, generic.head, frame));
  shade_neck(face_texture, matte, neutral, frame);
  // The sides of a turned head: no streaks from the outline, and a back.
  const std::vector<float> unseen_colour_radius = model::unseen_colour_radii(generic, fit.fitted_xy, outline);
  // Only the shell's texels: the face's own, out to its rim, stay sharp
  // (blurred, its jaw line moved under dlib's eye).
  std::vector<float> band_begins(outline.size());
  for (std::size_t k = 0; k < outline.size(); ++k)
    band_begins[k] = std::max(unseen_colour_radius[k],
                              model::ray_exit_radius(generic.head.centre, model::outline_ray_angle(k, outline.size()),
                                                     fitted_rim));
  smooth_outline_band(face_texture, outline, band_begins, generic.head.centre, frame);
  paint_unseen_head(face_texture, generic, unseen_colour_radius);
  if (options.eye_layer) {
    cv::Mat eye_alpha, alpha;
    cv::extractChannel(with_eye_holes(texture, eyes), eye_alpha, 3);
    cv::extractChannel(face_texture, alpha, 3);
    cv::insertChannel(cv::min(alpha, eye_alpha), face_texture, 3);
  }
  const ClosedLid lid = make_closed_lid(colour_texture, eyes);
  const ThinPlateSpline& warp = fit.warp;
  const auto masks = model::render_region_masks([&](glm::vec2 p) { return warp(p); }, frame, kMaskSize);

  model::AvatarPackage& package = result.package;
  package.generic_face_version = generic.version;
  package.fitted_vertices = fit.fitted_xy;
  package.head_outline = outline;
  std::copy(neutral.begin(), neutral.end(), package.landmarks.begin());
  package.skin_tone = estimate_skin_tone(texture, masks, kMaskSize);
  package.iris_colour = sample_iris_colour(texture, eyes);
  package.face_texture = encode_webp(face_texture, options.quality);
  package.closed_lid = encode_webp(lid.image, options.quality);
  package.closed_lid_rect = {lid.uv_rect.x, lid.uv_rect.y, lid.uv_rect.x + lid.uv_rect.width,
                             lid.uv_rect.y + lid.uv_rect.height};
  if (options.eye_layer) {
    const EyeTexture eye = make_eye_texture_from_photo(colour_photo, alignment, landmarks, generic.eyes[0],
                                                       package.iris_colour, kEyeTextureSize);
    if (!eye.warning.empty()) report.warnings.push_back(eye.warning);
    package.iris_colour = eye.iris;
    package.eye = encode_webp(eye.image, options.quality);
  }
  // The mouth layer shows what the photo shows between its lips, teeth
  // included: from the photo as it is, not the neutralised texture.
  package.mouth =
      encode_webp(make_mouth_layer(colour_photo_texture, frontal, model::fit_generic_face(generic, fit.fitted_xy)),
                  options.quality);
  const auto packed = model::pack_region_masks(masks, kMaskSize);
  package.colour_masks_a = encode_webp(to_bgr_mat(packed[0]), kLosslessWebp);
  package.colour_masks_b = encode_webp(to_bgr_mat(packed[1]), kLosslessWebp);
  package.preview = encode_webp(make_preview(colour_texture, frame), std::min(options.quality, 60));
  report.face_texture = to_rgba_image(face_texture);
  return result;
}

}  // namespace fw::photo
