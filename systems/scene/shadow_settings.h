// SPDX-License-Identifier: MIT
#pragma once
// Per-light shadow parameters (docs/ALGORITHMS.md section 4). Every light entity carries
// one; imported lights take them from the glTF light's `extras` (gltf_lights.h lists the keys).
#include <cstdint>

#include <glm/glm.hpp>

#include "systems/scene/enum_names.h"
#include "systems/scene/layers.h"

namespace sg::scene {

enum class ShadowAlgorithm : std::uint8_t { hard, pcf, noise, pcss, pcss_noise };

// The names extras, command lines, scripts and the sidecar use.
constexpr EnumNames<ShadowAlgorithm, 5> enum_names(ShadowAlgorithm) {
  return {{{ShadowAlgorithm::hard, "hard"},
           {ShadowAlgorithm::pcf, "pcf"},
           {ShadowAlgorithm::noise, "noise"},
           {ShadowAlgorithm::pcss, "pcss"},
           {ShadowAlgorithm::pcss_noise, "pcss_noise"}}};
}
inline constexpr auto all_shadow_algorithms = enum_values<ShadowAlgorithm>();

// When a light's map is drawn again (ShadowSettings::update). automatic: when it may be wrong (the
// light, its shadow settings or a caster in its reach changed); every_frame: every frame, as a
// light whose casters change unseen; on_demand: only when asked (request_shadow_redraw) or when
// its shadow settings change, the map otherwise kept where the light and its casters were then.
// Each also when its tile is new.
enum class ShadowUpdate : std::uint8_t { automatic, every_frame, on_demand };
constexpr EnumNames<ShadowUpdate, 3> enum_names(ShadowUpdate) {
  return {{{ShadowUpdate::automatic, "auto"},
           {ShadowUpdate::every_frame, "every_frame"},
           {ShadowUpdate::on_demand, "on_demand"}}};
}
// ShadowSettings::priority's range, in tiers (powers of two of the atlas importance).
inline constexpr float max_shadow_priority = 4.0f;

// ShadowSettings::contact_length's range, world units: contact shadows reach a short way.
inline constexpr float max_contact_length = 10.0f;

// The most cascaded maps a directional light may have (ShadowSettings::cascades).
inline constexpr std::uint32_t max_shadow_cascades = 4;

// The filter kernels' sizes a light may choose (docs/ALGORITHMS.md section 4). The defaults are
// the kernels the algorithms were measured with (docs/QUALITY.md); the limits are those the
// shaders unroll to.
struct ShadowKernel {
  // pcf on 2D maps: the tap grid's half width k, (2k + 1)^2 taps, 1 to max_pcf_half_width (cube
  // maps keep section 4's 20 directions).
  std::uint32_t pcf_half_width = 1;
  // pcss and pcss_noise: the blocker search's taps (1 to 16) and the filter's (1 to 32), the first
  // of a Poisson disk whose every prefix is well spread; fewer still where the kernel spans a
  // texel or two. Cube maps search their 8 corner directions below 16 taps and filter with them
  // below 20, else with all 20.
  std::uint32_t blocker_taps = 16;
  std::uint32_t filter_taps = 32;
  // noise: 4, 8 or 16 Gaussian taps.
  std::uint32_t noise_taps = 16;
  friend bool operator==(const ShadowKernel&, const ShadowKernel&) = default;
};
inline constexpr std::uint32_t max_pcf_half_width = 3;
inline constexpr std::uint32_t max_blocker_taps = 16;
inline constexpr std::uint32_t max_filter_taps = 32;
inline constexpr std::uint32_t max_noise_taps = 16;
// The noise taps a light may take: max_noise_taps divided by 1, 2 or 4.
constexpr bool valid_noise_taps(std::uint32_t taps) { return taps == 4 || taps == 8 || taps == 16; }

// Biases are in normalized linear depth, so that one value means the same distance anywhere in
// a map: view depth / far for spot maps, depth across near..far for orthographic maps
// (directional, cylinder), distance / range for point lights (shaders/shadow_sampling.glsl).
// The receiver compares with bias = max(slope_bias * (1 - dot(N, L)), constant_bias). The defaults are sized
// for maps of `resolution` texels over room-sized light volumes (tens of metres): enough to keep acne off lit
// floors and walls, small enough that contact shadows stay attached (no peter-panning).
struct ShadowSettings {
  ShadowAlgorithm algorithm = ShadowAlgorithm::pcf;
  float constant_bias = 0.0005f;    // b0
  float slope_bias = 0.005f;        // b1
  float pcf_radius = 1.5f;          // texels; the kernel's half width for pcf/noise
  float light_size = 0.3f;          // world units: the emitter width that scales PCSS penumbrae
  float density = 1.0f;             // [0, 1]; 0 removes the shadow, 1 the full darkening
  glm::vec3 shadow_color{0.0f};     // linear RGB blended into shadowed points
  std::uint32_t resolution = 1024;  // texels per side requested (a hint to the allocator)
  // Directional lights: at most this many cascaded maps over the view's depth (1 to
  // max_shadow_cascades; 1: one map fitted to the whole scene). Each asks for `resolution`; a
  // view that gains little from more (a camera far from the scene) uses fewer
  // (systems/shadows/cascades.h).
  std::uint32_t cascades = 4;
  ShadowKernel kernel;
  ShadowUpdate update = ShadowUpdate::automatic;
  // Tiers added to log2 of the light's atlas importance (its size on screen), within
  // +-max_shadow_priority: +1 asks for a map twice as wide, and the memory and time budgets lower
  // it as a light twice its size; -1 the other way.
  float priority = 0.0f;
  // World units (0 to max_contact_length; 0: none): how far a contact shadow's ray marches
  // through the camera's depth buffer toward the light, catching the small gaps under and beside
  // casters that a map too coarse misses (shaders/contact_shadows.glsl). Deferred lighting only.
  float contact_length = 0.0f;
  // The layers (layers.h) whose meshes cast into the light's maps.
  LayerMask caster_mask = all_layers;
  // The layers whose meshes the light lights. Not a shadow setting, but one of the per-light
  // settings glTF's lights lack, read, written and edited with them.
  LayerMask light_mask = all_layers;
  bool casts_shadow = true;

  friend bool operator==(const ShadowSettings&, const ShadowSettings&) = default;
};

}  // namespace sg::scene
