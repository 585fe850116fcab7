// SPDX-License-Identifier: MIT
#include "sandbox/ui.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>
#include <unordered_map>
#include <utility>

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>
#include <glm/gtc/type_ptr.hpp>

#include "ecs/query.h"
#include "ecs/transform.h"
#include "sandbox/ui_widgets.h"
#include "systems/scene/builtin_scenes.h"
#include "systems/scene/camera.h"
#include "systems/scene/lights.h"
#include "systems/scene/scene.h"
#include "systems/scene/scene_builder.h"
#include "systems/scene/shadow_requests.h"
#include "systems/scene/shadow_settings.h"
#include "systems/shadows/shadow_atlas_shape.h"

namespace sg::sandbox {
namespace {

constexpr const char* type_names[] = {"all", "point", "spot", "directional", "cylinder"};

// The light's kind (index into type_names), or 0 when the entity is no light.
int light_type(const ecs::World& world, ecs::Entity entity) {
  if (world.has<scene::PointLight>(entity)) return 1;
  if (world.has<scene::SpotLight>(entity)) return 2;
  if (world.has<scene::DirectionalLight>(entity)) return 3;
  if (world.has<scene::CylinderLight>(entity)) return 4;
  return 0;
}

std::string label_of(const ecs::World& world, ecs::Entity entity) {
  const scene::Name* name = world.try_get<scene::Name>(entity);
  const std::string shown = name && !name->value.empty() ? name->value : "light";
  return shown + "##" + std::to_string(entity.index);
}

template <class Light>
void edit_light_parameters(ecs::World& world, ecs::Entity entity) {
  edit<Light>(world, entity, [](Light& light) {
    bool changed = ImGui::ColorEdit3("color", glm::value_ptr(light.color));
    changed |= ImGui::DragFloat("intensity", &light.intensity, 0.05f, 0.0f, 1e6f);
    if constexpr (requires { light.range; })
      changed |= ImGui::DragFloat("range", &light.range, 0.05f, 0.01f, 1e4f);
    if constexpr (requires { light.outer_cone; }) {
      changed |=
          ImGui::SliderAngle("inner cone", &light.inner_cone, 0.0f, glm::degrees(light.outer_cone) - 0.1f);
      changed |= ImGui::SliderAngle("outer cone", &light.outer_cone, 1.0f, 90.0f);
    }
    if constexpr (requires { light.outer_radius; }) {  // r < R, as the cylinder light's falloff needs
      changed |= ImGui::DragFloat("outer radius", &light.outer_radius, 0.01f, 0.02f, 1e3f);
      changed |=
          ImGui::DragFloat("inner radius", &light.inner_radius, 0.01f, 0.0f, light.outer_radius - 0.01f);
      light.inner_radius = std::min(light.inner_radius, light.outer_radius - 0.01f);
    }
    return changed;
  });
}

// A light's direction as yaw (about +Y, from -Z) and pitch (from the horizon), in degrees: two
// numbers a person can drag. It rewrites the local rotation, keeping the light's up upright.
void edit_direction(ecs::World& world, ecs::Entity entity) {
  edit<ecs::LocalTransform>(world, entity, [](ecs::LocalTransform& local) {
    const glm::vec3 d = local.rotation * glm::vec3(0.0f, 0.0f, -1.0f);
    glm::vec2 angles(glm::degrees(std::atan2(d.x, -d.z)),
                     glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f))));
    if (!ImGui::DragFloat2("direction", glm::value_ptr(angles), 0.5f)) return false;
    const float yaw = glm::radians(angles.x);
    const float pitch = glm::radians(std::clamp(angles.y, -90.0f, 90.0f));
    const glm::vec3 to(std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch));
    local.rotation = scene::look_rotation(local.translation, local.translation + to);
    return true;
  });
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("yaw and pitch, degrees");
}

enum class Motion { orbit, bob };

