#include "prep_command.hpp"

#include <cmath>
#include <iostream>

#include "fw/model/file_io.hpp"
#include "fw/photo/photo_limits.hpp"
#include "fw/photo/prepare_avatar.hpp"
#include "fw/render/png.hpp"
#include "prep_preview.hpp"

namespace fw::server {
namespace {

struct PrepArgs {
  std::string photo;
  std::string output;
  std::string preview;
  std::string landmark_model;
  int face_index = 0;
  int quality = 80;
  bool no_eye_layer = false;
};

int prep(const PrepArgs& args) {
  const auto fail = [](const std::string& message) {
    std::cerr << "facewire-server prep: " << message << "\n";
    return 2;
  };
  std::vector<std::uint8_t> bytes;
  std::string error;
  if (!model::read_file(args.photo, photo::kMaxPhotoBytes, bytes, error)) return fail(error);

  photo::PrepError prep_error;
  const auto landmark_model =
      args.landmark_model.empty() ? std::nullopt : std::optional<std::filesystem::path>(args.landmark_model);
  auto preparer = photo::AvatarPreparer::create(landmark_model, prep_error);
  if (!preparer) return fail(prep_error.message);
  photo::PrepOptions options;
  options.face_index = args.face_index;
  options.quality = args.quality;
  options.eye_layer = !args.no_eye_layer;
  const auto avatar = preparer->prepare(bytes, options, prep_error);
  if (!avatar) return fail(args.photo + ": " + prep_error.message);
  for (const std::string& warning : avatar->report.warnings) std::cerr << "facewire-server prep: warning: " << warning << "\n";

  // Everything that can fail runs before anything is written.
  model::RgbaImage sheet;
  if (!args.preview.empty() && !make_prep_preview(*avatar, sheet, error)) return fail(error);
  const std::vector<std::uint8_t> package = model::serialize_avatar_package(avatar->package);
  if (!model::write_file_atomically(args.output, package, error)) return fail(error);
  if (!args.preview.empty() && !render::write_png(sheet, args.preview, error)) return fail(error);

  const photo::PrepReport& r = avatar->report;
  std::cout << "wrote " << args.output << " (" << package.size() << " bytes): " << r.faces_found << " face(s) found, "
            << std::lround(r.inter_ocular_px) << " px between the eyes, eye line " << std::lround(r.roll_deg)
            << " deg, head turned about " << std::lround(r.yaw_deg) << " deg and tilted "
            << std::lround(r.head_pitch_deg) << " deg\n";
  // The expression the photo showed, which the avatar's neutral face leaves out.
  std::string expression;
  for (std::size_t c = 0; c < codec::kAuChannelCount; ++c) {
    if (r.photo_expression[c] < 0.05f) continue;
    const codec::AuChannel channel = codec::kAuChannels[c];
    expression += " AU" + std::to_string(channel.au) +
                  (channel.side == codec::AuSide::both ? "" : channel.side == codec::AuSide::left ? "L" : "R") + " " +
                  std::to_string(std::lround(r.photo_expression[c] * 100)) + "%";
  }
  if (!expression.empty()) std::cout << "expression in the photo, taken out:" << expression << "\n";
  if (!args.preview.empty()) std::cout << "wrote " << args.preview << "\n";
  return 0;
}

}  // namespace

void add_prep_command(CLI::App& app) {
  auto args = std::make_shared<PrepArgs>();
  CLI::App* cmd = app.add_subcommand("prep", "Prepare an avatar package (.fwa) from a photo");
  cmd->add_option("photo", args->photo, "JPEG, PNG or WebP photo of one face (at most 10 MB, 40 megapixels)")->required();
  cmd->add_option("-o,--output", args->output, "package to write, e.g. NAME.fwa")->required();
  cmd->add_option("--preview", args->preview, "also write a preview sheet (PNG)");
  cmd->add_option("--face-index", args->face_index, "which face when there are several: 0 = the largest")
      ->check(CLI::Range(0, 99));
  cmd->add_option("--quality", args->quality, "texture quality 1..100")->check(CLI::Range(1, 100))->capture_default_str();
  cmd->add_flag("--no-eye-layer", args->no_eye_layer,
                "keep the photo's eyes in the texture (they cannot look around, but are exactly the photo's)");
  cmd->add_option("--landmark-model", args->landmark_model, "dlib 68-point model (default: Debian's libdlib-data)");
  cmd->callback([args] { std::exit(prep(*args)); });
}

}  // namespace fw::server
