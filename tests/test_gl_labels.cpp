// What a graphics debugger shows of the renderer: a label on every GL object it makes, a debug group per pass
// named as the pass list, and the marks of a captured frame. Read back through KHR_debug on the test's context:
// glGetObjectLabel for labels, a debug callback for the groups and markers.
#include <doctest/doctest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "core/gl/frame_capture.hpp"
#include "core/gl/program_cache.hpp"
#include "core/scene/builtin_scenes.hpp"
#include "lighting/lighting_bindings.hpp"
#include "lighting/lighting_pass.hpp"
#include "renderer/renderer.hpp"
#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"

using namespace pbr;

namespace {

std::string objectLabel(GLenum kind, GLuint id) {
  GLint maxLength = 0;
  glGetIntegerv(GL_MAX_LABEL_LENGTH, &maxLength);
  std::string label(static_cast<size_t>(std::max(maxLength, 1)), '\0');
  GLsizei length = 0;
  glGetObjectLabel(kind, id, static_cast<GLsizei>(label.size()), &length, label.data());
  label.resize(static_cast<size_t>(length));
  return label;
}

struct LiveObject {
  const char* kind;
  GLuint id;
  std::string label;
};

// Every GL object alive in the context, found by asking each kind's glIs* of every name up to a bound well past
// what one renderer makes: names are small integers handed out in order, and each test case runs in a process of
// its own, so these are the objects the case made.
std::vector<LiveObject> liveObjects() {
  struct Kind {
    const char* name;
    GLenum identifier;
    GLboolean (*is)(GLuint);
  };
  const Kind kinds[] = {{"buffer", GL_BUFFER, glIsBuffer},
                        {"texture", GL_TEXTURE, glIsTexture},
                        {"framebuffer", GL_FRAMEBUFFER, glIsFramebuffer},
                        {"vertex array", GL_VERTEX_ARRAY, glIsVertexArray},
                        {"program", GL_PROGRAM, glIsProgram},
                        {"sampler", GL_SAMPLER, glIsSampler},
                        {"query", GL_QUERY, glIsQuery}};
  constexpr GLuint kHighestName = 4096;
  std::vector<LiveObject> out;
  for (const Kind& k : kinds) {
    for (GLuint id = 1; id <= kHighestName; ++id) {
      if (k.is(id)) out.push_back({k.name, id, objectLabel(k.identifier, id)});
    }
  }
  return out;
}

struct DebugMessage {
  GLenum type;
  std::string text;
};

// Collects the application's debug groups and markers while it lives: debug output on and synchronous, every
// message enabled, a callback of its own; the context's previous callback and state come back afterwards.
class DebugMessageLog {
 public:
  DebugMessageLog()
      : wasEnabled_(glIsEnabled(GL_DEBUG_OUTPUT)), wasSynchronous_(glIsEnabled(GL_DEBUG_OUTPUT_SYNCHRONOUS)) {
    glGetPointerv(GL_DEBUG_CALLBACK_FUNCTION, &previousCallback_);
    glGetPointerv(GL_DEBUG_CALLBACK_USER_PARAM, &previousUser_);
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
    glDebugMessageCallback(collect, this);
  }
  ~DebugMessageLog() {
    glDebugMessageCallback(reinterpret_cast<GLDEBUGPROC>(previousCallback_), previousUser_);
    if (!wasSynchronous_) glDisable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    if (!wasEnabled_) glDisable(GL_DEBUG_OUTPUT);
  }
  DebugMessageLog(const DebugMessageLog&) = delete;
  DebugMessageLog& operator=(const DebugMessageLog&) = delete;

  const std::vector<DebugMessage>& messages() const { return messages_; }
  void clear() { messages_.clear(); }

 private:
  static void GLAD_API_PTR collect(GLenum source, GLenum type, GLuint, GLenum, GLsizei length, const GLchar* text,
                                   const void* self) {
    if (source != GL_DEBUG_SOURCE_APPLICATION) return;
    if (type != GL_DEBUG_TYPE_PUSH_GROUP && type != GL_DEBUG_TYPE_POP_GROUP && type != GL_DEBUG_TYPE_MARKER) return;
    auto* log = static_cast<DebugMessageLog*>(const_cast<void*>(self));
    log->messages_.push_back({type, length < 0 ? std::string(text) : std::string(text, static_cast<size_t>(length))});
  }

