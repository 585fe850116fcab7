// SPDX-License-Identifier: MIT
#pragma once
// KHR_lights_punctual, read from the raw JSON because tinygltf checks none of the extension's
// rules. The importer attaches each light to the nodes that reference it.
//
// Errors (SceneError): unknown light type; negative or zero range; negative intensity;
// non-finite numbers; a spot light without its "spot" object; spot cones with inner < 0,
// outer <= 0, outer > pi/2 or inner > outer; a node referencing a light that does not exist.
// Clamped with a warning: color components outside [0, 1]; inner == outer (the smooth rim
// would divide by zero, so inner becomes 0.9 * outer).
//
// Absent range means infinite in the extension; the renderer needs a finite one, so we use the
// distance where the inverse-square intensity I/d^2 falls to 1/256 (one 8-bit step):
// effective range = 16 * sqrt(intensity).
//
// Shadow settings come from the light's `extras` (not part of glTF, so nothing there fails the
// import; a wrong type or value is reported and the default or a clamped value used), as flat
// keys or in an `extras.shadowgraph` object, whose keys win (systems/scene/README.md):
//   algorithm     "hard" | "pcf" | "noise" | "pcss" | "pcss_noise"
//   bias          >= 0, constant bias          slope_bias   >= 0
//   pcf_radius    [0, 32] texels               light_size   >= 0, world units
//   density       [0, 1]                       shadow_color [r, g, b] each in [0, 1]
//   resolution    integer, [16, 16384] texels  casts_shadow true | false
//   cascades      [1, 4], directional lights   update       "auto" | "every_frame" | "on_demand"
//   priority      [-4, 4] tiers of atlas importance
#include <cstddef>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "systems/scene/gltf_source.h"
#include "systems/scene/lights.h"
#include "systems/scene/scene.h"
#include "systems/scene/shadow_settings.h"

namespace sg::scene {

struct ImportedLight {
  std::variant<PointLight, SpotLight, DirectionalLight> light;
  ShadowSettings shadow;
};

float effective_light_range(float intensity);

// Every light of the document's KHR_lights_punctual extension, in order; warnings go to `scene`.
std::vector<ImportedLight> read_gltf_lights(const GltfSource& source, Scene& scene);

// The light that nodes[node] references, if any. Throws SceneError when the reference is not
// an index into the `light_count` lights.
std::optional<std::size_t> node_light(const GltfSource& source, std::size_t node, std::size_t light_count);

}  // namespace sg::scene
