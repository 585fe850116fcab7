// SPDX-License-Identifier: MIT
#pragma once
// The lights of one frame, gathered from the ECS world: the GPU records the lighting pass reads
// (one array, one storage buffer) and the shadow views the shadow passes render. Plain data and
// functions, no GPU.
//
// A frame's lights go through three steps:
//   gather_lights   records and shadow views from the world, in the world's order; each view
//                   knows its light (entity), what it asks for and whether it changed;
//   ShadowSchedule  (shadow_schedule.h) gives each view its atlas tiles or none, decides which
//                   views render this frame, and writes the records' shadow fields;
//   sort_by_group   copies the records in light-group order, the order the lighting passes read.
#include <array>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "ecs/jobs/thread_pool.h"
#include "ecs/world.h"
#include "systems/scene/aabb.h"
#include "systems/scene/shadow_settings.h"
#include "systems/shadows/cascades.h"
#include "systems/shadows/gpu_light.h"
#include "systems/shadows/light_groups.h"
#include "systems/shadows/light_views.h"
#include "systems/shadows/shadow_atlas_planner.h"

namespace sg::shadows {

// What applies to every light each frame, whatever its own settings say (--shadows off). A
// setting a light may change afterwards, such as its algorithm, is set in the world instead,
// once, so that an edit is not overwritten.
struct LightOverrides {
  bool shadows = true;

  friend bool operator==(const LightOverrides&, const LightOverrides&) = default;
};

// Limits on map sizes, whatever the lights ask for.
inline constexpr uint32_t min_shadow_resolution = 16;
inline constexpr uint32_t max_map_resolution = 4096;
inline constexpr uint32_t max_cube_resolution = 2048;

// The key of a light's shadow views (ShadowMapView::key, ShadowCubeView::key): its entity, the
// same from frame to frame; cascade k of a directional light's has k + 1 in its top four bits.
uint64_t light_key(ecs::Entity entity);
inline constexpr int cascade_key_shift = 60;
uint64_t cascade_key(ecs::Entity entity, uint32_t cascade);
// Of a view's key: its light's key, and its cascade counted from 1 (0: the view is no cascade).
constexpr uint64_t view_light_key(uint64_t view_key) {
  return view_key & ((uint64_t{1} << cascade_key_shift) - 1);
}
constexpr uint32_t view_cascade_number(uint64_t view_key) { return uint32_t(view_key >> cascade_key_shift); }

// ShadowMapView::cascade of a view that is no cascade.
inline constexpr uint32_t no_cascade = UINT32_MAX;

struct ShadowMapView {
  uint32_t light = 0;                 // index into FrameLights::records
  uint64_t key = 0;                   // the light's entity, the same from frame to frame
  uint32_t requested_resolution = 0;  // the light's wish, an upper bound
  LightView view;
  // The sphere beyond which the light reaches nothing (xyz centre, w radius): casters outside
  // cannot shadow anything it lights. A negative radius for lights without a range.
  glm::vec4 reach{0.0f, 0.0f, 0.0f, -1.0f};
  // Its transform, light or shadow settings were written in or after the last gather's tick (a
  // write in that tick may have come after the gather). Systems advance the tick before gathering.
  bool changed = false;
  // The light's ShadowSettings::update and ::priority.
  scene::ShadowUpdate update = scene::ShadowUpdate::automatic;
  float priority = 0.0f;
  scene::LayerMask caster_mask = scene::all_layers;  // ShadowSettings::caster_mask
  // A cascade's record in FrameLights::cascades, where the schedule writes its map (no_cascade:
  // the view's map is its light's, in the light's record), and whether the view needs it this
  // frame (place_cascades: a view near the scene may use fewer cascades than the light allows).
  uint32_t cascade = no_cascade;
  bool needed = true;
  // From ShadowSchedule: its importance (light_importance: pixels on screen, 0 out of sight), its
  // tile (resolution 0: no shadow this frame), whether it renders, and whether the render may draw
  // just the moving casters over the map's static layer (ShadowRender::draw_moving_casters; `view`
  // is then the one that layer was drawn with). A path that keeps no static layers draws every
  // caster either way.
  float importance = 0.0f;
  uint32_t resolution = 0;
  AtlasTile tile;
  bool render = false;
  bool moving_casters_only = false;
  uint32_t frames_since_drawn = 0;  // of the map it has: 0 drawn this frame
  std::string name;                 // for the pass: "shadow <light name>"
};

struct ShadowCubeView {
  uint32_t light = 0;
  uint64_t key = 0;
  uint32_t requested_resolution = 0;
  glm::vec4 position_far{0.0f};  // shadow_cube.frag's light position and far plane, and its reach
  bool changed = false;
  scene::ShadowUpdate update = scene::ShadowUpdate::automatic;  // as ShadowMapView's
  float priority = 0.0f;
  scene::LayerMask caster_mask = scene::all_layers;
  float importance = 0.0f;           // as ShadowMapView's
  uint32_t resolution = 0;           // each face's side; 0: no shadow this frame
  std::array<AtlasTile, 6> tiles{};  // faces +X, -X, +Y, -Y, +Z, -Z, all on one layer
  bool render = false;
  bool moving_casters_only = false;  // as ShadowMapView's (position_far as drawn then)
  uint32_t frames_since_drawn = 0;
  std::string name;
};

// The six faces' view-projections a cube is drawn with, from its position and far plane. Worked
// out for the cubes drawn, not kept in each view: 384 bytes a cube that every pass over 50,000
// point lights' views read through.
inline CubeViews face_views(const ShadowCubeView& cube) {
  return point_light_cube(glm::vec3(cube.position_far), cube.position_far.w);
}

// One light as gather_lights first lists it: its record's place is its place in that list; a
// shadowed light's `view` indexes FrameLights::maps (or cubes, for point lights).
struct GatheredLight {
  enum Kind : uint8_t { spot, directional, cylinder, point };
  ecs::Entity entity;
  Kind kind = spot;
  bool shadowed = false;
  uint32_t view = 0;
  // A cascaded directional light's views are maps [view, view + cascades), their records
  // FrameLights::cascades [first_cascade, first_cascade + cascades); 0 for other lights.
  uint32_t cascades = 0;
  uint32_t first_cascade = 0;