// Starts or stops a motion (motions.h) of a light from where it stands: an orbit of 1 m around a
// point 1 m to its -X, a bob of 0.5 m around its height. Lights keep their place when stopped.
void set_motion(ecs::World& world, ecs::Entity entity, Motion motion, bool on) {
  const ecs::LocalTransform* local = world.try_get<ecs::LocalTransform>(entity);
  if (local == nullptr) return;
  const glm::vec3 position = local->translation;
  if (motion == Motion::orbit) {
    if (!on) {
      world.remove<scene::OrbitMotion>(entity);
    } else if (!world.has<scene::OrbitMotion>(entity)) {
      world.add<scene::OrbitMotion>(entity,
                                    scene::OrbitMotion{position - glm::vec3(1, 0, 0), 1.0f, 1.0f, 0.0f});
    }
  } else {
    if (!on) {
      world.remove<scene::BobMotion>(entity);
    } else if (!world.has<scene::BobMotion>(entity)) {
      world.add<scene::BobMotion>(entity, scene::BobMotion{position.y, 0.5f, 2.0f, 0.0f});
    }
  }
}

}  // namespace

SandboxUi::SandboxUi(GLFWwindow* window) {
  IMGUI_CHECKVERSION();
  context_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini left behind in the user's folder
  ImGui::StyleColorsDark();
  if (window != nullptr) glfw_ = ImGui_ImplGlfw_InitForVulkan(window, true);
}

SandboxUi::~SandboxUi() {
  ImGui::SetCurrentContext(context_);
  if (glfw_) ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext(context_);
}

bool SandboxUi::wants_input() const {
  const ImGuiIO& io = ImGui::GetIO();
  return io.WantCaptureMouse || io.WantCaptureKeyboard;
}

const ImDrawData* SandboxUi::build(scene::Scene& scene, const scene::CameraPose& pose, const UiFacts& facts,
                                   VkExtent2D size, float seconds) {
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  if (glfw_) {
    ImGui_ImplGlfw_NewFrame();
  } else {
    io.DisplaySize = ImVec2(float(size.width), float(size.height));
  }
  io.DeltaTime = seconds > 0.0f ? seconds : 1.0f / 60.0f;
  ImGui::NewFrame();
#if IMGUI_VERSION_NUM >= 18700
  const bool f1 = ImGui::IsKeyPressed(ImGuiKey_F1);  // imgui 1.87 on (Debian 13: 1.90) names its keys
#else
  const bool f1 = ImGui::IsKeyPressed(GLFW_KEY_F1);  // 1.86 (Debian 12): io.KeysDown by GLFW key codes
#endif
  if (glfw_ && f1) help_ = !help_;
  depth_views_.clear();
  stats_panel(facts);
  light_panel(scene, pose, facts);
  if (help_) help_panel();
  if (show_map_) shadow_map_panel(scene.world, facts);
  meshes_.draw(scene.world);
  ImGui::Render();
  return ImGui::GetDrawData();
}

