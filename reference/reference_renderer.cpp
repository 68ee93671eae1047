#include "reference/reference_renderer.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
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
  return {dvec3(m.baseColor), double(m.roughness), double(m.metalness)};
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
  ReferenceFrame frame{{width, height, std::vector<float>(size_t(width) * height * 4, 0.0f)},
                       std::vector<int>(size_t(width) * height, -1)};

  auto shadeRow = [&](int y) {
    for (int x = 0; x < width; ++x) {
      const Ray ray = cameraRay(scene.camera, width, height, x, y);
      // Clip to the camera's near and far planes along the view axis, as the rasterizer does.
      const double axial = glm::dot(ray.direction, forward);
      const std::optional<Hit> hit =
          geometry->closestHit(ray, scene.camera.nearPlane / axial, scene.camera.farPlane / axial);
      dvec3 color(0.0);
      if (hit) {
        const ReferenceMaterial m = toReference(scene.objects[hit->object].material);
        const dvec3 V = -ray.direction;
        const double NoV = std::max(glm::dot(hit->normal, V), 1e-4);
        if (!albedo[hit->object].empty()) color += dvec3(scene.ambient) * albedo[hit->object](NoV);
        for (const DirectionalLight& light : scene.directionalLights) {
          color += reflectedRadiance(light, hit->normal, V, m, options.forms);
        }
        for (const PointLight& light : scene.lights) {
          color += reflectedRadiance(light, hit->position, hit->normal, V, m, options.forms);
        }
      }
      if (hit) frame.objectIds[size_t(y) * width + x] = int(hit->object);
      float* p = &frame.radiance.pixels[(size_t(y) * width + x) * 4];
      p[0] = float(color.x);
      p[1] = float(color.y);
      p[2] = float(color.z);
      p[3] = 1.0f;
    }
  };

  parallelFor(height, threads, shadeRow);
  return frame;
}

}  // namespace pbr::reference