  friend bool operator==(const GatheredLight&, const GatheredLight&) = default;
};

// What a gather's list gave out: map views, cube views and cascade records.
struct GatheredViews {
  uint32_t maps = 0;
  uint32_t cubes = 0;
  uint32_t cascades = 0;
};

// The layout stamps (ecs::World::layout_stamp) of the pools gathering lists lights from.
using LightLayout = std::array<uint64_t, 6>;

struct FrameLights {
  // One record per light, in the order gathering lists the lights (views' `light` index it),
  // kept from frame to frame: gathering packs again only the lights written since (`refilled`,
  // their records without a shadow map), and the schedule writes the shadow fields where a map
  // was drawn, a record packed afresh, or a map lost. At 100,000 lights copying every record afresh each
  // frame took 2 ms of gathering on one thread of the 2-core VM, and writing every shadowed record's
  // fields 1.4 ms of the schedule (2026-12-04).
  std::vector<GpuLight> records;
  std::vector<uint8_t> refilled;  // per record: packed afresh by the last gather
  // After sort_by_group: record i's place among the records ordered by light group
  // (light_groups.h), the order the GPU reads; the records of group g are at [group_begin[g],
  // group_begin[g + 1]), so a pass that shades one group reads one range.
  std::vector<uint32_t> sorted_place;
  std::array<uint32_t, light_group_count + 1> group_begin{};
  // After sort_by_group, group g's light types (light_type_bits): a group's pass need hold only
  // those types' code.
  std::array<uint32_t, light_group_count> group_types{};
  // After sort_by_group, group g's lights with contact shadows (ShadowSettings::contact_length >
  // 0): a group's pass marches them only where it has some.
  std::array<uint32_t, light_group_count> group_contact_lights{};
  uint32_t contact_lights() const {
    return std::accumulate(group_contact_lights.begin(), group_contact_lights.end(), 0u);
  }
  std::vector<ShadowMapView> maps;
  std::vector<ShadowCubeView> cubes;
  // The cascades' records (cascades.h), uploaded right after the sorted records: a cascaded light's
  // record holds the index of its first one there (records.size() + its place here) and how
  // many the view uses (light_record.glsl). Each row of `cascaded` is one cascaded light.
  std::vector<GpuLight> cascades;
  struct CascadedLight {
    uint32_t record = 0;      // its record in `records`
    uint32_t first_view = 0;  // its views in `maps`, one per cascade
    uint32_t views = 0;
  };
  std::vector<CascadedLight> cascaded;
  ecs::Tick gathered_at = 0;  // the world's tick at the last gather: `changed` compares with it