void SandboxUi::stats_panel(const UiFacts& facts) {
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::Begin("Frame", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::Text("CPU %.2f ms   GPU %.2f ms", facts.cpu_frame_ms, facts.gpu_frame_ms);
  ImGui::Text("%s lighting, %u lights, %u without shadow", facts.lighting.c_str(), facts.lights,
              facts.lights_without_shadow);
  ImGui::Text("shadow views drawn %u (%u moving casters only), kept %u", facts.views_rendered,
              facts.views_moving_only, facts.views_cached);
  ImGui::Text("due maps wrong for %u frames (99%%), %u at most", facts.map_lag_p99, facts.map_lag_max);
  ImGui::Text("shadow atlas %.0f MiB (--shadow-memory at the start)", facts.shadow_mib);
  ImGui::SliderFloat("render scale", &render_scale_, 0.25f, 1.0f, "%.2f");
  if (ImGui::IsItemDeactivatedAfterEdit()) render_scale_request_ = render_scale_;
  ImGui::SameLine();
  ImGui::TextDisabled("%ux%u", facts.scene_extent.width, facts.scene_extent.height);
  ImGui::DragInt("shadow updates", &shadow_view_budget_, 4.0f, 0, 1 << 24,
                 shadow_view_budget_ > 0 ? "%d views a frame" : "every due view");
  constexpr double no_budget = 0.0, most_budget = 1000.0;
  ImGui::DragScalar("shadow budget", ImGuiDataType_Double, &shadow_time_budget_ms_, 0.05f, &no_budget,
                    &most_budget, shadow_time_budget_ms_ > 0.0 ? "%.2f ms" : "none");
  constexpr const char* views[] = {"lit", "shadows only"};
  ImGui::Combo("view", &view_, views, IM_ARRAYSIZE(views));
  ImGui::DragFloat3("ambient", glm::value_ptr(ambient_), 0.005f, 0.0f, 16.0f, "%.3f");
  ImGui::DragFloat("max fps", &max_fps_, 1.0f, 0.0f, 1000.0f, max_fps_ > 0.0f ? "%.0f" : "no cap");
  ImGui::Checkbox("lights per tile (heat map)", &light_heatmap_);
  if (light_heatmap_ && (facts.lighting == to_string(LightingPath::fused) ||
                         facts.lighting == to_string(LightingPath::every_light))) {
    ImGui::SameLine();
    ImGui::TextDisabled("(no light lists on this path)");
  }
  gpu_history_[history_next_] = float(facts.gpu_frame_ms);
  history_next_ = (history_next_ + 1) % gpu_history_.size();
  ImGui::PlotLines("GPU ms", gpu_history_.data(), int(gpu_history_.size()), int(history_next_), nullptr, 0.0f,
                   FLT_MAX, ImVec2(0, 40));
  if (facts.validation_errors) {
    ImGui::Text("validation layer: %u errors", *facts.validation_errors);
  } else {
    ImGui::TextDisabled("validation layer off (--validation)");
  }
  if (ImGui::CollapsingHeader("passes")) {
    for (const auto& [name, ms] : facts.passes) ImGui::Text("%8.3f ms  %s", ms, name.c_str());
  }
  // The atlas's occupancy: each page whole, tiles grey to black, free texels white (depth 1).
  if (ImGui::CollapsingHeader("shadow atlas")) {
    constexpr uint32_t shown_pages = 4;
    for (uint32_t page = 0; page < std::min(facts.atlas_pages, shown_pages); ++page) {
      if (page % 2 != 0) ImGui::SameLine();
      depth_views_.push_back({page, 0.0f, 1.0f, true});
      ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(depth_views_.size())),
                   ImVec2(160, 160));
    }
    if (facts.atlas_pages > shown_pages) ImGui::Text("(%u more pages)", facts.atlas_pages - shown_pages);
  }
  ImGui::InputText("##open", open_path_.data(), open_path_.size());
  ImGui::SameLine();
  if (ImGui::Button("open") && open_path_[0] != '\0') open_request_ = std::string(open_path_.data());
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("a .gltf or .glb file (or drop one on the window), replacing the scene");
  ImGui::TextDisabled("F1: help");
  ImGui::End();
}

// The selected light's map as the atlas holds it: one image for a 2D map, six for a cube. The
// tiles are the last frame's (this frame's lights are gathered after the panels are built).
void SandboxUi::shadow_map_panel(const ecs::World& world, const UiFacts& facts) {
  if (facts.frame_lights == nullptr || facts.atlas_page == 0 || selected_ == ecs::null_entity ||
      !world.alive(selected_)) {
    return;
  }
  const uint64_t key = ecs::entity_key(selected_);
  const float page = float(facts.atlas_page);
  const auto kib = [](uint32_t resolution, uint32_t faces) {
    return double(shadows::shadow_map_bytes(resolution, faces)) / 1024.0;
  };
  const auto image = [&](const shadows::AtlasTile& tile, const UiDepthView& view, float side) {
    depth_views_.push_back(view);
    const auto id = reinterpret_cast<ImTextureID>(static_cast<intptr_t>(depth_views_.size()));
    ImGui::Image(id, ImVec2(side, side), ImVec2(float(tile.x) / page, float(tile.y) / page),
                 ImVec2(float(tile.x + tile.size) / page, float(tile.y + tile.size) / page));
  };
  ImGui::SetNextWindowPos(ImVec2(8, 240), ImGuiCond_FirstUseEver);  // below "Frame"
  ImGui::Begin("Shadow map", &show_map_, ImGuiWindowFlags_AlwaysAutoResize);
  bool shown = false;
  for (const shadows::ShadowMapView& map : facts.frame_lights->maps) {
    if (shadows::view_light_key(map.key) != key || map.resolution == 0) continue;
    if (const uint32_t cascade = shadows::view_cascade_number(map.key)) ImGui::Text("cascade %u", cascade);
    ImGui::Text("%u x %u texels, layer %u, %.1f KiB, drawn %u frames ago", map.resolution, map.resolution,
                map.tile.page, kib(map.resolution, 1), map.frames_since_drawn);
    image(map.tile, {map.tile.page, map.view.near, map.view.far, map.view.orthographic}, 256.0f);
    shown = true;
  }
  for (const shadows::ShadowCubeView& cube : facts.frame_lights->cubes) {
    if (cube.key != key || cube.resolution == 0) continue;
    ImGui::Text("six faces of %u x %u texels, distance / range, %.1f KiB, drawn %u frames ago",
                cube.resolution, cube.resolution, kib(cube.resolution, 6), cube.frames_since_drawn);
    constexpr const char* faces[] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
    for (int f = 0; f < 6; ++f) {
      if (f % 3 != 0) ImGui::SameLine();
      ImGui::BeginGroup();
      ImGui::TextUnformatted(faces[f]);
      image(cube.tiles[f], {cube.tiles[f].page, 0.0f, 1.0f, true}, 128.0f);
      ImGui::EndGroup();
    }
    shown = true;
  }
  if (!shown) ImGui::TextUnformatted("no shadow map this frame (none cast, out of sight or over budget)");
  ImGui::End();
}

