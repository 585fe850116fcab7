// SPDX-License-Identifier: MIT
// Acne at every tile size, on lavapipe with validation: spot, point, cylinder and directional
// lights over a floor with thin planks lying on it, each light's map pinned to one size from 16 to
// 2,048 texels (cube faces to 1,024, a page's quarter) inside a shared atlas, for all five
// algorithms, seen from eye height and from a hundred metres. Lit floor must stay lit and the
// planks' shadows must stay attached, on every lighting path and both shadow rasters.
//
// A cell of the floor per light (its algorithm and size), far enough from the next that no light
// reaches another's cell: every floor pixel is measured against its own light. The frame is
// rendered twice, with shadows and without, in the shadow-only view (white surfaces, no ambient),
// so that a pixel's visibility is the ratio of the two. Directional lights light every cell: they
// are measured one per frame, the whole floor under each.
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "ecs/query.h"
#include "ecs/transform_system.h"
#include "rendergraph/device/frame_ring.h"
#include "rendergraph/device/readback.h"
#include "systems/frame/frame.h"
#include "systems/scene/lights.h"
#include "systems/scene/primitive_meshes.h"
#include "systems/scene/scene_builder.h"
#include "tests/support/gpu_test.h"
#include "tests/support/shadow_reference.h"

namespace sg::test {
namespace {

constexpr std::array<uint32_t, 8> tile_sizes{16, 32, 64, 128, 256, 512, 1024, 2048};
constexpr float pitch = 8.0f;  // metres between cell centres
constexpr uint32_t columns = tile_sizes.size();
constexpr uint32_t rows = std::size(scene::all_shadow_algorithms);
// Pixels where the light adds less than this (linear) are not measured.
constexpr float min_light = 0.1f;
// A lit pixel darker than this fraction of its unshadowed self is acne; a shadowed one brighter,
// a detached shadow.
constexpr float darkening = 0.1f;

enum class Kind { spot, point, cylinder, directional };

const char* name(Kind kind) {
  switch (kind) {
    case Kind::spot: return "spot";
    case Kind::point: return "point";
    case Kind::cylinder: return "cylinder";
    case Kind::directional: return "directional";
  }
  return "?";
}

glm::vec3 cell_centre(uint32_t column, uint32_t row) {
  return {(float(column) - 0.5f * float(columns - 1)) * pitch, 0.0f,
          (float(row) - 0.5f * float(rows - 1)) * pitch};
}

// The directions the lights shine: tilted like the stress scene's, so the floor is lit at a
// slope in every map. Spot lights and beams aim at their cell's centre from 4 m up.
const glm::vec3 aim = glm::normalize(glm::vec3(0.6f, -1.0f, 0.4f));
const glm::vec3 sun_aim = glm::normalize(glm::vec3(-0.7f, -1.0f, -0.5f));
glm::vec3 aimed_from(glm::vec3 centre) { return centre - 4.0f / -aim.y * aim; }
// Each light's size: the spot's cone, the point light's range, the beam's outer radius.
constexpr float spot_outer_cone = 0.6f;
constexpr float point_range = 4.5f;
constexpr float beam_radius = 2.5f;

// Each light's source relative to its cell's centre (point and spot), or a point far up its beam.
glm::vec3 source(Kind kind, glm::vec3 centre, glm::vec3 floor_point) {
  switch (kind) {
    case Kind::spot: return aimed_from(centre);
    case Kind::point: return centre + glm::vec3(0.0f, 2.5f, 0.0f);
    case Kind::cylinder: return floor_point - 100.0f * aim;
    case Kind::directional: return floor_point - 100.0f * sun_aim;
  }
  return {};
}

// A thin plank, 1.6 x 0.03 x 1.6 m, held 60 cm above the floor in each cell, off the light's
// axis: lights shine on it slanted, so its shadow lies partly in the open.
ecs::LocalTransform plank(glm::vec3 centre) {
  return {centre + glm::vec3(0.9f, 0.615f, 0.6f), glm::angleAxis(0.4f, glm::vec3(0, 1, 0)),
          glm::vec3(1.6f, 0.03f, 1.6f)};
}

struct Cell {
  scene::ShadowAlgorithm algorithm;
  uint32_t size;
};

uint32_t index_of(uint32_t column, uint32_t row) { return row * columns + column; }

Cell cell_of(uint32_t column, uint32_t row) {
  return {scene::all_shadow_algorithms[row], tile_sizes[column]};
}

scene::ShadowSettings shadow_of(Cell cell) {
  scene::ShadowSettings shadow;
  shadow.algorithm = cell.algorithm;
  shadow.resolution = cell.size;
  return shadow;
}

// The floor, a plank per cell and, but for directional lights, a light per cell (in cell order,
// row by row; maps above `max_size` held to it); a directional scene gets one sun, whose settings
// the caller sets per frame.
SceneView build(Kind kind, std::vector<Box>& planks, uint32_t max_size) {
  SceneView out;
  scene::Scene& scene = out.scene;
  scene.name = "acne";
  const uint32_t box = scene::add_box_mesh(scene.meshes);
  scene::Material grey;
  grey.base_color = {0.6f, 0.6f, 0.6f, 1.0f};
  grey.specular = 0.0f;
  scene::add_instance(
      scene, box, {{0.0f, -0.1f, 0.0f}, glm::quat(1, 0, 0, 0), {columns * pitch, 0.2f, rows * pitch}}, grey);
  for (uint32_t row = 0; row < rows; ++row) {
    for (uint32_t column = 0; column < columns; ++column) {
      const glm::vec3 centre = cell_centre(column, row);
      planks.push_back({ecs::to_matrix(plank(centre))});
      scene::add_instance(scene, box, plank(centre), grey);
      const Cell cell = cell_of(column, row);
      const scene::ShadowSettings shadow = shadow_of({cell.algorithm, std::min(cell.size, max_size)});
      const std::string label = std::to_string(index_of(column, row));
      switch (kind) {
        case Kind::spot: {
          scene::SpotLight spot{glm::vec3(1.0f), 0.9f, 12.0f, 0.8f * spot_outer_cone, spot_outer_cone};
          const glm::vec3 at = aimed_from(centre);
          scene::add_light(scene, spot, {at, scene::look_rotation(at, at + aim), glm::vec3(1.0f)}, shadow,
                           label);
          break;
        }
        case Kind::point: {
          scene::PointLight point{glm::vec3(1.0f), 0.9f, point_range};
          scene::add_light(scene, point, {source(kind, centre, centre)}, shadow, label);
          break;
        }
        case Kind::cylinder: {
          const glm::vec3 at = aimed_from(centre);
          scene::add_light(scene,
                           scene::CylinderLight{glm::vec3(1.0f), 0.7f, 0.6f * beam_radius, beam_radius},
                           {at, scene::look_rotation(at, at + aim), glm::vec3(1.0f)}, shadow, label);
          break;
        }
        case Kind::directional: break;
      }
    }
  }
  if (kind == Kind::directional) {
    scene::add_light(scene, scene::DirectionalLight{glm::vec3(1.0f), 0.7f},
                     {glm::vec3(0.0f, 10.0f, 0.0f),
                      scene::look_rotation({0, 10, 0}, glm::vec3(0, 10, 0) + sun_aim), glm::vec3(1.0f)},
                     scene::ShadowSettings{}, "sun");
  }
  ecs::update_world_transforms(scene.world, 0);
  return out;
}

// Seen from close by, 10 to 60 metres, and through a longer lens from 110 metres: the far view is
// where the camera's depth had least precision.
struct View {
  const char* name;
  scene::CameraPose pose;
  float yfov;
};
const View views[] = {{"near", {{0.0f, 9.0f, 28.0f}, {0.0f, 0.0f, 2.0f}}, glm::radians(70.0f)},
                      {"far", {{0.0f, 75.0f, 80.0f}, {0.0f, 0.0f, 0.0f}}, glm::radians(34.0f)}};

struct Tally {
  int lit = 0;
  int acne = 0;  // lit, darkened
  int shadowed = 0;
  int detached = 0;  // shadowed, not darkened
};

struct Measured {
  std::array<Tally, columns * rows> cells{};
  std::string report(const char* label) const {
    std::ostringstream out;
    out << label << " (lit / acne / shadowed / detached per algorithm and tile size):\n";
    for (uint32_t row = 0; row < rows; ++row) {
      out << "  " << to_string(scene::all_shadow_algorithms[row]) << ":";
      for (uint32_t column = 0; column < columns; ++column) {
        const Tally& t = cells[index_of(column, row)];
        out << "  " << tile_sizes[column] << " " << t.lit << "/" << t.acne << "/" << t.shadowed << "/"
            << t.detached;
      }
      out << "\n";
    }
    return out.str();
  }
};

// How wide, on the floor at `point`, one texel of the light's map is: the scale that filters and
// rasterization blur a shadow's edge over.
float texel_on_floor(Kind kind, glm::vec3 light, glm::vec3 point, uint32_t size) {
  const glm::vec3 to_light = glm::normalize(light - point);
  const float slant = 1.0f / std::max(to_light.y, 0.3f);  // the floor's normal is +Y
  float across = 0.0f;                                    // the map's width at the point
  switch (kind) {
    case Kind::spot: across = 2.0f * glm::dot(point - light, aim) * std::tan(spot_outer_cone); break;
    case Kind::point: across = 2.0f * glm::length(point - light); break;
    case Kind::cylinder: across = 2.0f * beam_radius; break;
    case Kind::directional: across = glm::length(glm::vec2(columns * pitch, rows * pitch)); break;
  }
  return across / float(size) * slant;
}

// How many texels of a map from a shadow's edge an algorithm may still blur it, the texel the
// nearest sample falls in included: a 3x3 grid 1.5 texels apart (pcf), Gaussian taps out to 2.6
// sigma of 1.5 texels (noise), a filter of at least a texel around each blocker (pcss; the
// planks' penumbrae are centimetres), each tap a bilinear 2x2 of a texel more.
float filter_texels(scene::ShadowAlgorithm algorithm) {
  switch (algorithm) {
    case scene::ShadowAlgorithm::hard: return 1.5f;
    case scene::ShadowAlgorithm::pcf: return 3.5f;
    case scene::ShadowAlgorithm::noise: return 5.5f;
    case scene::ShadowAlgorithm::pcss:
    case scene::ShadowAlgorithm::pcss_noise: return 3.0f;
  }
  return 5.5f;
}

// Where a plank shadows the floor from the light of the cell centred at `centre`: the plank's
// corners carried from the light (or along the beam) down to y = 0, and their convex hull,
// counter-clockwise seen from above.
std::vector<glm::vec2> shadow_outline(Kind kind, glm::vec3 centre, const Box& plank) {
  std::vector<glm::vec2> corners;
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 q(plank.model *
                      glm::vec4(k & 1 ? 0.5f : -0.5f, k & 2 ? 0.5f : -0.5f, k & 4 ? 0.5f : -0.5f, 1.0f));
    const glm::vec3 light = source(kind, centre, q);
    const glm::vec3 on_floor = light + light.y / (light.y - q.y) * (q - light);
    corners.emplace_back(on_floor.x, on_floor.z);
  }
  std::sort(corners.begin(), corners.end(),
            [](glm::vec2 a, glm::vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  const auto turn = [](glm::vec2 o, glm::vec2 a, glm::vec2 b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  std::vector<glm::vec2> hull;
  for (int pass = 0; pass < 2; ++pass) {  // Andrew's monotone chain: lower, then upper half
    const size_t start = hull.size();
    for (const glm::vec2 c : corners) {
      while (hull.size() >= start + 2 && turn(hull[hull.size() - 2], hull.back(), c) <= 0.0f) hull.pop_back();
      hull.push_back(c);
    }
    hull.pop_back();
    std::reverse(corners.begin(), corners.end());
  }
  return hull;
}

// Distance from `p` to the outline's edge, negative inside.
float signed_distance(const std::vector<glm::vec2>& outline, glm::vec2 p) {
  bool inside = true;
  float nearest = 1e30f;
  for (size_t i = 0; i < outline.size(); ++i) {
    const glm::vec2 a = outline[i], b = outline[(i + 1) % outline.size()];
    const glm::vec2 edge = b - a;
    inside = inside && edge.x * (p.y - a.y) - edge.y * (p.x - a.x) >= 0.0f;
    const float t = std::clamp(glm::dot(p - a, edge) / glm::dot(edge, edge), 0.0f, 1.0f);
    nearest = std::min(nearest, glm::length(p - (a + t * edge)));
  }
  return inside ? -nearest : nearest;
}

// The column (or row, with `count` rows) whose centre is nearest to x (or z).
uint32_t nearest(float coordinate, uint32_t count) {
  return uint32_t(
      std::clamp(std::round(coordinate / pitch + 0.5f * float(count - 1)), 0.0f, float(count - 1)));
}

// Whether the light of the cell centred at `centre` reaches floor point `p` at all: the spot's
// cone, the point light's range, the beam's outer radius.
bool reaches(Kind kind, glm::vec3 centre, glm::vec3 p) {
  const glm::vec3 light = source(kind, centre, p);
  switch (kind) {
    case Kind::spot: return glm::dot(glm::normalize(p - light), aim) > std::cos(spot_outer_cone);
    case Kind::point: return glm::length(p - light) < point_range;
    case Kind::cylinder: {
      const glm::vec3 from_axis = p - centre - glm::dot(p - centre, aim) * aim;
      return glm::length(from_axis) < beam_radius;
    }
    case Kind::directional: return true;
  }
  return false;
}

// The one cell whose light reaches `p`; nullopt where none or two do.
std::optional<uint32_t> only_light_reaching(Kind kind, glm::vec3 p) {
  std::optional<uint32_t> found;
  const uint32_t column = nearest(p.x, columns), row = nearest(p.z, rows);
  for (uint32_t r = row > 0 ? row - 1 : 0; r <= std::min(row + 1, rows - 1); ++r) {
    for (uint32_t c = column > 0 ? column - 1 : 0; c <= std::min(column + 1, columns - 1); ++c) {
      if (!reaches(kind, cell_centre(c, r), p)) continue;
      if (found) return std::nullopt;
      found = index_of(c, r);
    }
  }
  return found;
}

// Tallies one view of the floor: `shadowed` and `unshadowed` are its linear pictures with and
// without shadows. A pixel is measured against the light of the cell it lies in, or, with
// `sun_cell`, against the sun, into that cell's tally. Pixels within a filter's reach (in texels
// of the light's map) and a pixel and a half of a plank's shadow edge are left out, as are cells
// whose maps were held below their size (`max_size`).
extern void measure(Kind kind, const CameraImage& camera, const std::vector<Box>& planks,
                    const std::vector<float>& shadowed, const std::vector<float>& unshadowed,
                    std::optional<uint32_t> sun_cell, uint32_t max_size, Measured& out) {
  const float half_x = 0.5f * columns * pitch - 0.5f, half_z = 0.5f * rows * pitch - 0.5f;
  const float pixel_angle = 2.0f * std::tan(0.5f * camera.lens.yfov) / float(camera.size.y);
  for (uint32_t y = 0; y < camera.size.y; ++y) {
    for (uint32_t x = 0; x < camera.size.x; ++x) {
      const size_t i = size_t{y} * camera.size.x + x;
      const Ray ray = pixel_ray(camera, x, y);
      const std::optional<glm::vec3> hit = hit_floor(ray);
      if (!hit || std::abs(hit->x) > half_x || std::abs(hit->z) > half_z) continue;
      if (std::any_of(planks.begin(), planks.end(),
                      [&](const Box& b) { return segment_hits_box(ray.origin, *hit, b); })) {
        continue;  // a plank in front of the floor
      }
      if (unshadowed[i] < min_light) continue;
      const std::optional<uint32_t> lit_by = sun_cell ? sun_cell : only_light_reaching(kind, *hit);
      if (!lit_by) continue;
      const uint32_t index = *lit_by;
      const uint32_t column = sun_cell ? nearest(hit->x, columns) : index % columns;
      const uint32_t row = sun_cell ? nearest(hit->z, rows) : index / columns;
      const Cell cell = cell_of(index % columns, index / columns);
      if (cell.size > max_size) continue;
      const glm::vec3 light = source(kind, cell_centre(column, row), *hit);
      const float distance = glm::length(*hit - ray.origin);
      const float pixel = distance * pixel_angle / std::max(std::abs(ray.direction.y), 0.1f);
      const float reach =
          filter_texels(cell.algorithm) * texel_on_floor(kind, light, *hit, cell.size) + 1.5f * pixel;
      // No other plank is in this light's reach.
      const float edge = signed_distance(
          shadow_outline(kind, cell_centre(column, row), planks[index_of(column, row)]), {hit->x, hit->z});
      if (std::abs(edge) < reach) continue;
      const bool in_shadow = edge < 0.0f;
      const float visibility = shadowed[i] / unshadowed[i];
      Tally& t = out.cells[index];
      if (in_shadow) {
        ++t.shadowed;
        t.detached += visibility > 0.5f;
      } else {
        ++t.lit;
        t.acne += visibility < 1.0f - darkening;
      }
    }
  }
}

class ShadowAcne : public GpuTest {
 protected:
  static constexpr uint32_t width = 480;
  static constexpr uint32_t height = 270;
  // llvmpipe stops a shader's loops after 65,535 iterations, which can leave the compute raster's
  // tiles over 512 texels incomplete: it is measured up to this size.
  static constexpr uint32_t compute_raster_max = 512;
  static constexpr shadows::ShadowRaster hardware = shadows::ShadowRaster::hardware;
  static constexpr shadows::ShadowRaster compute = shadows::ShadowRaster::compute;

  // Linear green channel of one frame of `frame`.
  std::vector<float> render(Frame& frame) {
    frame.record(frames.begin_frame(), 0.0);
    frames.submit();
    frames.wait_idle();
    const vk::Rgba8Image image = vk::read_rgba8(context, frame.image());
    std::vector<float> out(size_t{width} * height);
    for (uint32_t y = 0; y < height; ++y) {
      for (uint32_t x = 0; x < width; ++x) out[size_t{y} * width + x] = vk::srgb_to_linear(image.at(x, y)[1]);
    }
    return out;
  }

  std::unique_ptr<Frame> frame_of(SceneView& scene, LightingPath lighting, shadows::ShadowRaster raster) {
    FrameSettings options;
    options.animate = false;
    options.renderer.view = LightingView::shadows;
    options.renderer.lighting = lighting;
    options.renderer.shadow_raster = raster;
    options.renderer.shadow_resolution = shadows::ShadowResolution::requested;
    options.renderer.shadow_memory_mib = 512;  // room for every map at its size: the budget demotes none
    auto frame = std::make_unique<Frame>(context, scene, options, frames.frames_in_flight());
    frame->resize({width, height});
    return frame;
  }

  // Every light of `scene` casting its shadow or none.
  static void set_shadows(SceneView& scene, bool on) {
    scene.scene.world.query<scene::ShadowSettings>().for_each(
        [&](scene::ShadowSettings& s) { s.casts_shadow = on; });
  }

  // Each light in sight has its map pinned to its cell's size (cube faces at most a quarter
  // page), and of every size at least three lie away from their page's corner (only a page's first
  // tile is at it): the atlas offsets are measured.
  void expect_placed_as_asked(const Frame& frame, uint32_t max_size) {
    const shadows::FrameLights& lights = frame.renderer().lights();
    std::array<int, columns> off_corner{};
    const auto expect_tile = [&](const std::string& view, uint32_t cap, const shadows::AtlasTile& tile) {
      if (tile.size == 0) return;                                                    // out of sight
      const uint32_t index = uint32_t(std::stoul(view.substr(view.find(' ') + 1)));  // "shadow <index>"
      const uint32_t column = index % columns;
      EXPECT_EQ(tile.size, std::min({tile_sizes[column], max_size, cap})) << view;
      off_corner[column] += tile.x != 0 || tile.y != 0;
    };
    for (const shadows::ShadowMapView& map : lights.maps) expect_tile(map.name, max_size, map.tile);
    for (const shadows::ShadowCubeView& cube : lights.cubes) {
      for (const shadows::AtlasTile& face : cube.tiles) expect_tile(cube.name, 1024, face);
    }
    for (uint32_t column = 0; column < columns; ++column) {
      if (tile_sizes[column] <= max_size) {
        EXPECT_GE(off_corner[column], 3) << tile_sizes[column] << " texels";
      }
    }
  }

  // The cells of `kind` on `lighting` with `raster`, from both cameras.
  void run(Kind kind, LightingPath lighting, shadows::ShadowRaster raster,
           uint32_t max_size = tile_sizes.back()) {
    std::vector<Box> planks;
    SceneView scene = build(kind, planks, max_size);
    const std::unique_ptr<Frame> frame = frame_of(scene, lighting, raster);
    int shadowed = 0;
    for (const View& view : views) {
      scene.pose = view.pose;
      scene.lens.yfov = view.yfov;
      const CameraImage camera{scene.pose, scene.lens, {width, height}};
      set_shadows(scene, false);
      const std::vector<float> unshadowed = render(*frame);
      Measured measured;
      if (kind == Kind::directional) {
        for (uint32_t index = 0; index < columns * rows; ++index) {
          const Cell cell = cell_of(index % columns, index / columns);
          if (cell.size > max_size) continue;
          scene.scene.world.query<scene::ShadowSettings>().for_each(
              [&](scene::ShadowSettings& s) { s = shadow_of(cell); });
          measure(kind, camera, planks, render(*frame), unshadowed, index, max_size, measured);
        }
      } else {
        set_shadows(scene, true);
        measure(kind, camera, planks, render(*frame), unshadowed, std::nullopt, max_size, measured);
        expect_placed_as_asked(*frame, max_size);
      }
      const std::string label = std::string(name(kind)) + ", " + view.name;
      std::string faults;
      int lit = 0;
      for (uint32_t index = 0; index < columns * rows; ++index) {
        const Tally& t = measured.cells[index];
        const Cell cell = cell_of(index % columns, index / columns);
        const std::string where = std::string(to_string(cell.algorithm)) + " at " + std::to_string(cell.size);
        if (t.acne > 0) faults += where + ": lit floor darkened at " + std::to_string(t.acne) + " pixels\n";
        if (t.detached > 0)
          faults += where + ": a plank's shadow missing at " + std::to_string(t.detached) + " pixels\n";
        lit += t.lit;
        shadowed += t.shadowed;
      }
      EXPECT_TRUE(faults.empty()) << label << ":\n" << faults << measured.report(label.c_str());
      EXPECT_GT(lit, 2000) << label;
    }
    // Most of a plank's shadow lies under it or within a filter's reach of its edge: the far view
    // of the slanted beams and the sun sees little of the rest.
    EXPECT_GE(shadowed, 40) << name(kind);
  }

  vk::FrameRing frames{context};
};

// Deferred lighting rebuilds positions from the camera's depth: the path where far views lost
// precision.
TEST_F(ShadowAcne, SpotLightsOnDeferredLighting) { run(Kind::spot, LightingPath::deferred, hardware); }
TEST_F(ShadowAcne, PointLightsOnDeferredLighting) { run(Kind::point, LightingPath::deferred, hardware); }
TEST_F(ShadowAcne, CylinderLightsOnDeferredLighting) {
  run(Kind::cylinder, LightingPath::deferred, hardware);
}
TEST_F(ShadowAcne, DirectionalLightOnDeferredLighting) {
  run(Kind::directional, LightingPath::deferred, hardware);
}

TEST_F(ShadowAcne, SpotLightsOnTheComputeRaster) {
  run(Kind::spot, LightingPath::deferred, compute, compute_raster_max);
}
TEST_F(ShadowAcne, PointLightsOnTheComputeRaster) {
  run(Kind::point, LightingPath::deferred, compute, compute_raster_max);
}
TEST_F(ShadowAcne, CylinderLightsOnTheComputeRaster) {
  run(Kind::cylinder, LightingPath::deferred, compute, compute_raster_max);
}
TEST_F(ShadowAcne, DirectionalLightOnTheComputeRaster) {
  run(Kind::directional, LightingPath::deferred, compute, compute_raster_max);
}

// The forward paths shade the rasterized positions.
TEST_F(ShadowAcne, SpotLightsOnFusedLighting) { run(Kind::spot, LightingPath::fused, hardware); }
TEST_F(ShadowAcne, PointLightsOnFusedLighting) { run(Kind::point, LightingPath::fused, hardware); }
TEST_F(ShadowAcne, CylinderLightsOnFusedLighting) { run(Kind::cylinder, LightingPath::fused, hardware); }

}  // namespace
}  // namespace sg::test