  // gather_lights' working storage, kept so that a frame allocates nothing once it has grown.
  struct Scratch {
    // sort_by_group: per piece of records, its count and types per group (light_group_count
    // each), then where the piece's records of each group go.
    std::vector<uint32_t> piece_groups;
    std::vector<uint32_t> piece_types;
    std::vector<uint32_t> piece_contact;  // per piece and group: its lights with contact shadows
    std::vector<GatheredLight> gathered;
    // The last gather's list, overrides, and whether each light had a Name: what a light
    // unchanged since keeps.
    std::vector<GatheredLight> last_gathered;
    GatheredViews views;                  // of last_gathered
    std::vector<CascadedLight> cascaded;  // of last_gathered, by their places in it
    LightLayout last_layout{};
    LightOverrides last_overrides;
    std::vector<uint8_t> named;
    uint64_t last_names_layout = 0;  // the Name pool's layout stamp at the last gather
    // Per entity index, its light's place in last_gathered (none: ~0u); per place, whether a
    // component of the light (transform, light, shadow settings, name) was written since the last
    // gather.
    std::vector<uint32_t> place_of_entity;
    std::vector<uint8_t> written;
  } scratch;
};

// Fills `out` (reusing its storage) from every light entity of `world`, in the world's order.
// Directional and cylinder maps are fitted around `scene_bounds`. Lights whose
// ShadowSettings::casts_shadow is false, and every light with overrides.shadows off, get no
// view. The records have no shadow map yet (ShadowSchedule gives them theirs). With a pool, the
// records and views are filled in chunks on it (the result is the same); `world` must not change
// meanwhile.
//
// A directional light with ShadowSettings::cascades above 1 gets that many views, one per
// cascade, whose LightViews place_cascades sets once the frame's camera is known.
//
// When the world lists the same lights as at the last gather into `out` (same entities, order
// and shadowed ones) with the same overrides, a spot or point light none of whose components
// (transform, light, shadow settings, name) was written since keeps its view and its record,
// shadow fields included, from then: but for the shadow fields the result is what gathering
// afresh gives, for less (view matrices, names, records).
void gather_lights(const ecs::World& world, const scene::Aabb& scene_bounds, const LightOverrides& overrides,
                   FrameLights& out, jobs::ThreadPool* pool = nullptr);

// The lights with a shadow view in `lights`: a directional light's cascades count once.
uint32_t shadowed_light_count(const FrameLights& lights);

// Fits the cascades of every cascaded directional light to `camera` over the scene within
// `scene_bounds` (fit_cascades): each cascade view's LightView, `needed` and `changed` (its view
// is not the one it had) and the light's record's count of cascades. Between gather_lights and
// the schedule, which gives the cascades' records their maps.
void place_cascades(FrameLights& lights, const CascadeCamera& camera, const scene::Aabb& scene_bounds);

// Where sort_by_group marks the places whose record changed: changed_at[place] becomes `now` where
// the record put there differs from what the place held.
struct SortedChanges {
  std::span<uint64_t> changed_at;  // as many as places
  uint64_t now = 0;
};

// Copies the records into `sorted` (as many places as records) by light group (stably, so
// lights keep the world's order within a group), from each record's type, algorithm and whether
// it has a shadow map, and fills sorted_place. With `changes`, `sorted` holds the last call's
// records, and a place whose record is the same is left as it is. With `pool`, the records are
// counted and copied on its threads.
void sort_by_group(FrameLights& lights, std::span<GpuLight> sorted, jobs::ThreadPool* pool = nullptr,
                   SortedChanges changes = {});

}  // namespace sg::shadows
