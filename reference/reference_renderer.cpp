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
          double(m.sheenRoughness), isTransmissive(m) ? double(m.transmission) : 0.0, double(m.thickness),
          dvec3(m.attenuationColor), double(m.attenuationDistance)};
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

// Adds to `color` the radiance the lights reflect from a hit towards V, or from behind a transmissive surface let
// through it, each light that casts shadows only where it reaches the hit. Lights are added in the order of the
// frames measured before shadows, so that those stay identical.
void addDirectLight(const Scene& scene, const Hit& hit, const dvec3& V, const ReferenceMaterial& m,
                    const BrdfForms& forms, ShadowRays& shadows, dvec3& color) {
  const auto adds = [&](double NoL) { return NoL > 0.0 || (NoL < 0.0 && m.transmission > 0.0); };
  for (const DirectionalLight& light : scene.directionalLights) {
    if (!adds(glm::dot(hit.normal, towardsLight(light))) || !shadows.reaches(light)) continue;
    color += reflectedRadiance(light, hit.normal, V, m, forms);
  }
  for (const PointLight& light : scene.lights) {
    const LightIncidence in = incidence(light, hit.position, hit.normal);
    if (!adds(in.NoL) || in.attenuation <= 0.0 || !shadows.reaches(light)) continue;
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

// A rough thin-walled transmissive surface's BTDF is integrated over this many microfacet normals, drawn in
// proportion to D(h) n.h on an 8 x 8 grid of strata (their centres: a deterministic frame).
constexpr int kTransmissionStrata = 8;
// A ray refracted into a volume may reflect totally inside it this many times before it is dropped.
constexpr int kMaxInternalReflections = 8;

// The first surface a camera ray meets, for ReferenceFrame's objectIds and visibility.
struct FirstSurface {
  int object = -1;
  float visibility = -1.0f;
};

// Follows rays through a scene: front to back through BLEND layers and transmissive surfaces, shading each surface
// met (shade) and compositing what shows behind it.
class PathTracer {
 public:
  PathTracer(const Scene& scene, const RayCaster& geometry, const std::vector<AlbedoTable>& albedo,
             const ReferenceOptions& options, std::atomic<int>& truncatedRays)
      : scene_(scene), geometry_(geometry), albedo_(albedo), options_(options),
        layerGap_(kLayerGap * geometry.extent()), truncatedRays_(truncatedRays) {}

  // The radiance arriving back along `ray` (a unit direction) from what it meets within [tMin, tMax], `layers`
  // layers having been crossed before. Front to back; T, the share of what lies behind the surfaces crossed that
  // still shows, per channel. A BLEND surface composites "over" with its alpha factor a (Porter & Duff 1984, A over
  // B with premultiplied colour a L: C += T a L, and B shows through by 1 - a). A transmissive one
  // (KHR_materials_transmission) adds its reflection and, for its covered share a, what shows through it: straight
  // on, times smoothTransmittance, when smooth and thin-walled; with the microfacet BTDF sampled when rough and
  // `sampleRough` (the first rough surface of a camera ray; the later ones are taken as smooth); refracted through
  // its volume (throughVolume) with KHR_materials_volume. The first surface that is neither ends the walk: alone on
  // the ray, it gives C = 0 + 1 L = L exactly. `first`, where given, receives the first surface met.
  dvec3 trace(const Ray& ray, double tMin, double tMax, int layers, bool sampleRough, FirstSurface* first) const {
    dvec3 color(0.0), T(1.0);
    for (int layer = layers; T != dvec3(0.0); ++layer) {
      const std::optional<Hit> hit = geometry_.closestHit(ray, tMin, tMax);
      if (!hit) break;
      const Material& material = scene_.objects[hit->object].material;
      const bool blend = material.alphaMode == AlphaMode::Blend;
      const ReferenceMaterial m = toReference(material);
      const bool transmits = m.transmission > 0.0;
      if ((blend || transmits) && layer == kMaxBlendLayers) {
        ++truncatedRays_;
        break;
      }
      ShadowRays shadows(geometry_, options_.shadows, *hit);
      const dvec3 L = shade(scene_, *hit, ray, albedo_[hit->object], options_.forms, shadows);
      if (first && layer == layers) *first = {int(hit->object), shadows.visibility()};
      const double a = blend ? double(material.alpha) : 1.0;
      color += T * a * L;
      if (!blend && !transmits) break;
      tMin = hit->t + layerGap_;
      if (!transmits) {
        T *= 1.0 - a;
        continue;
      }
      const dvec3 V = -ray.direction;
      const bool rough = sampleRough && m.roughness > kMinRoughness;
      if (m.thickness <= 0.0 && !rough) {
        // Thin and smooth: the light behind comes straight on, as through the uncovered share.
        T *= (1.0 - a) + a * smoothTransmittance(hit->normal, V, m, options_.forms);
        continue;
      }
      const dvec3 through = m.thickness > 0.0 ? throughVolume(*hit, ray, m, layer, sampleRough)
                                              : throughRoughSurface(*hit, V, m, layer);
      color += T * a * through;
      T *= 1.0 - a;
    }
    return color;
  }

 private:
  // What reaches V through a rough thin-walled surface: the BTDF integrated over its microfacet normals
  // (sampledTransmittance), each direction traced on from the surface.
  dvec3 throughRoughSurface(const Hit& hit, const dvec3& V, const ReferenceMaterial& m, int layer) const {
    const dvec3 N = hit.normal;
    const dvec3 t = glm::normalize(std::abs(N.x) > 0.5 ? glm::cross(N, dvec3(0, 1, 0)) : glm::cross(N, dvec3(1, 0, 0)));
    const dvec3 b = glm::cross(N, t);
    const double alpha = alphaFromRoughness(m.roughness);
    dvec3 sum(0.0);
    for (int i = 0; i < kTransmissionStrata; ++i) {
      for (int j = 0; j < kTransmissionStrata; ++j) {
        // GGX's normals in proportion to D(h) n.h (Walter et al. 2007, eq. 35 and 36).
        const double u1 = (i + 0.5) / kTransmissionStrata, u2 = (j + 0.5) / kTransmissionStrata;
        const double cosTheta = std::sqrt((1.0 - u1) / (1.0 + (alpha * alpha - 1.0) * u1));
        const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
        const double phi = 2.0 * kPi * u2;
        const dvec3 H = sinTheta * std::cos(phi) * t + sinTheta * std::sin(phi) * b + cosTheta * N;
        dvec3 L;
        const dvec3 weight = sampledTransmittance(N, V, H, m, options_.forms, L);
        if (weight == dvec3(0.0)) continue;
        sum += weight * trace({hit.position, L}, layerGap_, std::numeric_limits<double>::infinity(), layer + 1, false,
                              nullptr);
      }
    }
    return sum / double(kTransmissionStrata * kTransmissionStrata);
  }

  // What reaches V through a smooth transmissive volume entered at `hit` (KHR_materials_volume: the mesh is its
  // boundary, the thickness factor only says that there is one): the view ray refracted in by the index of
  // refraction (Snell), weighted by smoothTransmittance on the way in, attenuated by Beer-Lambert's law inside,
  // exp(-sigma d) with sigma = -ln(attenuationColor) / attenuationDistance, and refracted out where it leaves the
  // volume, weighted by 1 - F of the exact dielectric Fresnel there, or reflected inside where it cannot leave
  // (at most kMaxInternalReflections times). A volume the ray finds no way out of (an open mesh) is left along the
  // refracted ray. A rough volume is taken as smooth.
  dvec3 throughVolume(const Hit& hit, const Ray& ray, const ReferenceMaterial& m, int layer, bool sampleRough) const {
    if (m.ior < 1.0) return dvec3(0.0);  // ior 0 (F0 1) reflects everything
    const double inf = std::numeric_limits<double>::infinity();
    dvec3 weight = smoothTransmittance(hit.normal, -ray.direction, m, options_.forms);
    dvec3 sigma(0.0);
    if (std::isfinite(m.attenuationDistance)) {
      for (int i = 0; i < 3; ++i) sigma[i] = -std::log(std::max(m.attenuationColor[i], 1e-300)) / m.attenuationDistance;
    }
    // An interpolated normal leaning away from the ray (at a silhouette) refracts nothing in.
    const dvec3 in = glm::refract(ray.direction, hit.normal, 1.0 / m.ior);
    if (in == dvec3(0.0)) return dvec3(0.0);
    Ray inside{hit.position, glm::normalize(in)};
    for (int bounce = 0; bounce <= kMaxInternalReflections; ++bounce) {
      const std::optional<Hit> exit = geometry_.exitHit(inside, layerGap_, inf, hit.object);
      if (!exit) return weight * trace(inside, layerGap_, inf, layer + 1, sampleRough, nullptr);
      weight *= glm::exp(-sigma * exit->t);
      const dvec3 out = glm::refract(inside.direction, -exit->normal, m.ior);
      if (out == dvec3(0.0)) {
        inside = {exit->position, glm::reflect(inside.direction, -exit->normal)};
        continue;
      }
      weight *= 1.0 - fresnelDielectric(glm::dot(inside.direction, exit->normal), 1.0 / m.ior);
      return weight * trace({exit->position, glm::normalize(out)}, layerGap_, inf, layer + 1, sampleRough, nullptr);
    }
    return dvec3(0.0);
  }

  const Scene& scene_;
  const RayCaster& geometry_;
  const std::vector<AlbedoTable>& albedo_;
  const ReferenceOptions& options_;
  double layerGap_;
  std::atomic<int>& truncatedRays_;
};

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
  std::atomic<int> truncatedRays{0};
  const PathTracer tracer(scene, *geometry, albedo, options, truncatedRays);

  auto shadeRow = [&](int y) {
    for (int x = 0; x < width; ++x) {
      const size_t pixel = size_t(y) * width + x;
      const Ray ray = cameraRay(scene.camera, width, height, x, y);
      // Clip to the camera's near and far planes along the view axis, as the rasterizer does.
      const double axial = glm::dot(ray.direction, forward);
      const double tMax = scene.camera.farPlane / axial;
      const double tMin = scene.camera.nearPlane / axial;
      FirstSurface first;
      const dvec3 color = tracer.trace(ray, tMin, tMax, 0, true, &first);
      frame.objectIds[pixel] = first.object;
      if (!frame.visibility.empty()) frame.visibility[pixel] = first.visibility;
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
