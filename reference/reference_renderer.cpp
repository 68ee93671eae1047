#include "reference/reference_renderer.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>

#include "reference/directional_albedo.hpp"
#include "reference/directional_light.hpp"
#include "reference/mesh_scene.hpp"
#include "reference/point_light.hpp"
#include "reference/raycast.hpp"

namespace pbr::reference {

namespace {

constexpr int kAlbedoBins = 64;
constexpr int kAlbedoSamples = 32;  // per axis: the albedo is smooth in n.v and known to about 1e-3

template <class Work>
void parallelFor(int count, int threads, Work work) {
  const int workers = threads > 0 ? threads : std::max(1, int(std::thread::hardware_concurrency()));
  std::atomic<int> next{0};
  std::vector<std::thread> pool;
  for (int t = 0; t < workers; ++t) {
    pool.emplace_back([&] {
      for (int i = next++; i < count; i = next++) work(i);
    });
  }
  for (std::thread& t : pool) t.join();
}

ReferenceMaterial toReference(const Material& m) {
  return {dvec3(m.baseColor), double(m.roughness), double(m.metalness), double(m.ior), double(m.specular),
          dvec3(m.specularColor), double(m.clearcoat), double(m.clearcoatRoughness), dvec3(m.sheenColor),
          double(m.sheenRoughness)};
}

// One albedo table per object, empty where no ambient light makes it needed.
std::vector<AlbedoTable> albedoTables(const Scene& scene, const BrdfForms& forms, int threads) {
  std::vector<AlbedoTable> tables(scene.objects.size());
  if (scene.ambient == glm::vec3(0.0f)) return tables;
  parallelFor(int(scene.objects.size()), threads, [&](int i) {
    tables[size_t(i)] = AlbedoTable(toReference(scene.objects[size_t(i)].material), forms, kAlbedoBins, kAlbedoSamples);
  });
  return tables;
}

// Shadow rays start off the surface by this share of the scene's extent, along the normal on the lit side (n.l > 0):
// far above double's rounding of a hit point (about 1e-16 of its coordinates), far below what a frame resolves (a
// pixel spans about 1e-3 of a scene it shows whole, at 1280 pixels across), so a surface neither shadows itself nor
// lets light through where objects touch. They stop as far short of a point light.
constexpr double kShadowOffset = 1e-6;

// Of the lights that cast shadows and add to one hit: how many there are and how many reach it.
class ShadowRays {
 public:
  ShadowRays(const RayCaster& geometry, ShadowMode mode, const Hit& hit)
      : geometry_(geometry), mode_(mode), offset_(kShadowOffset * geometry.extent()),
        origin_(hit.position + offset_ * hit.normal) {}

  // Whether a point light reaches the hit, given that it adds to it; counted if it casts shadows.
  bool reaches(const PointLight& light) {
    const dvec3 toLight = dvec3(light.position) - origin_;
    const double distance = glm::length(toLight);
    return reaches(light.castsShadows, toLight / distance, distance - offset_);
  }
  bool reaches(const DirectionalLight& light) {
    return reaches(light.castsShadows, towardsLight(light), std::numeric_limits<double>::infinity());
  }
  // The mean 0/1 visibility of the casting lights counted, -1 for none.
  float visibility() const { return casting_ > 0 ? float(double(reaching_) / casting_) : -1.0f; }

 private:
  bool reaches(bool sceneSays, const dvec3& L, double tMax) {
    if (!castsShadows(sceneSays, mode_)) return true;
    ++casting_;
    // A light within the offset of the surface, or on it, is not shadowed: no ray is left to cast.
    const bool reached = !(tMax > 0.0 && geometry_.occluded({origin_, L}, 0.0, tMax));
    reaching_ += reached;
    return reached;
  }