  GLboolean wasEnabled_, wasSynchronous_;
  void* previousCallback_ = nullptr;
  void* previousUser_ = nullptr;
  std::vector<DebugMessage> messages_;
};

// The groups opened at nesting depth `depth` (0: outermost), in order. Fails the case when the pushes and pops
// do not pair up, each pop naming the group it closes.
std::vector<std::string> groupsAtDepth(const std::vector<DebugMessage>& messages, size_t depth) {
  std::vector<std::string> open, out;
  for (const DebugMessage& m : messages) {
    if (m.type == GL_DEBUG_TYPE_PUSH_GROUP) {
      if (open.size() == depth) out.push_back(m.text);
      open.push_back(m.text);
    } else if (m.type == GL_DEBUG_TYPE_POP_GROUP) {
      REQUIRE_MESSAGE(!open.empty(), "a debug group is popped that was never pushed: " << m.text);
      CHECK(open.back() == m.text);
      open.pop_back();
    }
  }
  CHECK_MESSAGE(open.empty(), "debug groups left open: " << open.size());
  return out;
}

// The groups opened directly inside the first group named `parent`.
std::vector<std::string> groupsInside(const std::vector<DebugMessage>& messages, const std::string& parent) {
  std::vector<std::string> out;
  int depth = -1;  // of the parent, once open
  int current = 0;
  for (const DebugMessage& m : messages) {
    if (m.type == GL_DEBUG_TYPE_PUSH_GROUP) {
      if (depth >= 0 && current == depth + 1) out.push_back(m.text);
      if (depth < 0 && m.text == parent) depth = current;
      ++current;
    } else if (m.type == GL_DEBUG_TYPE_POP_GROUP) {
      --current;
      if (current == depth) break;
    }
  }
  return out;
}

std::vector<std::string> names(const PassList& passes) {
  std::vector<std::string> out;
  for (const FramePass& p : passes) out.push_back(p.name);
  return out;
}

Scene litScene() {
  Scene scene = makeBuiltinScene("default");
  scene.environment = EnvironmentDesc{};  // the procedural sky: IBL maps, samplers and their precomputation
  return scene;
}

}  // namespace

TEST_CASE("labels: every GL object a renderer makes is labelled, the G-buffer, cluster lists and programs by name") {
  PBR_REQUIRE_GL();
  const ShaderLibrary shaders;
  const Scene scene = litScene();
  Renderer renderer(shaders, scene, 64, 36);
  Profiler profiler(TimingMode::GpuQueries);  // timestamp queries are objects too
  FrameOptions options;
  options.stats = true;
  options.aa = AntiAliasing::Fxaa;
  options.debug = DebugChannel::Clusters;
  ImageRgba8 ldr;
  renderer.renderFrame(options, profiler, {&ldr, nullptr});
  options.model = ShadingModel::BlinnPhong;
  options.culling = Culling::None;
  renderer.renderFrame(options, profiler);
  profiler.takeResults(true);

  const GBuffer& g = renderer.gbuffer();
  CHECK(objectLabel(GL_TEXTURE, g.baseColor.id()) == "gbuffer.baseColor");
  CHECK(objectLabel(GL_TEXTURE, g.normal.id()) == "gbuffer.normal");
  CHECK(objectLabel(GL_TEXTURE, g.material.id()) == "gbuffer.material");
  CHECK(objectLabel(GL_TEXTURE, g.depth.id()) == "gbuffer.depth");
  CHECK(objectLabel(GL_FRAMEBUFFER, g.framebuffer.id()) == "gbuffer");
  CHECK(objectLabel(GL_TEXTURE, renderer.ldr().id()) == "frame.display");
  CHECK(objectLabel(GL_TEXTURE, renderer.ibl()->specular().id()) == "ibl.specular");
  CHECK(objectLabel(GL_BUFFER, renderer.ibl()->irradiance().id()) == "ibl.irradiance");

  const std::vector<LiveObject> objects = liveObjects();
  std::set<std::string> labels;
  for (const LiveObject& o : objects) {
    CAPTURE(o.kind);
    CAPTURE(o.id);
    CHECK_MESSAGE(!o.label.empty(), "an unlabelled " << o.kind << " " << o.id);
    labels.insert(o.label);
  }
  // The enumeration sees the renderer: at least the objects named here, and many more.
  CHECK(objects.size() > 40);
  for (const char* name : {"clusters.lightIndices", "clusters.headers", "clusters.block", "clusters.slotMasks",
                           "clusters.visibleLights", "lights.points", "lights.directional", "frame.block",
                           "frame.radiance", "frame.beforeAntiAliasing", "gbuffer.objectBlocks", "mesh 0.vertices",
                           "mesh 0", "lighting.pairStats", "post.block", "fxaa.sampler", "ibl.dfg",
                           "ibl.dfg.sampler", "profiler.timestamp"}) {
    CHECK_MESSAGE(labels.count(name), "no object labelled " << name);
  }
  // Programs: the file and the defines that choose the permutation, binding points and switches off left out.
  const auto program = [&](const std::string& prefix) {
    return std::count_if(labels.begin(), labels.end(), [&](const std::string& l) { return l.rfind(prefix, 0) == 0; });
  };
  CHECK(program("lighting/deferred.comp [") >= 2);  // PBR clustered, Blinn-Phong brute force
  // The light pass in one invocation per light and in one workgroup per large light.
  CHECK(program("lighting/cluster_lights.comp") == 2);
  CHECK(program("lighting/cluster_fill.comp") == 1);
  CHECK(program("gbuffer/gbuffer.vert + gbuffer/gbuffer.frag") >= 1);
  CHECK(labels.count("post/fxaa.comp"));
  CHECK(program("lighting.ambientAlbedo [") == 0);  // IBL replaces the ambient table
  for (const std::string& l : labels) {
    CHECK_MESSAGE(l.find("_UBO") == std::string::npos, l);
    CHECK_MESSAGE(l.find("_SSBO") == std::string::npos, l);
  }
}

