// SPDX-License-Identifier: MIT
#include "sandbox/mesh_panel.h"

#include <imgui.h>

#include "ecs/hierarchy.h"
#include "ecs/query.h"
#include "sandbox/ui_widgets.h"
#include "systems/scene/material.h"
#include "systems/scene/mesh_instance.h"
#include "systems/scene/scene.h"

namespace sg::sandbox {

std::string mesh_label(const ecs::World& world, ecs::Entity entity) {
  const auto named = [&](ecs::Entity e) {
    const scene::Name* name = world.try_get<scene::Name>(e);
    return name != nullptr && !name->value.empty() ? name : nullptr;
  };
  if (const scene::Name* own = named(entity)) return own->value;
  if (const ecs::Parent* parent = world.try_get<ecs::Parent>(entity)) {
    if (const scene::Name* name = named(parent->entity)) return name->value;
  }
  return "mesh " + std::to_string(world.get<scene::MeshInstance>(entity).mesh);
}

void MeshPanel::draw(ecs::World& world) {
  ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Meshes")) {
    ImGui::End();
    return;
  }
  ImGui::InputText("find", filter_.data(), filter_.size());
  const std::string_view filter(filter_.data());
  listed_.clear();
  world.query<const scene::MeshInstance>().for_each([&](ecs::Entity entity, const scene::MeshInstance&) {
    std::string label = mesh_label(world, entity);
    if (label.find(filter) != std::string::npos) listed_.emplace_back(entity, std::move(label));
  });
  ImGui::Text("%zu drawables", listed_.size());
  if (ImGui::BeginListBox("##meshes", ImVec2(-1.0f, 160.0f))) {
    ImGuiListClipper clipper;
    clipper.Begin(int(listed_.size()));
    while (clipper.Step()) {
      for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
        const auto& [entity, label] = listed_[size_t(i)];
        ImGui::PushID(int(entity.index));
        if (ImGui::Selectable(label.c_str(), entity == selected_)) selected_ = entity;
        ImGui::PopID();
      }
    }
    ImGui::EndListBox();
  }
  if (selected_ != ecs::null_entity && world.alive(selected_) && world.has<scene::MeshInstance>(selected_)) {
    ImGui::Separator();
    edit<scene::MeshInstance>(world, selected_, [](scene::MeshInstance& mesh) {
      bool changed = ImGui::Checkbox("casts shadow", &mesh.casts_shadow);
      ImGui::SameLine();
      changed |= ImGui::Checkbox("receives shadow", &mesh.receives_shadow);
      changed |= edit_layers("lit on layers", mesh.light_layers);
      changed |= edit_layers("casts on layers", mesh.shadow_layers);
      return changed;
    });
    // Its material: every drawable has its own copy (glTF primitives share none).
    if (world.has<scene::Material>(selected_)) {
      edit<scene::Material>(world, selected_, [](scene::Material& material) {
        bool changed = ImGui::SliderFloat("specular", &material.specular, 0.0f, 1.0f);
        changed |= ImGui::SliderFloat("shininess", &material.shininess, 1.0f, 4096.0f, "%.0f",
                                      ImGuiSliderFlags_Logarithmic);
        return changed;
      });
    }
  }
  ImGui::End();
}

}  // namespace sg::sandbox