  const RayCaster& geometry_;
  ShadowMode mode_;
  double offset_;
  dvec3 origin_;
  int casting_ = 0;
  int reaching_ = 0;
};

// Adds to `color` the radiance the lights reflect from a hit towards V, each light that casts shadows only where it
// reaches the hit. Lights are added in the order of the frames measured before shadows, so that those stay identical.
void addDirectLight(const Scene& scene, const Hit& hit, const dvec3& V, const ReferenceMaterial& m,
                    const BrdfForms& forms, ShadowRays& shadows, dvec3& color) {
  for (const DirectionalLight& light : scene.directionalLights) {
    if (glm::dot(hit.normal, towardsLight(light)) <= 0.0 || !shadows.reaches(light)) continue;
    color += reflectedRadiance(light, hit.normal, V, m, forms);
  }
  for (const PointLight& light : scene.lights) {
    const LightIncidence in = incidence(light, hit.position, hit.normal);
    if (in.NoL <= 0.0 || in.attenuation <= 0.0 || !shadows.reaches(light)) continue;
    color += reflectedRadiance(light, hit.position, hit.normal, V, m, forms);
  }
}

// The radiance one surface that a camera ray meets sends back along it: ambient light through its albedo table
// (empty without ambient light), then the lights, each that casts shadows counted in `shadows`; an unlit surface's
// base colour.
dvec3 shade(const Scene& scene, const Hit& hit, const Ray& ray, const AlbedoTable& albedo, const BrdfForms& forms,
            ShadowRays& shadows) {
  const Material& material = scene.objects[hit.object].material;
  // KHR_materials_unlit: the base colour is the radiance; no light is reflected.
  if (material.unlit) return dvec3(material.baseColor);
  const ReferenceMaterial m = toReference(material);
  const dvec3 V = -ray.direction;
  const double NoV = std::max(glm::dot(hit.normal, V), 1e-4);
  dvec3 color(0.0);
  if (!albedo.empty()) color += dvec3(scene.ambient) * albedo(NoV);
  addDirectLight(scene, hit, V, m, forms, shadows, color);
  return color;
}

// A camera ray goes on past a BLEND layer from this share of the scene's extent beyond it, as shadow rays leave
// their surface: far past the rounding of the hit, so that it never meets that surface again (nor the triangle
// beside it along a shared edge), far short of any gap a frame resolves. Surfaces nearer each other than that along
// the ray count as one, the nearer.
constexpr double kLayerGap = 1e-6;

}  // namespace

Geometry parseGeometry(const std::string& name) {
  if (name == "meshes") return Geometry::Meshes;
  if (name == "analytic") return Geometry::Analytic;
  throw std::invalid_argument("unknown geometry '" + name + "' (expected meshes or analytic)");
}

const char* toString(Geometry geometry) { return geometry == Geometry::Meshes ? "meshes" : "analytic"; }

bool ReferenceFrame::interior(int x, int y) const {
  const int w = radiance.width, h = radiance.height;
  const int id = objectIds[size_t(y) * w + x];
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const int nx = std::clamp(x + dx, 0, w - 1), ny = std::clamp(y + dy, 0, h - 1);
      if (objectIds[size_t(ny) * w + nx] != id) return false;
    }
  }
  return true;
}

ReferenceFrame renderReference(const Scene& scene, int width, int height, const ReferenceOptions& options) {
  const int threads = options.threads;
  if (scene.environment) {
    throw SceneError(scene.name + ": environment: the reference renderer has no image-based lighting (point and "
                                  "directional lights and uniform ambient only)");
  }
  const std::unique_ptr<const RayCaster> geometry =
      options.geometry == Geometry::Meshes ? std::unique_ptr<const RayCaster>(std::make_unique<MeshScene>(scene))
                                           : std::make_unique<AnalyticScene>(scene);
  const std::vector<AlbedoTable> albedo = albedoTables(scene, options.forms, threads);
  const dvec3 forward = glm::normalize(dvec3(scene.camera.target) - dvec3(scene.camera.position));
  const size_t pixels = size_t(width) * height;
  ReferenceFrame frame{{width, height, std::vector<float>(pixels * 4, 0.0f)}, std::vector<int>(pixels, -1),
                       std::vector<float>(options.shadows != ShadowMode::None ? pixels : 0, -1.0f), 0};
  const double layerGap = kLayerGap * geometry->extent();
  std::atomic<int> truncatedRays{0};

  auto shadeRow = [&](int y) {
    for (int x = 0; x < width; ++x) {
      const size_t pixel = size_t(y) * width + x;
      const Ray ray = cameraRay(scene.camera, width, height, x, y);
      // Clip to the camera's near and far planes along the view axis, as the rasterizer does.
      const double axial = glm::dot(ray.direction, forward);
      const double tMax = scene.camera.farPlane / axial;
      double tMin = scene.camera.nearPlane / axial;
      // Front to back through the BLEND layers; T is the share of what lies behind them that still shows. The first
      // surface that is not a layer ends the walk: alone on the ray, it gives C = 0 + 1 L = L exactly.
      dvec3 color(0.0);
      double T = 1.0;
      for (int layer = 0; T > 0.0; ++layer) {
        const std::optional<Hit> hit = geometry->closestHit(ray, tMin, tMax);
        if (!hit) break;
        const Material& material = scene.objects[hit->object].material;
        const bool blend = material.alphaMode == AlphaMode::Blend;
        if (blend && layer == kMaxBlendLayers) {
          ++truncatedRays;
          break;
        }
        ShadowRays shadows(*geometry, options.shadows, *hit);
        const dvec3 L = shade(scene, *hit, ray, albedo[hit->object], options.forms, shadows);
        if (layer == 0) {
          frame.objectIds[pixel] = int(hit->object);
          if (!frame.visibility.empty()) frame.visibility[pixel] = shadows.visibility();
        }
        if (!blend) {
          color += T * L;
          break;
        }
        // Porter & Duff 1984, A over B with premultiplied colour a L: C += T a L, and B shows through by 1 - a.
        color += T * double(material.alpha) * L;
        T *= 1.0 - double(material.alpha);
        tMin = hit->t + layerGap;
      }
      float* p = &frame.radiance.pixels[pixel * 4];
      p[0] = float(color.x);
      p[1] = float(color.y);
      p[2] = float(color.z);
      p[3] = 1.0f;
    }
  };

  std::atomic<int> rowsDone{0};
  parallelFor(height, threads, [&](int y) {
    shadeRow(y);
    const int done = ++rowsDone;
    if (options.progress) options.progress(double(done) / double(height));
  });
  frame.truncatedRays = truncatedRays;
  return frame;
}

}  // namespace pbr::reference