TEST_CASE("labels: a program's label is its file and the defines of its permutation") {
  PBR_REQUIRE_GL();
  const ShaderLibrary shaders;
  ProgramCache programs(shaders);
  LightingOptions options;
  const ShaderDefines defines =
      concat(lightingPermutation(options, true, HdrFormat::Rgba16f), lightingBindingDefines());
  const std::string label = objectLabel(GL_PROGRAM, programs.compute("lighting/deferred.comp", defines).id());
  CHECK(label == programLabel("lighting/deferred.comp", defines));
  CHECK(label.rfind("lighting/deferred.comp [", 0) == 0);
  CHECK(label.find(" CLUSTERED") != std::string::npos);
  CHECK(label.find("HDR_IMAGE_FORMAT=rgba16f") != std::string::npos);
  CHECK(label.find("LIGHTING_STATS") == std::string::npos);  // off
  CHECK(label.find("LIGHT_SSBO") == std::string::npos);      // a binding point
}

TEST_CASE("labels: a label longer than the driver takes is cut to GL_MAX_LABEL_LENGTH") {
  PBR_REQUIRE_GL();
  GLint maxLength = 0;
  glGetIntegerv(GL_MAX_LABEL_LENGTH, &maxLength);
  REQUIRE(maxLength >= 256);  // the GL 4.3 minimum
  const std::string longLabel(static_cast<size_t>(maxLength) + 10, 'x');
  const Buffer buffer(longLabel, 4);
  CHECK(glGetError() == GL_NO_ERROR);
  CHECK(objectLabel(GL_BUFFER, buffer.id()) == longLabel.substr(0, static_cast<size_t>(maxLength) - 1));
}

TEST_CASE("debug groups: a frame is one group per pass, named and ordered as its pass list, each closed") {
  PBR_REQUIRE_GL();
  const ShaderLibrary shaders;
  const Scene scene = makeBuiltinScene("default");
  Renderer renderer(shaders, scene, 64, 36);
  Profiler profiler(TimingMode::Serializing);
  FrameOptions options;
  options.aa = AntiAliasing::Fxaa;
  options.debug = DebugChannel::Slices;
  ImageRgba8 ldr;
  const FrameCapture capture{&ldr, nullptr};
  renderer.renderFrame(options, profiler, capture);  // compiles and sizes: not what is checked

  DebugMessageLog log;
  renderer.renderFrame(options, profiler, capture);
  const std::vector<std::string> passes = names(renderer.passList(options, capture));
  REQUIRE(passes == std::vector<std::string>{"gbuffer", "cluster", "lighting", "post", "aa", "debug", "readback"});
  CHECK(groupsAtDepth(log.messages(), 0) == passes);
  // The cluster pass's five compute passes, as README's pipeline lists them.
  CHECK(groupsInside(log.messages(), "cluster") ==
        std::vector<std::string>{"cluster occupancy", "cluster activate", "cluster lights", "cluster scan",
                                 "cluster fill"});
  const size_t pushes = std::count_if(log.messages().begin(), log.messages().end(),
                                      [](const DebugMessage& m) { return m.type == GL_DEBUG_TYPE_PUSH_GROUP; });
  const size_t pops = std::count_if(log.messages().begin(), log.messages().end(),
                                    [](const DebugMessage& m) { return m.type == GL_DEBUG_TYPE_POP_GROUP; });
  CHECK(pushes == pops);

  // Brute force, Blinn-Phong: another pass list, the same rule.
  log.clear();
  options = FrameOptions{};
  options.model = ShadingModel::BlinnPhong;
  options.culling = Culling::None;
  renderer.renderFrame(options, profiler);
  CHECK(groupsAtDepth(log.messages(), 0) == names(renderer.passList(options)));
}

