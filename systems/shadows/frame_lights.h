#pragma once
// The lights of one frame, gathered from the ECS world: the GPU records the lighting pass reads
// (one array, one storage buffer) and the shadow views the shadow passes render. Plain data and
// functions, no GPU: the renderer uploads the records and sizes the shadow storage from them.
//
// Shadow storage is shared by all lights: spot, directional and cylinder lights each own one
// layer of a 2D depth array, point lights one cube of a depth cube-map array. The storage must
// have layers of at least map_size texels (the largest resolution any 2D light asks for) and
// faces of at least cube_size (needed_storage()); a light asking for less renders into, and
// samples, the top-left square of its layer of its own size. Once the storage is sized,
// place_shadow_maps() tells each record where its map is.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "ecs/world.h"
#include "systems/scene/aabb.h"
#include "systems/scene/shadow_settings.h"
#include "systems/shadows/gpu_light.h"
#include "systems/shadows/light_groups.h"
#include "systems/shadows/light_views.h"
#include "systems/shadows/shadow_storage_size.h"

namespace sg::shadows {

// Command-line overrides applied to every light (--algorithm, --shadows off).
struct LightOverrides {
  std::optional<scene::ShadowAlgorithm> algorithm;
  bool shadows = true;
};

// Limits on map sizes, whatever the lights ask for.
inline constexpr uint32_t min_shadow_resolution = 16;
inline constexpr uint32_t max_map_resolution = 4096;
inline constexpr uint32_t max_cube_resolution = 2048;

struct ShadowMapView {
  uint32_t light = 0;  // index into FrameLights::records
  uint32_t layer = 0;
  uint32_t resolution = 0;  // the square region [0, resolution)^2 of the layer
  LightView view;
  // The sphere beyond which the light reaches nothing (xyz centre, w radius): casters outside
  // cannot shadow anything it lights. A negative radius for lights without a range.
  glm::vec4 reach{0.0f, 0.0f, 0.0f, -1.0f};
  std::string name;  // for the pass: "shadow <light name>"
};

struct ShadowCubeView {
  uint32_t light = 0;
  uint32_t cube = 0;                  // layers 6 * cube .. 6 * cube + 5
  uint32_t requested_resolution = 0;  // the light's wish; all faces share the storage's size
  CubeViews views;
  glm::vec4 position_far{0.0f};  // shadow_cube.frag's push constant, and the light's reach
  std::string name;
};

struct FrameLights {
  // Ordered by light group (light_groups.h): the records of group g are
  // [group_begin[g], group_begin[g + 1]), so a pass that shades one group reads one range.
  std::vector<GpuLight> records;
  std::array<uint32_t, light_group_count + 1> group_begin{};
  std::vector<ShadowMapView> maps;
  std::vector<ShadowCubeView> cubes;
  uint32_t map_size = min_shadow_resolution;   // the smallest layer side that fits, texels
  uint32_t cube_size = min_shadow_resolution;  // the smallest cube face side that fits, texels

  // gather_lights' working storage, kept so that a frame allocates nothing once it has grown.
  struct Scratch {
    std::vector<uint32_t> groups;  // per record as gathered
    std::vector<uint32_t> moved_to;
    std::vector<GpuLight> records;
  } scratch;
};

// Fills `out` (reusing its storage) from every light entity of `world`. Directional and
// cylinder maps are fitted around `scene_bounds`. Lights whose ShadowSettings::casts_shadow is
// false, and every light with overrides.shadows off, get no map. The records do not yet say
// where their maps are (place_shadow_maps).
void gather_lights(const ecs::World& world, const scene::Aabb& scene_bounds, const LightOverrides& overrides,
                   FrameLights& out);

// The shadow storage the lights need: a layer per 2D map, a cube per point light, each at least
// as large as the largest request.
ShadowStorageSize needed_storage(const FrameLights& lights);

// Gives every shadowed record its map in storage whose layers are `layer_size` texels and
// whose cube faces are `face_size` texels (at least lights.map_size and lights.cube_size).
void place_shadow_maps(FrameLights& lights, uint32_t layer_size, uint32_t face_size);

}  // namespace sg::shadows
