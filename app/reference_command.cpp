#include <chrono>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <optional>
#include <thread>

#include "app/args.hpp"
#include "app/commands.hpp"
#include "app/option_table.hpp"
#include "app/common_options.hpp"
#include "app/file_clash.hpp"
#include "app/scene_source.hpp"
#include "core/io/image_output.hpp"
#include "core/io/output_file.hpp"
#include "core/scene/messages.hpp"
#include "core/scene/shadow_settings.hpp"
#include "reference/brdf_form_names.hpp"
#include "reference/display_transform.hpp"
#include "reference/reference_renderer.hpp"
#include "renderer/frame_limits.hpp"

namespace pbr {

namespace {

constexpr const char* kSummary =
    "Ray-casts each pixel centre in double precision and evaluates the reference PBR model (GGX, exact "
    "height-correlated Smith, exact dielectric Fresnel, Schlick for metals, Lambert (1 - F(n.v))), or with --variant "
    "the approximations of a renderer variant; writes the same linear radiance as 'pbr render --hdr'. Textures are "
    "ignored: material factors only, and alpha-masked cut-outs cast solid shadows. The default mesh geometry makes "
    "the difference to 'pbr render' shading alone; against --geometry analytic it is the tessellation's error. The "
    "--out image is made on the CPU too, in double precision: exposure, the tone curve, exact sRGB encoding, 8 bits "
    "(reference/display_transform.hpp). Scenes are lit by their point, spot and directional lights, without an "
    "environment.";

// What the command line asks of the reference, read and checked before anything is traced.
struct ReferenceRequest {
  std::string outHdr, outLdr;
  glm::ivec2 size{0};
  reference::ReferenceOptions options;
  Scene scene;
  ExposureChoice exposure;
  ToneCurve curve{};  // readToneCurve's
};

ReferenceRequest readRequest(const Args& args) {
  ReferenceRequest r;
  r.outHdr = args.get("--hdr");
  r.outLdr = args.get("--out");
  if (r.outHdr.empty() && r.outLdr.empty()) throw UsageError("--hdr F.exr|F.pfm or --out F.png|F.jpg is required");
  // An unknown extension fails before the frame is traced.
  if (!r.outHdr.empty()) hdrFileFormat(r.outHdr);
  if (!r.outLdr.empty()) ldrFileFormat(r.outLdr);
  SceneParams params = sceneFileParams(args);
  params.defaultEnvironment = DefaultEnvironment::None;  // the reference has no image-based lighting
  applySceneShapeOptions(args, params);
  r.size = args.getSize("--size");
  r.options.threads = args.getInt("--threads", 0, 1024);
  r.options.geometry = reference::parseGeometry(args.get("--geometry"));
  r.options.forms = reference::parseBrdfForms(args.get("--variant"));
  r.options.shadows = parseShadowMode(args.get("--shadows"));
  r.scene = resolveScene(args.get("--scene"), params);
  r.exposure = applyExposureOptions(args, r.scene);
  if (r.exposure.autoExposure) throw UsageError("--exposure auto is metered on the GPU: give the reference a number");
  r.curve = readToneCurve(args);
  checkOutputsApart(sceneInputs(args.get("--scene"), r.scene), {{"--hdr", r.outHdr}, {"--out", r.outLdr}});
  // The frame in memory: radiance (16 bytes a pixel), object ids and shadow visibility (4 each), and the file's
  // copy of the radiance as it is written (16).
  checkFrameSize(r.size.x, r.size.y, "--size", 40, {kMaxSizeSide, availableMemoryBytes()});
  return r;
}

// A long run says how far it is, on stderr, every few seconds (the reference calls it from its threads).
class ProgressLines {
 public:
  void operator()(double done) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begun_).count();
    const std::lock_guard<std::mutex> lock(mutex_);
    if (seconds - lastReport_ < 5.0 || done >= 1.0) return;
    lastReport_ = seconds;
    if (done < 0.05) {
      std::fprintf(stderr, "reference: %.1f%% of the rows after %.0f s\n", 100.0 * done, seconds);
    } else {
      std::fprintf(stderr, "reference: %.0f%% of the rows after %.0f s, about %.0f s left\n", 100.0 * done, seconds,
                   seconds * (1.0 - done) / done);
    }
  }

 private:
  const std::chrono::steady_clock::time_point begun_ = std::chrono::steady_clock::now();
  std::mutex mutex_;
  double lastReport_ = 0.0;
};

// The 8-bit image of the radiance, made on the CPU in double precision.
ImageRgba8 displayImage(const ImageRgbaF& radiance, float exposure, ToneCurve curve) {
  ImageRgba8 ldr{radiance.width, radiance.height, {}};
  ldr.pixels.reserve(radiance.pixels.size());
  for (size_t i = 0; i + 3 < radiance.pixels.size(); i += 4) {
    const float* p = &radiance.pixels[i];
    const glm::ivec3 code = reference::displayCode(glm::dvec3(p[0], p[1], p[2]), exposure, curve);
    ldr.pixels.insert(ldr.pixels.end(), {uint8_t(code.x), uint8_t(code.y), uint8_t(code.z), 255});
  }
  return ldr;
}

}  // namespace

int runReference(const std::vector<std::string>& argv) {
  const auto& specs = commandOptions(Command::Reference);
  Args args(specs, argv);
  if (args.helpRequested()) {
    std::cout << Args::helpText("pbr reference --hdr F.exr|--out F.png [options]", kSummary, specs);
    return 0;
  }
  ReferenceRequest r = readRequest(args);
  // Opened before tracing, so that an unwritable path fails at once; renamed into place once written.
  std::optional<OutputFile> hdrFile, ldrFile;
  if (!r.outHdr.empty()) hdrFile.emplace(r.outHdr);
  if (!r.outLdr.empty()) ldrFile.emplace(r.outLdr);
  ProgressLines progress;
  r.options.progress = [&progress](double done) { progress(done); };

  const auto start = std::chrono::steady_clock::now();
  const reference::ReferenceFrame frame = reference::renderReference(r.scene, r.size.x, r.size.y, r.options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (hdrFile) hdrFile->write([&](std::ostream& o) { writeHdr(o, hdrFileFormat(r.outHdr), frame.radiance); });
  if (ldrFile) {
    const ImageRgba8 ldr = displayImage(frame.radiance, r.exposure.exposure, r.curve);
    ldrFile->write([&](std::ostream& o) { writeLdr(o, ldrFileFormat(r.outLdr), ldr); });
  }
  if (frame.truncatedRays > 0) {
    warnOnce("reference: " + std::to_string(frame.truncatedRays) + " pixels' rays met more than " +
         std::to_string(reference::kMaxBlendLayers) + " BLEND layers: the surfaces beyond them are left out");
  }
  std::printf("reference: %s (%s geometry), %dx%d, %zu lights, shadows %s, %s, %.2f s on %u threads (CPU, double "
              "precision)\n",
              r.scene.name.c_str(), r.options.geometry == reference::Geometry::Meshes ? "mesh" : "analytic",
              r.size.x, r.size.y, r.scene.lights.size(), toString(r.options.shadows),
              toString(r.options.forms).c_str(), seconds,
              r.options.threads > 0 ? unsigned(r.options.threads) : std::thread::hardware_concurrency());
  if (hdrFile) std::printf("wrote %s\n", r.outHdr.c_str());
  if (ldrFile) {
    std::printf("wrote %s (exposure %g, tone curve %s)\n", r.outLdr.c_str(), double(r.exposure.exposure),
                toString(r.curve));
  }
  return 0;
}

}  // namespace pbr