TEST_CASE("debug groups: untimed IBL precomputation is a group holding its four passes") {
  PBR_REQUIRE_GL();
  const ShaderLibrary shaders;
  const Scene scene = litScene();
  DebugMessageLog log;
  const Renderer renderer(shaders, scene, 64, 36);  // no precomputation profiler
  CHECK(groupsAtDepth(log.messages(), 0) == std::vector<std::string>{"ibl precompute"});
  CHECK(groupsInside(log.messages(), "ibl precompute") ==
        std::vector<std::string>{"ibl environment", "ibl irradiance", "ibl specular", "ibl dfg"});
}

TEST_CASE("capture: frame K opens with a debug marker and is one group around exactly its passes") {
  PBR_REQUIRE_GL();
  const ShaderLibrary shaders;
  const Scene scene = makeBuiltinScene("default");
  Renderer renderer(shaders, scene, 64, 36);
  Profiler profiler(TimingMode::Serializing);
  const FrameCapturer capturer;
  if (!capturer.renderDoc()) CHECK(capturer.describe(2).find("RenderDoc not found") != std::string::npos);
  renderer.captureFrame(2, capturer);
  const FrameOptions options;
  const std::vector<std::string> passes = names(renderer.passList(options));

  DebugMessageLog log;
  for (int i = 0; i < 3; ++i) renderer.renderFrame(options, profiler);
  std::vector<std::string> markers;
  for (const DebugMessage& m : log.messages()) {
    if (m.type == GL_DEBUG_TYPE_MARKER) markers.push_back(m.text);
  }
  CHECK(markers == std::vector<std::string>{"capture frame 2"});
  std::vector<std::string> expected = passes;
  expected.push_back("capture frame 2");
  expected.insert(expected.end(), passes.begin(), passes.end());
  CHECK(groupsAtDepth(log.messages(), 0) == expected);
  CHECK(groupsInside(log.messages(), "capture frame 2") == passes);
  // The marker comes right before the group it announces.
  const auto marker = std::find_if(log.messages().begin(), log.messages().end(),
                                   [](const DebugMessage& m) { return m.type == GL_DEBUG_TYPE_MARKER; });
  REQUIRE(marker + 1 != log.messages().end());
  CHECK((marker + 1)->type == GL_DEBUG_TYPE_PUSH_GROUP);
  CHECK((marker + 1)->text == "capture frame 2");
}

TEST_CASE("capture: pbr render --capture-frame without RenderDoc says so and renders") {
  const test::TempDir dir;
  const test::PbrRun run =
      test::runPbr(dir, {"render", "--size", "64x36", "--warmup", "0", "--frames", "1", "--capture-frame", "3"});
  CHECK(run.exitCode == 0);
  CHECK(run.out.find("capture: RenderDoc not found (not injected into this process): frame 3 is marked by the debug "
                     "group and marker 'capture frame 3' only") != std::string::npos);
}

TEST_CASE("capture: pbr render --capture-frame under RenderDoc captures exactly that frame through its API") {
#ifdef __SANITIZE_ADDRESS__
  MESSAGE("skipped: AddressSanitizer must come first among preloaded libraries");
#else
  const test::TempDir dir;
  const test::PbrRun run = test::runPbr(
      dir, {"render", "--size", "64x36", "--warmup", "0", "--frames", "1", "--capture-frame", "2"},
      std::string("export LD_PRELOAD=") + PBR_FAKE_RENDERDOC + ";");
  CHECK(run.exitCode == 0);
  CHECK(run.out.find("capture: RenderDoc (API 1.1.2) captures frame 2, marked by the debug group and marker "
                     "'capture frame 2'") != std::string::npos);
  // One capture, of the current context and any window, started before it ends.
  const std::string start = "fake RenderDoc: StartFrameCapture(null, null)\n";
  const std::string end = "fake RenderDoc: EndFrameCapture(null, null)\n";
  const size_t started = run.err.find(start), ended = run.err.find(end);
  REQUIRE(started != std::string::npos);
  REQUIRE(ended != std::string::npos);
  CHECK(started < ended);
  CHECK(run.err.find(start, started + 1) == std::string::npos);
  CHECK(run.err.find(end, ended + 1) == std::string::npos);
#endif
}