void SandboxUi::help_panel() {
  ImGui::Begin("Help", &help_, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::TextUnformatted(
      "right mouse + move   look around\n"
      "W A S D              move\n"
      "Q E                  down, up\n"
      "mouse wheel          speed\n"
      "F                    frame the selected light, or the scene\n"
      "P                    screenshot (shadowgraph-N.png)\n"
      "drop a .gltf / .glb  open it in place of the scene\n"
      "F1                   this help\n"
      "Esc                  quit");
  ImGui::End();
}

void SandboxUi::light_panel(scene::Scene& scene, const scene::CameraPose& pose, const UiFacts& facts) {
  ecs::World& world = scene.world;
  ImGui::SetNextWindowPos(ImVec2(360, 8), ImGuiCond_FirstUseEver);  // beside "Frame"
  ImGui::SetNextWindowSizeConstraints(ImVec2(340, 0), ImVec2(480, 10'000));
  ImGui::Begin("Lights", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::Combo("type", &type_filter_, type_names, IM_ARRAYSIZE(type_names));
  // New lights a few metres in front of the camera, spots and beams looking down.
  const glm::vec3 ahead = pose.eye + 3.0f * glm::normalize(pose.target - pose.eye);
  const ecs::LocalTransform placed{ahead, scene::look_rotation(ahead, ahead - glm::vec3(0, 1, 0))};
  const std::string number = std::to_string(world.entity_count());
  if (ImGui::Button("+ point"))
    selected_ = scene::add_light(scene, scene::PointLight{}, placed, {}, "point " + number);
  ImGui::SameLine();
  if (ImGui::Button("+ spot"))
    selected_ = scene::add_light(scene, scene::SpotLight{}, placed, {}, "spot " + number);
  ImGui::SameLine();
  if (ImGui::Button("+ directional")) {
    selected_ = scene::add_light(scene, scene::DirectionalLight{}, placed, {}, "directional " + number);
  }
  ImGui::SameLine();
  if (ImGui::Button("+ cylinder")) {
    selected_ = scene::add_light(scene, scene::CylinderLight{}, placed, {}, "cylinder " + number);
  }
  ImGui::SameLine();
  if (ImGui::Button("save")) save_requested_ = true;
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("the lights and camera, beside the scene (SCENE.shadowgraph.json)");
  ImGui::SameLine();
  if (ImGui::Button("export glTF")) export_requested_ = true;
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("the whole scene with its edited lights and this view, as SCENE.edited.glb");
  constexpr const char* orders[] = {"scene order", "by name", "by importance"};
  ImGui::Combo("order", &order_, orders, IM_ARRAYSIZE(orders));
  // Importance as the shadow schedule measured it last frame (lights without shadows: 0).
  std::unordered_map<uint64_t, float> importance;
  if (facts.frame_lights != nullptr) {
    for (const shadows::ShadowMapView& map : facts.frame_lights->maps) importance[map.key] = map.importance;
    for (const shadows::ShadowCubeView& cube : facts.frame_lights->cubes)
      importance[cube.key] = cube.importance;
  }
  listed_.clear();
  world.query<const scene::ShadowSettings>().for_each([&](ecs::Entity entity, const scene::ShadowSettings&) {
    const int type = light_type(world, entity);
    if (type == 0 || (type_filter_ != 0 && type != type_filter_)) return;
    const auto found = importance.find(ecs::entity_key(entity));
    listed_.emplace_back(entity, found == importance.end() ? 0.0f : found->second);
  });
  if (order_ == 1) {
    std::stable_sort(listed_.begin(), listed_.end(), [&](const auto& a, const auto& b) {
      return label_of(world, a.first) < label_of(world, b.first);
    });
  } else if (order_ == 2) {
    std::stable_sort(listed_.begin(), listed_.end(),
                     [](const auto& a, const auto& b) { return a.second > b.second; });
  }
  if (selected_ == ecs::null_entity && !listed_.empty())
    selected_ = listed_.front().first;  // the editor starts on one
  if (ImGui::BeginListBox("##lights", ImVec2(-1.0f, 120.0f))) {
    for (const auto& [entity, _] : listed_) {
      if (ImGui::Selectable(label_of(world, entity).c_str(), entity == selected_)) selected_ = entity;
    }
    ImGui::EndListBox();
  }
  // Every light listed (the type filter applies).
  for (const auto& [label, motion, on] :
       {std::tuple{"orbit all", Motion::orbit, true}, std::tuple{"bob all", Motion::bob, true},
        std::tuple{"stop all", Motion::orbit, false}}) {
    if (ImGui::Button(label)) {
      for (const auto& [entity, _] : listed_) {
        set_motion(world, entity, motion, on);
        if (!on) set_motion(world, entity, Motion::bob, false);
      }
    }
    ImGui::SameLine();
  }
  ImGui::Checkbox("play", &playing_);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("glTF animations, orbits and bobs (--animate sets the start)");
  // One algorithm for every light listed, as --algorithm gives them at the start.
  if (enum_combo("algorithm of all", all_algorithm_)) {
    for (const auto& [entity, _] : listed_) {
      edit<scene::ShadowSettings>(world, entity, [&](scene::ShadowSettings& shadow) {
        return std::exchange(shadow.algorithm, all_algorithm_) != all_algorithm_;
      });
    }
  }
  if (selected_ != ecs::null_entity && world.alive(selected_) && light_type(world, selected_) != 0) {
    ImGui::Separator();
    ImGui::TextUnformatted(type_names[light_type(world, selected_)]);
    if (ImGui::Button("remove")) {
      world.destroy(selected_);
      selected_ = ecs::null_entity;
      ImGui::End();
      return;
    }
    ImGui::SameLine();
    ImGui::Checkbox("show map", &show_map_);
    ImGui::SameLine();
    bool orbits = world.has<scene::OrbitMotion>(selected_);
    if (ImGui::Checkbox("orbit", &orbits)) set_motion(world, selected_, Motion::orbit, orbits);
    ImGui::SameLine();
    bool bobs = world.has<scene::BobMotion>(selected_);
    if (ImGui::Checkbox("bob", &bobs)) set_motion(world, selected_, Motion::bob, bobs);
    if (world.has<ecs::LocalTransform>(selected_)) {
      edit<ecs::LocalTransform>(world, selected_, [](ecs::LocalTransform& local) {
        return ImGui::DragFloat3("position", glm::value_ptr(local.translation), 0.05f);
      });
    }
    if (light_type(world, selected_) > 1 && world.has<ecs::LocalTransform>(selected_))
      edit_direction(world, selected_);  // every light but the point light has one
    switch (light_type(world, selected_)) {
      case 1: edit_light_parameters<scene::PointLight>(world, selected_); break;
      case 2: edit_light_parameters<scene::SpotLight>(world, selected_); break;
      case 3: edit_light_parameters<scene::DirectionalLight>(world, selected_); break;
      case 4: edit_light_parameters<scene::CylinderLight>(world, selected_); break;
    }
    const bool directional = world.try_get<scene::DirectionalLight>(selected_) != nullptr;
    edit<scene::ShadowSettings>(world, selected_, [directional](scene::ShadowSettings& shadow) {
      bool changed = ImGui::Checkbox("casts shadow", &shadow.casts_shadow);
      changed |= enum_combo("algorithm", shadow.algorithm);
      changed |= ImGui::DragFloat("constant bias", &shadow.constant_bias, 0.0001f, 0.0f, 0.1f, "%.4f");
      changed |= ImGui::DragFloat("slope bias", &shadow.slope_bias, 0.0005f, 0.0f, 0.5f, "%.4f");
      changed |= ImGui::DragFloat("pcf radius", &shadow.pcf_radius, 0.05f, 0.0f, 16.0f);
      changed |= ImGui::DragFloat("light size", &shadow.light_size, 0.01f, 0.0f, 10.0f);
      changed |= ImGui::SliderFloat("density", &shadow.density, 0.0f, 1.0f);
      changed |= ImGui::ColorEdit3("shadow color", glm::value_ptr(shadow.shadow_color));
      int resolution = static_cast<int>(shadow.resolution);
      if (ImGui::SliderInt("resolution", &resolution, 16, 4096)) {
        shadow.resolution = static_cast<uint32_t>(resolution);
        changed = true;
      }
      int cascades = static_cast<int>(shadow.cascades);
      if (directional && ImGui::SliderInt("cascades", &cascades, 1, int(scene::max_shadow_cascades))) {
        shadow.cascades = static_cast<uint32_t>(cascades);
        changed = true;
      }
      changed |= enum_combo("update", shadow.update);
      changed |= ImGui::SliderFloat("priority", &shadow.priority, -scene::max_shadow_priority,
                                    scene::max_shadow_priority, "%.2f tiers");
      // The kernel of the light's own algorithm.
      const auto taps = [&](const char* label, uint32_t& value, uint32_t most) {
        int shown = static_cast<int>(value);
        if (!ImGui::SliderInt(label, &shown, 1, static_cast<int>(most))) return false;
        value = static_cast<uint32_t>(shown);
        return true;
      };
      scene::ShadowKernel& kernel = shadow.kernel;
      if (shadow.algorithm == scene::ShadowAlgorithm::pcf) {
        changed |= taps("pcf half width", kernel.pcf_half_width, scene::max_pcf_half_width);
      } else if (shadow.algorithm == scene::ShadowAlgorithm::noise) {
        int noise = kernel.noise_taps == 4 ? 0 : kernel.noise_taps == 8 ? 1 : 2;
        if (ImGui::Combo("noise taps", &noise, "4\08\016\0")) {
          kernel.noise_taps = 4u << noise;
          changed = true;
        }
      } else if (shadow.algorithm != scene::ShadowAlgorithm::hard) {
        changed |= taps("blocker taps", kernel.blocker_taps, scene::max_blocker_taps);
        changed |= taps("filter taps", kernel.filter_taps, scene::max_filter_taps);
      }
      changed |= ImGui::SliderFloat("contact shadow", &shadow.contact_length, 0.0f, 2.0f,
                                    shadow.contact_length > 0.0f ? "%.2f m" : "off");
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("the length of a ray marched through the depth buffer (deferred)");
      changed |= edit_layers("lights layers", shadow.light_mask);
      changed |= edit_layers("shadowed by layers", shadow.caster_mask);
      return changed;
    });
    if (ImGui::Button("redraw shadow")) scene::request_shadow_redraw(world, selected_);
  }
  ImGui::End();
}

scene::Aabb SandboxUi::selection_bounds(const ecs::World& world) const {
  if (selected_ == ecs::null_entity || !world.alive(selected_)) return {};
  const ecs::WorldTransform* transform = world.try_get<ecs::WorldTransform>(selected_);
  if (transform == nullptr) return {};
  float reach = 1.0f;
  if (const auto* point = world.try_get<scene::PointLight>(selected_)) reach = point->range;
  if (const auto* spot = world.try_get<scene::SpotLight>(selected_)) reach = spot->range;
  const glm::vec3 centre = scene::light_position(*transform);
  const glm::vec3 half(std::clamp(reach, 1.0f, 10.0f));
  return {centre - half, centre + half};
}

}  // namespace sg::sandbox
