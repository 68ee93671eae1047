#include "app/viewer/overlay.hpp"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>

#include <glm/trigonometric.hpp>

#include "app/viewer/environment_folder.hpp"
#include "app/viewer/overlay_graph.hpp"
#include "app/viewer/viewer.hpp"
#include "core/gl/context.hpp"
#include "core/gl/gl.hpp"
#include "core/scene/exposure.hpp"
#include "core/scene/gltf_file.hpp"
#include "core/scene/gltf_loader.hpp"
#include "core/scene/shadow_settings.hpp"
#include "shadows/shadow_plan.hpp"

namespace pbr {

namespace {

constexpr float kPanelWidth = 380.0f;
constexpr float kMargin = 8.0f;
constexpr float kGraphHeight = 90.0f;
constexpr int kMaxLights = 1 << 20;  // the scene parameters' limit

// One term of the shading variant: its key in parseShadingVariant's text, how many values it has, and access to it.
struct VariantTerm {
  const char* key;
  int count;
  int (*get)(const ShadingVariant&);
  void (*set)(ShadingVariant&, int);
};

const VariantTerm kPbrTerms[] = {
    {"visibility", 3, [](const ShadingVariant& v) { return int(v.visibility); },
     [](ShadingVariant& v, int i) { v.visibility = Visibility(i); }},
    {"ndf", 2, [](const ShadingVariant& v) { return int(v.ndf); }, [](ShadingVariant& v, int i) { v.ndf = Ndf(i); }},
    {"fresnel", 3, [](const ShadingVariant& v) { return int(v.fresnel); },
     [](ShadingVariant& v, int i) { v.fresnel = Fresnel(i); }},
    {"diffuse", 4, [](const ShadingVariant& v) { return int(v.diffuse); },
     [](ShadingVariant& v, int i) { v.diffuse = Diffuse(i); }},
};
const VariantTerm kBlinnPhongTerms[] = {
    {"lobe", 2, [](const ShadingVariant& v) { return int(v.lobe); },
     [](ShadingVariant& v, int i) { v.lobe = BlinnPhongLobe(i); }},
};

// A term's value as the variant's text names it ("exact", "schlick-sg", ...), so that the names are the
// command line's.
std::string termName(const ShadingVariant& variant, const char* key) {
  const std::string text = toString(variant) + "," + toString(variant.lobe) + ",";
  const std::string prefix = std::string(key) + "=";
  const size_t start = text.find(prefix) + prefix.size();
  return text.substr(start, text.find(',', start) - start);
}

void variantCombo(Viewer& viewer, const VariantTerm& term) {
  const ShadingVariant current = viewer.frameOptions().variant;
  if (!ImGui::BeginCombo(term.key, termName(current, term.key).c_str())) return;
  for (int i = 0; i < term.count; ++i) {
    ShadingVariant candidate = current;
    term.set(candidate, i);
    if (ImGui::Selectable(termName(candidate, term.key).c_str(), i == term.get(current))) viewer.setVariant(candidate);
  }
  ImGui::EndCombo();
}

void row(const char* label, const char* format, double value) {
  ImGui::TextUnformatted(label);
  ImGui::SameLine(170.0f);
  ImGui::Text(format, value);
}

}  // namespace

Overlay::Overlay(GLFWwindow* window) {
  IMGUI_CHECKVERSION();
  context_ = ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the layout is the program's: no imgui.ini left in the working directory
  ImGui::StyleColorsDark();
  if (!ImGui_ImplGlfw_InitForOpenGL(window, true)) {
    ImGui::DestroyContext(context_);
    throw ContextError("the overlay's GLFW backend did not start");
  }
  if (!ImGui_ImplOpenGL3_Init("#version 450 core")) {
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext(context_);
    throw ContextError("the overlay's OpenGL backend found no usable libGL.so.1");
  }
}

Overlay::~Overlay() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext(context_);
}

bool Overlay::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool Overlay::wantsKeyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

