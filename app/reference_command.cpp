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

int runReference(const std::vector<std::string>& argv) {
  const auto& specs = commandOptions(Command::Reference);
  Args args(specs, argv);
  if (args.helpRequested()) {
    std::cout << Args::helpText("pbr reference --hdr F.exr|--out F.png [options]",
                                "Ray-casts each pixel centre in double precision and evaluates the reference PBR "
                                "model (GGX, exact height-correlated Smith, exact dielectric Fresnel, Schlick for "
                                "metals, Lambert (1 - F(n.v))), or with --variant the approximations of a renderer "
                                "variant; writes the same linear radiance as 'pbr render --hdr'. "
                                "Textures are ignored: material factors only, and alpha-masked cut-outs "
                                "cast solid shadows. The default mesh geometry "
                                "makes the difference to 'pbr render' shading alone; against --geometry analytic "
                                "it is the tessellation's error. The --out image is made on the CPU too, in double "
                                "precision: exposure, the tone curve, exact sRGB encoding, 8 bits "
                                "(reference/display_transform.hpp). Scenes are lit by their point, spot and "
                                "directional lights, without an environment.",
                                specs);
    return 0;
  }
  const std::string out = args.get("--hdr"), outLdr = args.get("--out");
  if (out.empty() && outLdr.empty()) throw UsageError("--hdr F.exr|F.pfm or --out F.png|F.jpg is required");
  // An unknown extension fails before the frame is traced.
  if (!out.empty()) hdrFileFormat(out);
  if (!outLdr.empty()) ldrFileFormat(outLdr);
  SceneParams params = sceneFileParams(args);
  params.defaultEnvironment = DefaultEnvironment::None;  // the reference has no image-based lighting
  applySceneShapeOptions(args, params);
  const glm::ivec2 size = args.getSize("--size");
  reference::ReferenceOptions options;
  options.threads = args.getInt("--threads", 0, 1024);
  options.geometry = reference::parseGeometry(args.get("--geometry"));
  options.forms = reference::parseBrdfForms(args.get("--variant"));
  options.shadows = parseShadowMode(args.get("--shadows"));
  Scene scene = resolveScene(args.get("--scene"), params);
  const ExposureChoice exposure = applyExposureOptions(args, scene);
  if (exposure.autoExposure) throw UsageError("--exposure auto is metered on the GPU: give the reference a number");
  const ToneCurve curve = readToneCurve(args);
  checkOutputsApart(sceneInputs(args.get("--scene"), scene), {{"--hdr", out}, {"--out", outLdr}});
  // Opened before tracing, so that an unwritable path fails at once; renamed into place once written.
  std::optional<OutputFile> hdrFile, ldrFile;
  if (!out.empty()) hdrFile.emplace(out);
  if (!outLdr.empty()) ldrFile.emplace(outLdr);
  // The frame in memory: radiance (16 bytes a pixel), object ids and shadow visibility (4 each), and the file's
  // copy of the radiance as it is written (16).
  checkFrameSize(size.x, size.y, "--size", 40, {kMaxSizeSide, availableMemoryBytes()});
  // A long run says how far it is, on stderr, every few seconds.
  const auto begun = std::chrono::steady_clock::now();
  std::mutex progressMutex;
  double lastReport = 0.0;
  options.progress = [&](double done) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begun).count();
    const std::lock_guard<std::mutex> lock(progressMutex);
    if (seconds - lastReport < 5.0 || done >= 1.0) return;
    lastReport = seconds;
    if (done < 0.05) {
      std::fprintf(stderr, "reference: %.1f%% of the rows after %.0f s\n", 100.0 * done, seconds);
    } else {
      std::fprintf(stderr, "reference: %.0f%% of the rows after %.0f s, about %.0f s left\n", 100.0 * done, seconds,
                   seconds * (1.0 - done) / done);
    }
  };

  const auto start = std::chrono::steady_clock::now();
  const reference::ReferenceFrame frame = reference::renderReference(scene, size.x, size.y, options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (hdrFile) hdrFile->write([&](std::ostream& o) { writeHdr(o, hdrFileFormat(out), frame.radiance); });
  if (ldrFile) {
    ImageRgba8 ldr{frame.radiance.width, frame.radiance.height, {}};
    ldr.pixels.reserve(frame.radiance.pixels.size());
    for (size_t i = 0; i + 3 < frame.radiance.pixels.size(); i += 4) {
      const float* p = &frame.radiance.pixels[i];
      const glm::ivec3 code = reference::displayCode(glm::dvec3(p[0], p[1], p[2]), exposure.exposure, curve);
      ldr.pixels.insert(ldr.pixels.end(), {uint8_t(code.x), uint8_t(code.y), uint8_t(code.z), 255});
    }
    ldrFile->write([&](std::ostream& o) { writeLdr(o, ldrFileFormat(outLdr), ldr); });
  }
  if (frame.truncatedRays > 0) {
    warnOnce("reference: " + std::to_string(frame.truncatedRays) + " pixels' rays met more than " +
         std::to_string(reference::kMaxBlendLayers) + " BLEND layers: the surfaces beyond them are left out");
  }
  std::printf("reference: %s (%s geometry), %dx%d, %zu lights, shadows %s, %s, %.2f s on %u threads (CPU, double "
              "precision)\n",
              scene.name.c_str(), options.geometry == reference::Geometry::Meshes ? "mesh" : "analytic", size.x,
              size.y, scene.lights.size(), toString(options.shadows), toString(options.forms).c_str(), seconds,
              options.threads > 0 ? unsigned(options.threads) : std::thread::hardware_concurrency());
  if (!out.empty()) std::printf("wrote %s\n", out.c_str());
  if (!outLdr.empty()) {
    std::printf("wrote %s (exposure %g, tone curve %s)\n", outLdr.c_str(), double(exposure.exposure), toString(curve));
  }
  return 0;
}

}  // namespace pbr
