// SPDX-License-Identifier: MIT
#pragma once
// The panels' shared widgets (Dear ImGui): a component edited in place, an enum's combo, a layer
// mask's row of boxes.
#include <string>

#include <imgui.h>

#include "ecs/world.h"
#include "systems/scene/enum_names.h"
#include "systems/scene/layers.h"

namespace sg::sandbox {

// Edits `value` of component T of `entity` with `widget`; writes (and so marks it changed) only
// when the widget changed it.
template <class T, class Widget>
void edit(ecs::World& world, ecs::Entity entity, Widget widget) {
  T copy = world.get<T>(entity);
  if (widget(copy)) world.get_mut<T>(entity) = copy;
}

// A combo of E's names (enum_names.h), as extras, scripts and the sidecar spell them.
template <NamedEnum E>
bool enum_combo(const char* label, E& value) {
  constexpr auto names = enum_names(E{});
  int current = 0;
  const char* labels[names.size()];
  for (size_t i = 0; i < names.size(); ++i) {
    labels[i] = names[i].second.data();
    if (names[i].first == value) current = int(i);
  }
  if (!ImGui::Combo(label, &current, labels, int(names.size()))) return false;
  value = names[size_t(current)].first;
  return true;
}

// A box per layer (systems/scene/layers.h), 0 on the left, then the label.
inline bool edit_layers(const char* label, scene::LayerMask& mask) {
  bool changed = false;
  ImGui::PushID(label);
  for (unsigned layer = 0; layer < scene::layer_count; ++layer) {
    unsigned flags = mask;
    if (layer > 0) ImGui::SameLine(0.0f, 2.0f);
    ImGui::PushID(int(layer));
    if (ImGui::CheckboxFlags("##layer", &flags, 1u << layer)) {
      mask = static_cast<scene::LayerMask>(flags);
      changed = true;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("layer %u", layer);
    ImGui::PopID();
  }
  ImGui::PopID();
  ImGui::SameLine();
  ImGui::TextUnformatted(label);
  return changed;
}

}  // namespace sg::sandbox
