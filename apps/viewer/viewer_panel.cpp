#include "viewer_panel.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>
#include <imgui.h>

namespace penumbra::viewer {

namespace {

// One option's control, chosen by its kind; returns the value to set when it was changed.
std::optional<std::string> optionControl(const OptionControl& option) {
  const OptionSpec& spec = *option.spec;
  const std::string label = spec.name;
  switch (spec.kind) {
    case OptionKind::Flag: {
      bool on = option.value == "true";
      if (ImGui::Checkbox(label.c_str(), &on)) return on ? "true" : "false";
      break;
    }
    case OptionKind::Choice: {
      int current = int(std::find(spec.choices.begin(), spec.choices.end(), option.value) -
                        spec.choices.begin());
      if (ImGui::BeginCombo(label.c_str(), option.value.c_str())) {
        for (int i = 0; i < int(spec.choices.size()); ++i) {
          if (ImGui::Selectable(spec.choices[i].c_str(), i == current)) return spec.choices[i];
        }
        ImGui::EndCombo();
      }
      break;
    }
    case OptionKind::Integer: {
      int64_t value = std::stoll(option.value);
      const bool changed =
          spec.max - spec.min <= 4096
              ? ImGui::SliderScalar(label.c_str(), ImGuiDataType_S64, &value, &spec.min, &spec.max)
              : ImGui::InputScalar(label.c_str(), ImGuiDataType_S64, &value);
      if (changed) return std::to_string(std::clamp(value, spec.min, spec.max));
      break;
    }
    case OptionKind::Number: {
      double value = std::stod(option.value);
      const bool bounded = std::isfinite(spec.number_min) && std::isfinite(spec.number_max) &&
                           spec.number_max - spec.number_min < 1e6;
      const bool changed =
          bounded ? ImGui::SliderScalar(label.c_str(), ImGuiDataType_Double, &value,
                                        &spec.number_min, &spec.number_max, "%.4g")
                  : ImGui::InputDouble(label.c_str(), &value, 0.0, 0.0, "%.6g");
      if (changed) return formatNumber(std::clamp(value, spec.number_min, spec.number_max));
      break;
    }
  }
  if (ImGui::IsItemHovered() && !spec.help.empty()) ImGui::SetTooltip("%s", spec.help.c_str());
  return std::nullopt;
}

void techniqueSection(ViewerModel& model, PanelRequests& requests) {
  if (!ImGui::CollapsingHeader("Technique", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const TechniqueEntry& current = currentTechnique(model);
  if (ImGui::BeginCombo("technique", current.info->name.c_str())) {
    for (const TechniqueEntry& entry : model.techniques) {
      if (ImGui::Selectable(entry.info->name.c_str(), &entry == &current)) {
        selectTechnique(model, entry.info->name);
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", entry.info->summary.c_str());
    }
    ImGui::EndCombo();
  }
  for (const OptionControl& option : currentTechnique(model).options) {
    ImGui::PushID(option.spec->name.c_str());
    if (const auto value = optionControl(option)) {
      try {
        setOption(model, option.spec->name, *value);
      } catch (const std::exception& e) {
        requests.error = e.what();
      }
    }
    ImGui::PopID();
  }
}

void lightSection(ViewerModel& model) {
  if (!ImGui::CollapsingHeader("Lights", ImGuiTreeNodeFlags_DefaultOpen)) return;
  for (size_t i = 0; i < model.lights.size(); ++i) {
    const std::string label = fmt::format("{} {}", i, lightShapeName(model.lights[i].shape));
    if (ImGui::RadioButton(label.c_str(), model.selected_light == i)) selectLight(model, i);
    ImGui::SameLine();
  }
  ImGui::NewLine();
  Light& light = model.lights[model.selected_light];
  ImGui::Text("centre %.3f %.3f %.3f", light.center.x, light.center.y, light.center.z);
  float intensity = light.intensity;
  if (ImGui::SliderFloat("intensity", &intensity, 0.0f, 4.0f)) setLightIntensity(model, intensity);
  if (light.shape == LightShape::Rectangle) {
    float w = glm::length(light.edge_u), h = glm::length(light.edge_v), turn = 0.0f;
    const bool changed = ImGui::SliderFloat("width", &w, 0.01f, 4.0f) |
                         ImGui::SliderFloat("height", &h, 0.01f, 4.0f) |
                         ImGui::SliderFloat("turn (deg)", &turn, -10.0f, 10.0f);
    if (changed) setRectangleLight(model, w, h, turn);
    return;
  }
  float radius = light.radius;
  if (ImGui::SliderFloat("radius", &radius, 0.0f, std::max(2.0f, 2.0f * light.radius))) {
    setLightRadius(model, radius);
  }
  if (light.shape == LightShape::Disk) {
    float tilt = glm::degrees(std::acos(std::clamp(-light.normal.y, -1.0f, 1.0f)));
    float azimuth = glm::degrees(std::atan2(light.normal.z, light.normal.x));
    if (ImGui::SliderFloat("tilt (deg)", &tilt, 0.0f, 89.0f) |
        ImGui::SliderFloat("azimuth (deg)", &azimuth, -180.0f, 180.0f)) {
      setDiskNormal(model, tilt, azimuth);
    }
  }
}

void frameSection(ViewerModel& model, const PanelView& view) {
  if (!ImGui::CollapsingHeader("Frame", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::SliderFloat("preview scale", &model.preview_scale, 0.125f, 1.0f, "%.3f");
  ImGui::Checkbox("fewer samples while dragging", &model.preview_samples);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("options with a preview value (exact's samples, the oracle's rays) take "
                      "it while the view moves");
  }
  if (ImGui::SliderInt("threads", &model.threads, 0, 16, model.threads == 0 ? "all" : "%d")) {
    ++model.generation;
  }
  if (ImGui::Checkbox("SIMD", &model.simd)) ++model.generation;
  if (ImGui::BeginCombo("overlay", overlayName(model.overlay).c_str())) {
    for (Overlay overlay : allOverlays()) {
      if (ImGui::Selectable(overlayName(overlay).c_str(), overlay == model.overlay)) {
        setOverlay(model, overlay);
      }
    }
    ImGui::EndCombo();
  }
  if (!view.overlay_note.empty()) ImGui::TextWrapped("%s", view.overlay_note.c_str());
}

void compareSection(ViewerModel& model, const PanelView& view) {
  if (!ImGui::CollapsingHeader("Compare with the oracle", ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (ImGui::BeginCombo("compare", compareModeName(model.compare).c_str())) {
    for (CompareMode mode : allCompareModes()) {
      if (ImGui::Selectable(compareModeName(mode).c_str(), mode == model.compare)) {
        model.compare = mode;
      }
    }
    ImGui::EndCombo();
  }
  if (model.compare == CompareMode::Off) return;
  ImGui::SliderFloat("tolerance", &model.compare_tolerance, 0.0f, 0.5f, "%.3f");
  ImGui::SliderFloat("heat scale", &model.heatmap_scale, 0.01f, 1.0f, "%.3f");
  if (!view.comparison) {
    ImGui::TextUnformatted("oracle: its first pass is running");
    return;
  }
  const Comparison& c = *view.comparison;
  ImGui::Text("oracle: %d passes, %d rays a pixel", c.oracle_passes, c.oracle_rays);
  ImGui::Text("MAE %.5f   off %.3f %%", c.difference.mae,
              100.0 * c.difference.fraction_over_tolerance);
}

void statsSection(const PanelView& view) {
  if (!ImGui::CollapsingHeader("Timings and counters", ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (view.frame_ms && !view.frame_ms->empty()) {
    const std::vector<float> ms(view.frame_ms->begin(), view.frame_ms->end());
    std::vector<float> sorted = ms;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const float median = sorted[sorted.size() / 2];
    ImGui::Text("frame %.2f ms (median), %.1f frames/s", median, median > 0 ? 1000.0f / median : 0);
    ImGui::PlotLines("ms", ms.data(), int(ms.size()), 0, nullptr, 0.0f, FLT_MAX, ImVec2(0, 50));
  }
  if (!view.shown || !view.shown->frame) return;
  const DeliveredFrame& shown = *view.shown;
  if (shown.prepare_ms > 0) ImGui::Text("prepare %.2f ms", shown.prepare_ms);
  if (ImGui::BeginTable("passes", 2)) {
    for (const auto& [name, ms] : shown.frame->total.time_ms) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(name.c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%.3f ms", ms);
    }
    ImGui::EndTable();
  }
  if (ImGui::BeginTable("counters", 2)) {
    // Every counter of the frame, the shared ones and the technique's own.
    shown.frame->total.forEachCounter(
        [](const char* name, const char* description, uint64_t value) {
          ImGui::TableNextRow();
          ImGui::TableNextColumn();
          ImGui::TextUnformatted(name);
          if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", description);
          ImGui::TableNextColumn();
          ImGui::Text("%llu", static_cast<unsigned long long>(value));
        });
    ImGui::EndTable();
  }
}

}  // namespace

PanelRequests drawPanel(ViewerModel& model, const PanelView& view, float x, float width,
                        float height) {
  PanelRequests requests;
  ImGui::SetNextWindowPos(ImVec2(x, 0.0f));
  ImGui::SetNextWindowSize(ImVec2(width, height));
  ImGui::Begin("penumbra", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::PushItemWidth(width * 0.5f);
  if (ImGui::Button("Save screenshot")) requests.save_screenshot = true;
  ImGui::SameLine();
  if (ImGui::Button("Save scene")) requests.save_scene = true;
  // The level of detail on screen: a preview while dragging, then the refined frame.
  ImGui::TextColored(ImVec4(1.0f, 1.0f, 0.0f, 1.0f), "%s", view.level.c_str());
  if (!view.message.empty()) ImGui::TextWrapped("%s", view.message.c_str());
  techniqueSection(model, requests);
  lightSection(model);
  frameSection(model, view);
  compareSection(model, view);
  statsSection(view);
  ImGui::PopItemWidth();
  ImGui::End();
  return requests;
}

}  // namespace penumbra::viewer
