#include "view_panel.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

namespace throng::tools {
namespace {

void statistics(const PanelInfo& info) {
  const ViewStats& s = *info.stats;
  ImGui::Text("%.1f fps  (%.2f ms per frame)", s.fps(), s.frameMs());
  const PassTimes& gpu = s.last();
  ImGui::Text("GPU ms: synthesis %.2f, render %.2f, panel %.2f", gpu.synthesisMs, gpu.renderMs,
              gpu.panelMs);
  ImGui::Text("%s", info.device.c_str());
  ImGui::Text("%ux%u, %s, %s clock", info.width, info.height, info.presentMode.c_str(),
              info.clock.c_str());
  ImGui::Text("%u characters x %u joints, %llu active", info.characters, info.jointsPerCharacter,
              static_cast<unsigned long long>(info.lod.activeJoints));
  const render::Camera& c = *info.camera;
  ImGui::Text("eye %.1f %.1f %.1f  target %.1f %.1f %.1f", c.eye.x, c.eye.y, c.eye.z, c.target.x,
              c.target.y, c.target.z);
}

void sceneControls(PanelControls& c, const PanelInfo& info) {
  ImGui::InputInt("characters", &c.characters, 100, 1000);
  c.characters = std::clamp(c.characters, 1, 4000000);
  ImGui::Combo("scenario", &c.scenario, kScenarioNames,
               c.storyboardAvailable ? IM_ARRAYSIZE(kScenarioNames) : kStoryboardScenario);
  ImGui::InputInt("seed", &c.seed);
  ImGui::SliderFloat("density", &c.density, 0.05f, 4.0f, "%.2f /m2");
  ImGui::DragFloatRange2("speed w", &c.speedMin, &c.speedMax, 0.01f, 0.0f, 1.0f, "%.2f", "%.2f");
  ImGui::SliderFloat("speed period", &c.speedPeriod, 0.0f, 30.0f,
                     c.speedPeriod > 0.0f ? "%.1f s" : "off");
  if (ImGui::Button("respawn")) c.respawn = true;
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("a new crowd with this count, scenario, seed and density\n%s",
                      info.clips.c_str());
}

void playbackAndCamera(PanelControls& c) {
  ImGui::Checkbox("pause", &c.paused);
  ImGui::SameLine();
  if (ImGui::Button("step")) c.step = true;
  ImGui::SameLine();
  ImGui::Checkbox("vsync", &c.vsync);
  ImGui::SliderFloat("time scale", &c.timeScale, 0.0f, 4.0f, "%.2fx");
  for (int i = 0; i < IM_ARRAYSIZE(kPresetNames); ++i) {
    if (i > 0) ImGui::SameLine();
    if (ImGui::Button(kPresetNames[i])) c.preset = i;
  }
  if (ImGui::Button("reset camera")) c.resetCamera = true;
  ImGui::SameLine();
  if (ImGui::Button("screenshot")) c.screenshot = true;
}

void bindings() {
  ImGui::TextDisabled("left drag: orbit   right/middle drag: pan");
  ImGui::TextDisabled("wheel: zoom   W A S D Q E: fly (Shift x4)");
  ImGui::TextDisabled("1-4: wide/top/street/closeup   R: reset");
  ImGui::TextDisabled("Space: pause   N: step   V: vsync");
  ImGui::TextDisabled("Tab/F1: panel   F12: screenshot   Esc: quit");
}

// The coverage LOD: on/off (respawns), live thresholds and tint, and what this frame's masks
// say. The motion cache's settings apply on respawn, its counters are live.
void lod(PanelControls& c, const PanelInfo& info) {
  ImGui::Checkbox("coverage LOD", &c.lod);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("switching it respawns the crowd");
  ImGui::SameLine();
  ImGui::BeginDisabled(!info.lodEnabled);
  ImGui::Checkbox("tint", &c.lodTint);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("green near, yellow mid, red far");
  ImGui::EndDisabled();
  // Live: a character gets a level once its projected standing height reaches this many pixels.
  const ImGuiSliderFlags log = ImGuiSliderFlags_Logarithmic;
  ImGui::SliderFloat("mid height", &c.lodMidPixels, 0.0f, 4096.0f, "mid from %.0f px tall", log);
  ImGui::SliderFloat("near height", &c.lodNearPixels, 0.0f, 4096.0f, "all joints from %.0f px tall",
                     log);
  const LodStats& s = info.lod;
  const double all = double(info.characters) * info.jointsPerCharacter;
  ImGui::Text("active joints %llu (%.1f%%)", static_cast<unsigned long long>(s.activeJoints),
              all > 0.0 ? 100.0 * double(s.activeJoints) / all : 0.0);
  ImGui::Text("far %llu  mid %llu  near %llu", static_cast<unsigned long long>(s.levels[0]),
              static_cast<unsigned long long>(s.levels[1]),
              static_cast<unsigned long long>(s.levels[2]));
  if (!info.lodEnabled) ImGui::TextDisabled("LOD off: every joint of every character");
}

void cache(PanelControls& c, const PanelInfo& info) {
  ImGui::Checkbox("motion cache", &c.cache);
  ImGui::SameLine();
  ImGui::TextDisabled("(on respawn)");
  ImGui::SliderFloat("budget", &c.cacheBudgetMb, 1.0f, 256.0f, "%.0f MB");
  ImGui::SliderFloat("bucket width", &c.bucketWidth, 0.01f, 0.25f, "w %.3f");
  if (!info.cacheEnabled) {
    ImGui::TextDisabled("cache off in this crowd");
    return;
  }
  const synth::MotionCacheStats& s = info.cache;
  ImGui::Text("hits %u  misses %u  evictions %u", s.hits, s.misses, s.evictions);
  ImGui::Text("%u entries, %.2f of %.2f MB", s.entries, s.bytesUsed / 1048576.0,
              s.budgetBytes / 1048576.0);
}

// The capes of the newest completed frame, as the cloth layer counted and timed them.
void capes(const PanelInfo& info) {
  const ClothFrameStats& f = info.stats->cloth();
  ImGui::TextDisabled("%s", info.clothFile.c_str());
  if (f.frame == 0) {
    ImGui::TextDisabled("no frame completed yet");
    return;
  }
  const CapeCounts n = capeCounts(f.capes, info.clothSplat);
  ImGui::Text("states decoded %u  (demoted %u)", f.capes.usedStates, f.capes.demoted);
  ImGui::Text("capes: triangles %u  coarse %u  splatted %u", n.triangles, n.coarse, n.splatted);
  ImGui::TextDisabled("levels 0-3: %u / %u / %u / %u", f.capes.capes[0], f.capes.capes[1],
                      f.capes.capes[2], f.capes.capes[3]);
  ImGui::Text("cloth GPU ms %.2f: decode %.2f, draw %.2f, splat %.2f", f.gpu.totalMs(),
              f.gpu.decodeMs, f.gpu.drawMs, f.gpu.splatMs);
  ImGui::TextDisabled("advance %.2f, mark %.2f", f.gpu.advanceMs, f.gpu.markMs);
}

void lodAndCache(PanelControls& c, const PanelInfo& info) {
  lod(c, info);
  ImGui::Separator();
  cache(c, info);
}

}  // namespace

PanelRect drawPanel(PanelControls& controls, const PanelInfo& info) {
  PanelRect rect;
  ImGui::SetNextWindowPos(ImVec2(kPanelX, kPanelY), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.85f);
  if (ImGui::Begin("throng (Tab hides)", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::PushItemWidth(ImGui::GetFontSize() * 11.0f);
    if (ImGui::CollapsingHeader("statistics", ImGuiTreeNodeFlags_DefaultOpen)) statistics(info);
    if (ImGui::CollapsingHeader("crowd", ImGuiTreeNodeFlags_DefaultOpen))
      sceneControls(controls, info);
    if (ImGui::CollapsingHeader("playback and camera", ImGuiTreeNodeFlags_DefaultOpen))
      playbackAndCamera(controls);
    if (ImGui::CollapsingHeader("LOD and cache", ImGuiTreeNodeFlags_DefaultOpen))
      lodAndCache(controls, info);
    if (info.clothEnabled && ImGui::CollapsingHeader("capes", ImGuiTreeNodeFlags_DefaultOpen))
      capes(info);
    if (ImGui::CollapsingHeader("keys and mouse")) bindings();
    ImGui::PopItemWidth();
    if (!controls.message.empty()) {
      ImGui::PushTextWrapPos(ImGui::GetFontSize() * 20.0f);
      ImGui::TextUnformatted(controls.message.c_str());
      ImGui::PopTextWrapPos();
    }
  }
  ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  rect = {pos.x, pos.y, size.x, size.y};
  ImGui::End();
  return rect;
}

}  // namespace throng::tools
