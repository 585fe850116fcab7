// SPDX-License-Identifier: MIT
#pragma once
// Layers let a light pick what it lights and what shadows it: a mesh sits on some of eight
// layers, a light names the layers it acts on. A light lights a surface whose
// MeshInstance::light_layers share a bit with its ShadowSettings::light_mask, and a caster
// shadows a light's map when its MeshInstance::shadow_layers share a bit with the light's
// ShadowSettings::caster_mask. Eight, because the deferred path carries a pixel's light layers
// in its G-buffer, exactly, in a half float (shaders/gbuffer.glsl).
#include <cstdint>

namespace sg::scene {

using LayerMask = std::uint8_t;
inline constexpr std::uint32_t layer_count = 8;
inline constexpr LayerMask all_layers = 0xFF;   // a light's default: it acts on every layer
inline constexpr LayerMask first_layer = 0x01;  // a mesh's default: on layer 0 alone

}  // namespace sg::scene
