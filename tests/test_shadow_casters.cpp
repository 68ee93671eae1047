// The casters' depths in a shadow view (GBufferPass::renderDepth): a closed caster (core/scene/closed_mesh.hpp)
// drawn with only its faces turned toward the light leaves the same depths as the same box drawn from both faces,
// whether it is mirrored by its pose or wound to look inward, from a sun's orthographic view and a lamp's
// perspective one (the sun's against the box top's depth computed here); and a lamp inside a closed box still has
// the box's walls in its view.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "core/gl/gl_objects.hpp"
#include "core/gl/program_cache.hpp"
#include "core/gl/shader_library.hpp"
#include "core/scene/closed_mesh.hpp"
#include "core/scene/mesh.hpp"
#include "core/scene/scene.hpp"
#include "core/scene/shadow_settings.hpp"
#include "gbuffer/gbuffer_pass.hpp"
#include "shadows/shadow_views.hpp"
#include "tests/gl_test_context.hpp"

namespace {

constexpr int kSide = 64;

// A unit box centred at (0, 0.5, 0), as `mesh` under `transform`.
pbr::Scene boxOnly(const pbr::MeshData& mesh, const glm::mat4& transform) {
  pbr::Scene s;
  s.meshes.push_back(mesh);
  pbr::SceneObject o;
  o.mesh = 0;
  o.transform = glm::translate(glm::mat4(1.0f), {0.0f, 0.5f, 0.0f}) * transform;
  s.objects.push_back(o);
  return s;
}

// The depths `scene`'s casters leave in one kSide-square view, cleared to the far plane (0, reversed Z); the
// number of one-sided draws made, when asked.
std::vector<float> casterDepths(const pbr::ShaderLibrary& shaders, const pbr::Scene& scene,
                                const pbr::ShadowCasterView& view, size_t* oneSided = nullptr) {
  pbr::ProgramCache programs(shaders);
  pbr::GBufferPass pass(programs, scene);
  const pbr::Texture depth("test.casterDepth", GL_DEPTH_COMPONENT32F, kSide, kSide);
  pbr::Framebuffer framebuffer("test.casterFramebuffer");
  framebuffer.attach(GL_DEPTH_ATTACHMENT, depth);
  glNamedFramebufferDrawBuffer(framebuffer.id(), GL_NONE);
  const float far = 0.0f;
  glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &far);
  const pbr::ShadowCasterDraws drawn = pass.renderDepth(scene, framebuffer.id(), {view}, false);
  CHECK(drawn.draws == 1);
  if (oneSided) *oneSided = drawn.oneSided;
  std::vector<float> texels(size_t(kSide) * kSide);
  glGetTextureImage(depth.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(texels.size() * sizeof(float)),
                    texels.data());
  return texels;
}

size_t covered(const std::vector<float>& depths) {
  size_t n = 0;
  for (const float d : depths) n += d > 0.0f ? 1 : 0;
  return n;
}

}  // namespace

TEST_CASE("shadow casters: a closed caster drawn with its faces toward the light leaves the depths both faces do") {
  PBR_REQUIRE_GL();
  const pbr::ShaderLibrary shaders;
  const pbr::MeshData box = pbr::makeBoxMesh();
  pbr::MeshData inward = box;  // every face wound to look in
  for (size_t t = 0; t + 2 < inward.indices.size(); t += 3) std::swap(inward.indices[t + 1], inward.indices[t + 2]);
  pbr::MeshData open = box;  // a triangle drawn twice: its edges no longer pair up, so both faces are drawn
  open.indices.insert(open.indices.end(), box.indices.begin(), box.indices.begin() + 3);
  REQUIRE(pbr::meshClosure(box) == pbr::MeshClosure::Outward);
  REQUIRE(pbr::meshClosure(inward) == pbr::MeshClosure::Inward);
  REQUIRE(pbr::meshClosure(open) == pbr::MeshClosure::Open);

  // A sun straight down, its view 2 m square and its depth range y in [-1, 3] (1 at the top, nearest the light), the
  // image's x along +x and up along -z, as shadows/shadow_views.cpp frames a view looking along the light.
  pbr::ShadowCasterView sun;
  sun.viewProjection = glm::transpose(glm::mat4(1, 0, 0, 0, 0, 0, -1, 0, 0, 0.25f, 0, 0.25f, 0, 0, 0, 1));
  sun.viewport = {0, 0, kSide, kSide};
  // A lamp above and beside the box, looking down; one inside the box, looking down at its floor.
  const auto lamp = [](const glm::vec3& position) {
    pbr::ShadowCasterView v;
    v.viewProjection = pbr::perspectiveView(position, {0.0f, -1.0f, 0.0f}, 1.0f, 10.0f, kSide,
                                            pbr::kShadowBorderTexels).viewProjection;
    v.viewport = {0, 0, kSide, kSide};
    v.reach = glm::vec4(position, 10.0f);
    return v;
  };
  const pbr::ShadowCasterView above = lamp({0.3f, 2.5f, 0.2f}), inside = lamp({0.1f, 0.6f, -0.05f});

  // Mirrored by its pose, the box's quads are split along their other diagonals: compared with the open box
  // mirrored too, since the rasterizer rounds depth across a quad's two splits differently.
  const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), {-1.0f, 1.0f, 1.0f});
  for (const auto& [name, view] : {std::pair<std::string, pbr::ShadowCasterView>{"sun", sun}, {"lamp", above},
                                   {"lamp inside", inside}}) {
    for (const bool mirrored : {false, true}) {
      CAPTURE(name);
      CAPTURE(mirrored);
      const glm::mat4 pose = mirrored ? mirror : glm::mat4(1.0f);
      size_t openOneSided = 1, boxOneSided = 0;
      const std::vector<float> expected = casterDepths(shaders, boxOnly(open, pose), view, &openOneSided);
      CHECK(openOneSided == 0);
      // The box covers part of the view; from inside, all of it.
      CHECK(covered(expected) > size_t(kSide));
      if (name == "lamp inside") {
        CHECK(covered(expected) == expected.size());
      } else {
        CHECK(covered(expected) < expected.size());
      }
      // Straight down, the sun meets the box's top (y = 1, depth 0.25 y + 0.25) before its bottom (0.25): every
      // texel the box covers holds the top's depth.
      if (name == "sun") {
        size_t other = 0;
        for (const float d : expected) other += d == 0.0f || std::abs(d - 0.5f) < 1e-6f ? 0 : 1;
        CHECK(other == 0);
      }
      CHECK(casterDepths(shaders, boxOnly(box, pose), view, &boxOneSided) == expected);
      CHECK(boxOneSided == (name == "lamp inside" ? 0u : 1u));
      CHECK(casterDepths(shaders, boxOnly(inward, pose), view) == expected);
    }
  }
}