void Overlay::draw(Viewer& viewer) {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  // Two frames within one tick of the clock would stop ImGui on a zero time step.
  ImGuiIO& io = ImGui::GetIO();
  io.DeltaTime = std::max(io.DeltaTime, 1e-6f);
  ImGui::NewFrame();

  // Measurements at the top right, controls at the top left: the middle of the frame stays in view.
  const ImVec2 maxSize(kPanelWidth, std::max(io.DisplaySize.y - 2.0f * kMargin, 1.0f));
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - kMargin, kMargin), ImGuiCond_Always, ImVec2(1.0f, 0.0f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(kPanelWidth, 0.0f), maxSize);
  ImGui::SetNextWindowBgAlpha(0.8f);
  if (ImGui::Begin("frame", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    const glm::ivec2 size = viewer.frameSize();
    ImGui::Text("%s | %dx%d | %s timing", viewer.options().sceneName.c_str(), size.x, size.y,
                viewer.timingMode() == TimingMode::GpuQueries ? "GPU" : "serialized");
    if (ImGui::CollapsingHeader("Frame time", ImGuiTreeNodeFlags_DefaultOpen)) frameTimes(viewer);
    if (ImGui::CollapsingHeader("Lights", ImGuiTreeNodeFlags_DefaultOpen)) lightStatistics(viewer);
  }
  ImGui::End();
  ImGui::SetNextWindowPos(ImVec2(kMargin, kMargin), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSizeConstraints(ImVec2(kPanelWidth, 0.0f), maxSize);
  ImGui::SetNextWindowBgAlpha(0.8f);
  if (ImGui::Begin("controls", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    if (ImGui::CollapsingHeader("Shading", ImGuiTreeNodeFlags_DefaultOpen)) controls(viewer);
    if (ImGui::CollapsingHeader("Environment", ImGuiTreeNodeFlags_DefaultOpen)) environment(viewer);
    if (ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) camera(viewer);
    if (viewer.playsAnimation() && ImGui::CollapsingHeader("Animation", ImGuiTreeNodeFlags_DefaultOpen)) {
      animation(viewer);
    }
    if (ImGui::CollapsingHeader("Keys")) keys();
  }
  ImGui::End();
  ImGui::Render();

  // Into the window, whatever the renderer left bound; the backend saves and restores the rest of the GL state.
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void Overlay::frameTimes(const Viewer& viewer) {
  const PassHistory& history = viewer.passHistory();
  if (history.frames().empty()) {
    ImGui::TextUnformatted("waiting for the first timed frame");
    return;
  }
  ImGui::Text("%.2f ms, the last %zu frames by pass", history.frames().back().totalMs(), history.frames().size());
  drawPassGraph(history, ImGui::GetContentRegionAvail().x, kGraphHeight);
}

void Overlay::lightStatistics(Viewer& viewer) {
  const LightStats& s = viewer.lightStats();
  const Scene& scene = viewer.scene();
  row("point and spot lights", "%.0f", double(s.lights));
  if (!scene.directionalLights.empty()) row("directional lights", "%.0f", double(scene.directionalLights.size()));
  if (s.decision) {
    ImGui::TextUnformatted(("auto ran " + std::string(toString(s.decision->ran))).c_str());
    const auto predicted = [](const char* label, double ms) {
      if (ms >= 0.0) row(label, "%.3f ms", ms);
    };
    predicted("  predicted clustered", s.decision->clusteredMs);
    predicted("  predicted brute force", s.decision->bruteForceMs);
    predicted("  brute force at least", s.decision->bruteForceAtLeastMs);
    predicted("  untried: a frame up to", s.decision->bruteForceTrialUpToMs);
  }
  if (s.culling == Culling::Clustered) {
    if (viewer.frameOptions().stats) row("visible lights", "%.0f", double(s.visibleLights));
    row("clusters", "%.0f", double(s.clusters));
    row("  tile side", "%.0f px", double(s.tileSize));
    row("  with a surface", "%.0f", double(s.activeClusters));
    row("  with lights", "%.0f", double(s.nonEmptyClusters));
    row("lights per cluster", "%.2f (mean)", s.averagePerNonEmpty());
    row("", "%.0f (max)", double(s.maxPerCluster));
    row("index entries", "%.0f", double(s.indexEntries));
    if (s.overflowedClusters) row("overflowed clusters", "%.0f", double(s.overflowedClusters));
  } else {
    ImGui::TextDisabled("brute force: every light for every pixel");
  }
  if (s.shadows.shadowedLights || s.shadows.unshadowedLights) {
    row("shadowed lights", "%.0f", double(s.shadows.shadowedLights));
    row("  views rendered", "%.0f", double(s.shadows.viewsRendered));
    row("  kept from the frame before", "%.0f", double(s.shadows.viewsKept));
    row("  views skipped", "%.0f (no receiver in view)", double(s.shadows.viewsSkipped));
    row("  planes left out", "%.0f (nothing visible beyond)", double(s.shadows.planesLeftOut));
    row("  one-sided draws", "%.0f (closed casters)", double(s.shadows.oneSidedDraws));
    const int atlas = viewer.frameOptions().shadows.atlasSize;
    row("  atlas used", "%.1f %%", 100.0 * double(s.shadows.texelsUsed) / (double(atlas) * atlas));
    if (s.shadows.cascadeTexelMax > 0.0f) {
      row("  cascade texels from", "%.3g m", double(s.shadows.cascadeTexelMin));
      row("  to", "%.3g m", double(s.shadows.cascadeTexelMax));
    }
    if (s.shadows.reused) ImGui::TextDisabled("  maps kept from the frame before");
    row("  draws", s.shadows.drawsPerLight ? "%.0f (per light)" : "%.0f (per view)", double(s.shadows.draws));
    row("  CPU: plan", "%.2f ms", s.shadows.planMs);
    row("  CPU: recording", "%.2f ms", s.shadows.recordMs);
    if (s.shadows.shrunkLights) row("  shrunk (atlas full)", "%.0f", double(s.shadows.shrunkLights));
    if (s.shadows.unshadowedLights) row("  no map (atlas full)", "%.0f", double(s.shadows.unshadowedLights));
  }
  bool counters = viewer.frameOptions().stats;
  if (ImGui::Checkbox("GPU counters (pairs; cost time)", &counters)) viewer.setGpuCounters(counters);
  if (counters && s.pairs.evaluated) {
    row("pairs evaluated", "%.0f", double(s.pairs.evaluated));
    row("pairs contributing", "%.0f", double(s.pairs.contributing));
    row("culling efficiency", "%.3f", s.cullingEfficiency());
  }
}

void Overlay::shadowControls(Viewer& viewer) {
  ShadowSettings s = viewer.frameOptions().shadows;
  int mode = static_cast<int>(s.mode);
  ImGui::TextUnformatted("shadows");
  ImGui::SameLine(90.0f);
  bool changed = false;
  for (const ShadowMode m : {ShadowMode::Auto, ShadowMode::On, ShadowMode::None}) {
    if (m != ShadowMode::Auto) ImGui::SameLine();
    changed |= ImGui::RadioButton(toString(m), &mode, static_cast<int>(m));
  }
  s.mode = static_cast<ShadowMode>(mode);
  ImGui::Indent();
  ImGui::SetNextItemWidth(120.0f);
  if (ImGui::BeginCombo("filter", toString(s.filter))) {
    for (const ShadowFilter filter : {ShadowFilter::Hard, ShadowFilter::Pcf3x3, ShadowFilter::Poisson16}) {
      if (ImGui::Selectable(toString(filter), filter == s.filter)) {
        s.filter = filter;
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  ImGui::SetNextItemWidth(120.0f);
  const std::string atlasLabel = std::to_string(s.atlasSize) + " (" +
                                 std::to_string(shadowAtlasBytes(s.atlasSize) >> 20) + " MiB)";
  if (ImGui::BeginCombo("atlas", atlasLabel.c_str())) {
    for (int size = kMinShadowAtlas; size <= kMaxShadowAtlas; size *= 2) {
      const std::string label = std::to_string(size) + " (" + std::to_string(shadowAtlasBytes(size) >> 20) + " MiB)";
      if (ImGui::Selectable(label.c_str(), size == s.atlasSize)) {
        s.atlasSize = size;
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  changed |= ImGui::Checkbox("keep still maps", &s.cache);
  ImGui::Unindent();
  if (changed) viewer.setShadows(s);
}

void Overlay::controls(Viewer& viewer) {
  const FrameOptions& f = viewer.frameOptions();
  int model = f.model == ShadingModel::Pbr ? 0 : 1;
  ImGui::TextUnformatted("model");
  ImGui::SameLine(90.0f);
  if (ImGui::RadioButton("PBR", &model, 0)) viewer.setModel(ShadingModel::Pbr);
  ImGui::SameLine();
  if (ImGui::RadioButton("Blinn-Phong", &model, 1)) viewer.setModel(ShadingModel::BlinnPhong);
  ImGui::Indent();
  if (f.model == ShadingModel::Pbr) {
    for (const VariantTerm& term : kPbrTerms) variantCombo(viewer, term);
  } else {
    for (const VariantTerm& term : kBlinnPhongTerms) variantCombo(viewer, term);
  }
  ImGui::Unindent();

  int culling = f.culling == Culling::Clustered ? 0 : f.culling == Culling::None ? 1 : 2;
  ImGui::TextUnformatted("culling");
  ImGui::SameLine(90.0f);
  if (ImGui::RadioButton("clustered", &culling, 0)) viewer.setCulling(Culling::Clustered);
  ImGui::SameLine();
  if (ImGui::RadioButton("none (brute force)", &culling, 1)) viewer.setCulling(Culling::None);
  ImGui::SameLine();
  if (ImGui::RadioButton("auto", &culling, 2)) viewer.setCulling(Culling::Auto);

  shadowControls(viewer);

  // BLEND materials' compositing, for the scenes that have any.
  const bool blends = hasBlendMaterial(viewer.scene());
  if (blends) {
    int transparency = static_cast<int>(f.transparency);
    ImGui::TextUnformatted("blending");
    for (const Transparency t : {Transparency::Sorted, Transparency::Oit, Transparency::Exact}) {
      ImGui::SameLine(t == Transparency::Sorted ? 90.0f : 0.0f);
      if (ImGui::RadioButton(toString(t), &transparency, static_cast<int>(t))) viewer.setTransparency(t);
    }
  }

  // The material extensions the scene uses, each lobe switchable to compare the scene with and without it.
  const MaterialLobes& used = viewer.usedLobes();
  if (f.model == ShadingModel::Pbr && (used.specular || used.clearcoat || used.sheen || used.transmission)) {
    MaterialLobes lobes = viewer.lobes();
    ImGui::TextUnformatted("lobes");
    int shown = 0;
    const auto lobe = [&](bool usedByScene, const char* label, bool& on) {
      if (!usedByScene) return;
      // Two to a line, in the column the other rows' controls start at.
      if (shown % 2 == 0 && shown > 0) ImGui::NewLine();
      ImGui::SameLine(shown % 2 == 0 ? 90.0f : 0.0f);
      ++shown;
      if (ImGui::Checkbox(label, &on)) viewer.setLobes(lobes);
    };
    lobe(used.specular, "ior/specular", lobes.specular);
    lobe(used.clearcoat, "clearcoat", lobes.clearcoat);
    lobe(used.sheen, "sheen", lobes.sheen);
    lobe(used.transmission, "transmission", lobes.transmission);
  }

  if (f.model == ShadingModel::Pbr && ImGui::BeginCombo("tone curve (T)", toString(f.toneCurve))) {
    for (const ToneCurve curve : kToneCurves) {
      if (ImGui::Selectable(toString(curve), f.toneCurve == curve)) viewer.setToneCurve(curve);
    }
    ImGui::EndCombo();
  }

  if (ImGui::BeginCombo("debug view", viewName(viewer.view()))) {
    if (ImGui::Selectable("final", !viewer.view())) viewer.setView(std::nullopt);
    for (const DebugChannel channel : kDebugChannels) {
      if (ImGui::Selectable(toString(channel), viewer.view() == channel)) viewer.setView(channel);
    }
    ImGui::EndCombo();
  }
  if (viewer.view() && needsClusterGrid(*viewer.view()) && f.culling != Culling::Clustered) {
    ImGui::TextDisabled("(the cluster views need clustered culling)");
  }
  const DebugNeeds needs = viewer.view() ? debugChannelInfo(*viewer.view()).needs : DebugNeeds::Nothing;
  if (needs == DebugNeeds::ShadowCaster && !viewer.lightStats().shadows.shadowedLights) {
    ImGui::TextDisabled("(no light casts: shadows on makes every light cast)");
  }
  if (needs == DebugNeeds::BlendSurface && !blends) {
    ImGui::TextDisabled("(no material of the scene blends)");
  }

  bool autoExposure = f.autoExposure;
  if (f.model == ShadingModel::Pbr && ImGui::Checkbox("auto exposure (X)", &autoExposure)) {
    viewer.setAutoExposure(autoExposure);
  }
  if (f.autoExposure && viewer.meteredExposure()) {
    ImGui::SameLine();
    ImGui::TextDisabled("metered EV100 %.2f, adapting 3 EV/s brighter, 1 darker",
                        double(viewer.meteredExposure()->targetEv100));
  }
  // Exposure in stops of the display multiplier, and the camera's EV100 that gives it with the scene's
  // multiplier (the scene file's exposure, EV100 = log2(exposure / (1.2 multiplier))). Either turns the automatic
  // exposure off.
  float stops = std::log2(std::max(f.exposure, 1e-30f));
  if (ImGui::DragFloat("exposure", &stops, 0.02f, -40.0f, 40.0f, "%+.2f stops")) viewer.setExposure(std::exp2(stops));
  ImGui::SameLine();
  ImGui::TextDisabled("x%.3g", f.exposure);
  // Lights are photometric, so every scene has an EV100 that gives this exposure; a scene without one of its own
  // keeps its plain multiplier in a saved file.
  const float sceneExposure = viewer.scene().exposure;
  if (sceneExposure > 0.0f) {
    float ev100 = std::log2(sceneExposure / (1.2f * std::max(f.exposure, 1e-30f)));
    const char* label = viewer.scene().ev100 ? "EV100" : "EV100 (equivalent)";
    if (ImGui::DragFloat(label, &ev100, 0.02f, -kMaxEv100, kMaxEv100, "%.2f")) {
      viewer.setExposure(sceneExposure * static_cast<float>(exposureFromEv100(ev100)));
    }
  }

  int count = lightCountInput_ >= 0 ? lightCountInput_ : static_cast<int>(viewer.lightCount());
  ImGui::SetNextItemWidth(120.0f);
  if (ImGui::InputInt("lights", &count, 0, 0, ImGuiInputTextFlags_EnterReturnsTrue)) {
    viewer.setLightCount(static_cast<size_t>(std::clamp(count, 1, kMaxLights)));
    lightCountInput_ = -1;
  } else {
    lightCountInput_ = ImGui::IsItemActive() ? count : -1;
  }
  ImGui::SameLine();
  if (ImGui::Button("/2")) viewer.setLightCount(std::max<size_t>(viewer.lightCount() / 2, 1));
  ImGui::SameLine();
  if (ImGui::Button("x2")) viewer.setLightCount(std::min<size_t>(viewer.lightCount() * 2, kMaxLights));
  bool paused = viewer.lightsPaused();
  ImGui::SameLine();
  if (ImGui::Checkbox("paused", &paused)) viewer.setPaused(paused);
}

void Overlay::environment(Viewer& viewer) {
  const std::optional<EnvironmentDesc>& current = viewer.scene().environment;
  if (!environmentsListed_) {
    environmentFolder_ = environmentFolder(viewer.options().environmentFolder, current);
    environmentFiles_ = hdrFiles(environmentFolder_);
    environmentsListed_ = true;
  }
  ImGui::TextWrapped("%s", environmentFolder_.c_str());
  ImGui::SameLine();
  if (ImGui::SmallButton("rescan")) environmentsListed_ = false;
  const auto pick = [&](const std::string& label, const std::string& choice, bool selected) {
    if (ImGui::Selectable(label.c_str(), selected) && !selected) {
      environmentMessage_ = viewer.setEnvironment(choice);
    }
  };
  if (ImGui::BeginListBox("##environments", ImVec2(-1.0f, 6.0f * ImGui::GetTextLineHeightWithSpacing()))) {
    pick("none", "none", !current);
    pick("sky (procedural)", "sky", current && current->file.empty());
    for (const std::string& file : environmentFiles_) {
      std::error_code error;
      const bool selected =
          current && !current->file.empty() && std::filesystem::equivalent(current->file, file, error);
      pick(std::filesystem::path(file).filename().string(), file, selected);
    }
    ImGui::EndListBox();
  }
  if (environmentFiles_.empty()) ImGui::TextDisabled("no .hdr files in that folder (--env-dir DIR)");
  if (!environmentMessage_.empty()) ImGui::TextWrapped("%s", environmentMessage_.c_str());
}

void Overlay::animation(Viewer& viewer) {
  for (const std::shared_ptr<const GltfPlayback>& p : viewer.scene().gltfPlayback) {
    ImGui::TextWrapped("%s: %s, %.2f s", std::filesystem::path(p->file->path).filename().string().c_str(),
                       p->animationName.c_str(), p->duration);
  }
  float time = static_cast<float>(viewer.animationTime());
  ImGui::SetNextItemWidth(-80.0f);
  if (ImGui::SliderFloat("time (s)", &time, 0.0f, static_cast<float>(viewer.animationDuration()), "%.2f")) {
    viewer.setAnimationTime(time);
  }
  bool paused = viewer.lightsPaused();
  if (ImGui::Checkbox("paused (P)", &paused)) viewer.setPaused(paused);
}

void Overlay::camera(Viewer& viewer) {
  const OrbitCamera& orbit = viewer.camera();
  const Camera& c = orbit.camera();
  ImGui::Text("position  %8.3f %8.3f %8.3f", c.position.x, c.position.y, c.position.z);
  ImGui::Text("target    %8.3f %8.3f %8.3f", c.target.x, c.target.y, c.target.z);
  ImGui::Text("yaw %.1f deg, pitch %.1f deg, distance %.3f", glm::degrees(orbit.yaw()), glm::degrees(orbit.pitch()),
              orbit.distance());
  if (c.orthographic) {
    ImGui::Text("orthographic, half height %.3g, near %.3g, far %.3g", c.orthoHalfHeight, c.nearPlane, c.farPlane);
  } else {
    ImGui::Text("fov %.1f deg (vertical), near %.3g, far %.3g", c.fovYDeg, c.nearPlane, c.farPlane);
  }
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::InputText("##scene file", scenePath_, sizeof scenePath_);
  if (ImGui::Button("save as scene JSON")) {
    try {
      viewer.saveScene(scenePath_);
      sceneMessage_ = std::string("wrote ") + scenePath_ + " (pbr render --scene " + scenePath_ + ")";
    } catch (const std::exception& e) {
      sceneMessage_ = e.what();
    }
  }
  if (!sceneMessage_.empty()) ImGui::TextWrapped("%s", sceneMessage_.c_str());
}

void Overlay::keys() {
  for (const KeyHelp& key : viewerKeys()) {
    ImGui::TextUnformatted(key.keys.c_str());
    ImGui::SameLine(110.0f);
    ImGui::TextWrapped("%s", key.action.c_str());
  }
}

}  // namespace pbr
