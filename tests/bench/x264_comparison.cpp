#include "x264_comparison.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <unistd.h>

#include "fw/model/face_reconstruction.hpp"
#include "fw/model/file_io.hpp"
#include "fw/photo/prepare_avatar.hpp"
#include "fw/render/avatar_appearance.hpp"
#include "fw/render/face_renderer.hpp"

namespace fw::bench {
namespace {

constexpr int kSize = 256;
constexpr std::size_t kFrameBytes = static_cast<std::size_t>(kSize) * kSize * 3;
constexpr const char* kX264Settings = "libx264rgb -preset medium (RGB 4:4:4, so colour is not subsampled)";

// A scratch directory removed with everything in it at the end.
struct ScratchDir {
  std::filesystem::path path;
  ScratchDir() {
    path = std::filesystem::temp_directory_path() / ("facewire-bench-x264-" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

// Sum of squared differences of two RGB buffers of the same size.
double squared_error(const std::uint8_t* a, const std::uint8_t* b, std::size_t n) {
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double d = static_cast<double>(a[i]) - static_cast<double>(b[i]);
    sum += d * d;
  }
  return sum;
}

double psnr_db(double sum_sq, std::size_t samples) {
  if (sum_sq <= 0) return 99.0;  // identical: report a ceiling rather than infinity
  return 10.0 * std::log10(255.0 * 255.0 * static_cast<double>(samples) / sum_sq);
}

// The astronaut's avatar as the renderer draws it; false and `error` if the
// portrait is missing or does not prepare.
bool astronaut_appearance(const std::string& photo, render::AvatarAppearance& appearance, std::string& error) {
  std::vector<std::uint8_t> bytes;
  if (!model::read_file(photo, 20u << 20, bytes, error)) return false;
  photo::PrepError prep_error;
  auto preparer = photo::AvatarPreparer::create(std::nullopt, prep_error);
  if (!preparer) {
    error = prep_error.message;
    return false;
  }
  const auto prepared = preparer->prepare(bytes, {}, prep_error);
  if (!prepared) {
    error = prep_error.message;
    return false;
  }
  return render::load_avatar_appearance(prepared->package, appearance, error);
}

// Renders every face of `track` into `out` (RGB, 256x256 per frame).
void render_track(render::FaceRenderer& renderer, render::FaceId face, const render::AvatarAppearance& appearance,
                  const std::vector<codec::FaceParams>& track, std::vector<std::uint8_t>& out) {
  const render::Camera camera = render::Camera::portrait(1.0f);
  out.clear();
  out.reserve(track.size() * kFrameBytes);
  for (const codec::FaceParams& params : track) {
    const model::FaceShape shape = model::reconstruct_face(appearance.avatar, params);
    renderer.set_face_shape(face, shape.positions, shape.uvs);
    const render::FaceDraw draw = render::face_draw(face, params);
    const model::RgbaImage image = renderer.render({&draw, 1}, camera);
    for (std::size_t p = 0; p < image.pixels.size(); p += 4)
      out.insert(out.end(), image.pixels.begin() + static_cast<std::ptrdiff_t>(p),
                 image.pixels.begin() + static_cast<std::ptrdiff_t>(p) + 3);
  }
}

bool run_quiet(const std::string& command) { return std::system((command + " >/dev/null 2>&1").c_str()) == 0; }

struct X264Point {
  bool ok = false;
  double psnr = 0, bits = 0;
};

// Codes the reference at `crf`, decodes it again and measures it.
X264Point x264_at(double crf, const std::filesystem::path& dir, const std::vector<std::uint8_t>& reference, int fps) {
  const std::string raw = (dir / "reference.rgb").string(), coded = (dir / "coded.h264").string(),
                    decoded = (dir / "decoded.rgb").string();
  std::ostringstream encode;
  encode << "ffmpeg -nostdin -v error -y -f rawvideo -pix_fmt rgb24 -s " << kSize << "x" << kSize << " -r " << fps
         << " -i '" << raw << "' -c:v libx264rgb -preset medium -crf " << crf << " -f h264 '" << coded << "'";
  std::ostringstream decode;
  decode << "ffmpeg -nostdin -v error -y -i '" << coded << "' -f rawvideo -pix_fmt rgb24 '" << decoded << "'";
  X264Point point;
  if (!run_quiet(encode.str()) || !run_quiet(decode.str())) return point;
  std::vector<std::uint8_t> back;
  std::string error;
  if (!model::read_file(decoded, reference.size() + 1, back, error) || back.size() != reference.size()) return point;
  point.ok = true;
  point.psnr = psnr_db(squared_error(reference.data(), back.data(), back.size()), back.size());
  point.bits = 8.0 * static_cast<double>(std::filesystem::file_size(coded));
  return point;
}

}  // namespace

X264Comparison compare_with_x264(const std::vector<codec::FaceParams>& original,
                                 const std::vector<codec::FaceParams>& shown, double ours_bps, int fps,
                                 const std::string& photo) {
  X264Comparison result;
  result.x264_settings = kX264Settings;
  result.ours_bps = ours_bps;
  result.frames = static_cast<int>(original.size());
  if (original.empty() || original.size() != shown.size()) {
    result.skipped = "no track to render";
    return result;
  }
  if (!run_quiet("ffmpeg -version")) {
    result.skipped = "ffmpeg is not installed (deploy/install-deps.sh installs it)";
    return result;
  }
  render::AvatarAppearance appearance;
  std::string error;
  if (!astronaut_appearance(photo, appearance, error)) {
    result.skipped = "the astronaut's avatar: " + error;
    return result;
  }
  render::RendererOptions options;
  options.width = options.height = kSize;
  auto renderer = render::FaceRenderer::create(options, error);
  if (!renderer) {
    result.skipped = error;
    return result;
  }
  const render::FaceId face = renderer->add_face(appearance.avatar.face, appearance.textures);

  std::vector<std::uint8_t> reference, ours;
  render_track(*renderer, face, appearance, original, reference);
  render_track(*renderer, face, appearance, shown, ours);
  result.ours_psnr_db = psnr_db(squared_error(reference.data(), ours.data(), ours.size()), ours.size());

  ScratchDir dir;
  {
    std::ofstream raw(dir.path / "reference.rgb", std::ios::binary);
    raw.write(reinterpret_cast<const char*>(reference.data()), static_cast<std::streamsize>(reference.size()));
    if (!raw) {
      result.skipped = "cannot write the reference video to " + dir.path.string();
      return result;
    }
  }
  // The coarsest CRF (fewest bits) whose PSNR still reaches ours: PSNR falls
  // as CRF rises, so bisect over [0, 51].
  const double seconds = static_cast<double>(original.size()) / fps;
  double lo = 0, hi = 51;
  X264Point best = x264_at(lo, dir.path, reference, fps);
  if (!best.ok) {
    result.skipped = "ffmpeg could not code the reference with libx264rgb";
    return result;
  }
  result.x264_reached = best.psnr >= result.ours_psnr_db;
  double best_crf = lo;
  if (result.x264_reached) {
    for (int step = 0; step < 8; ++step) {
      const double mid = std::round((lo + hi) * 50) / 100;  // two decimals, as x264 takes them
      const X264Point p = x264_at(mid, dir.path, reference, fps);
      if (p.ok && p.psnr >= result.ours_psnr_db) {
        lo = mid;
        best = p;
        best_crf = mid;
      } else {
        hi = mid;
      }
    }
  }
  result.x264_crf = best_crf;
  result.x264_psnr_db = best.psnr;
  result.x264_bps = best.bits / seconds;
  return result;
}

}  // namespace fw::bench
