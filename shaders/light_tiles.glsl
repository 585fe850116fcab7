// SPDX-License-Identifier: MIT
// Tiled light culling (light_tiles.comp) and what the tiled lighting reads from it. Also compiled
// as C++ (tests/support/light_tiles_reference.cpp, Light standing for sg::shadows::GpuLight), so
// the CPU reference culls with the very same tests: keep to what both languages read alike.
#ifndef SG_LIGHT_TILES_GLSL
#define SG_LIGHT_TILES_GLSL

#include "light_tile_layout.glsl"

// The sphere around a tile's visible surfaces: the eight corners of the tile's slice of the
// view frustum between its nearest and farthest depth (Vulkan NDC, depth 0..1), brought back
// to world space. Loose for deep tiles, but the same on the CPU and the GPU.
vec4 tile_bounding_sphere(mat4 inverse_view_projection, vec2 ndc_min, vec2 ndc_max, float depth_min,
                          float depth_max) {
  vec3 corners[8];
  vec3 centre = vec3(0.0f);
  for (uint i = 0u; i < 8u; ++i) {
    vec4 ndc = vec4((i & 1u) != 0u ? ndc_max.x : ndc_min.x, (i & 2u) != 0u ? ndc_max.y : ndc_min.y,
                    (i & 4u) != 0u ? depth_max : depth_min, 1.0f);
    vec4 world = inverse_view_projection * ndc;
    corners[i] = vec3(world) / world.w;
    centre += corners[i];
  }
  centre *= 0.125f;
  float radius = 0.0f;
  for (uint i = 0u; i < 8u; ++i) radius = max(radius, length(corners[i] - centre));
  return vec4(centre, radius);
}

// Where a tile's visible surfaces lie, bounded two ways: a sphere, and the cone from the camera
// through the tile cut by two spheres around the camera. A deep tile (a column's edge before a far
// wall) has a sphere as wide as it is deep, where the cone is as narrow as the tile: from the
// stress hall's eye-height camera at 1920x1080, 100,000 lights, the sphere alone listed 9.0
// million (tile, light) pairs (H200, 2026-12-03).
struct TileVolume {
  vec4 sphere;    // xyz centre, w radius; w < 0: no surfaces
  vec4 apex_sin;  // xyz the camera's position, w sin of the cone's half angle
  vec4 axis_cos;  // xyz the cone's unit axis, w cos of its half angle
  vec4 shells;    // x, y: the least and greatest distance from the camera of the tile's surfaces;
                  // z, w: its nearest and farthest depth plane's distance along the view direction
  vec4 rays[4];   // xyz: the tile's corner rays from the camera, a unit step along the view direction
  vec4 forward;   // xyz: the view direction
  vec4 depths;    // x, y: the depths (camera_depth.glsl) it was bounded by; z, w: 1 / their
                  // distances along the view direction, which a perspective makes linear in depth
  uvec4 slices;   // x: bit k where a surface lies in depth slice k (depth_slice_position); 0: unknown
};

// A tile's surfaces can lie far apart in depth (a chair's back before the floor far behind it),
// and a spot light's cone can pass between them. The span from the tile's nearest depth plane to
// its farthest is cut into DEPTH_SLICES equal slices; the culling marks those that hold a surface,
// and lists a spot light only where its cone meets a marked slice. Among 4,000 spots in the stress
// hall at 1920x1080 the lists held 32,479 pairs at eye height against 73,901 with the tile's whole
// slice alone, and 34,245 with 16 slices (lavapipe, 2026-12-05). Among 100,000 lights at eye height
// the frame took 25.8 ms against 27.7 with the whole slice alone (H100, 2026-12-05).
const uint DEPTH_SLICES = 32u;
// A tile whose depth span is shorter than this part of its farthest plane's distance is tested
// whole. From afar the slices took 5% more pairs out of the stress hall's lists, but the tiles'
// pass from 1.4 to 2.2 ms: 13.1 ms a frame against 12.5 with shallow tiles tested whole, 25.8 at
// eye height either way (100,000 lights, H100, 2026-12-05).
const float SLICED_DEPTH_SPAN = 0.125f;
// The camera's position: the point every view ray starts from (clip space (0, 0, 1, 0) brought back).
vec3 camera_position(mat4 inverse_view_projection) {
  vec4 eye = inverse_view_projection * vec4(0.0f, 0.0f, 1.0f, 0.0f);
  return vec3(eye) / eye.w;
}

// The volume of the tile between NDC corners `ndc_min` and `ndc_max`, between depths `depth_min`
// and `depth_max`.
TileVolume tile_volume(mat4 inverse_view_projection, vec2 ndc_min, vec2 ndc_max, float depth_min,
                       float depth_max) {
  TileVolume tile;
  tile.sphere = tile_bounding_sphere(inverse_view_projection, ndc_min, ndc_max, depth_min, depth_max);
  vec3 apex = camera_position(inverse_view_projection);
  vec4 centre = inverse_view_projection * vec4(0.0f, 0.0f, 1.0f, 1.0f);
  vec3 forward = normalize(vec3(centre) / centre.w - apex);
  tile.depths = vec4(depth_min, depth_max, 0.0f, 0.0f);
  tile.slices = uvec4(0u);
  vec3 rays[4];
  vec3 axis = vec3(0.0f);
  float nearest = 3.0e38f;
  float farthest = 0.0f;
  vec2 planes = vec2(3.0e38f, 0.0f);
  for (uint i = 0u; i < 8u; ++i) {
    vec4 ndc = vec4((i & 1u) != 0u ? ndc_max.x : ndc_min.x, (i & 2u) != 0u ? ndc_max.y : ndc_min.y,
                    (i & 4u) != 0u ? depth_max : depth_min, 1.0f);
    vec4 world = inverse_view_projection * ndc;
    vec3 offset = vec3(world) / world.w - apex;
    // No point of a depth's plane in the tile is nearer than that plane along the view direction;
    // the farthest is a corner.
    float ahead = dot(offset, forward);
    nearest = min(nearest, ahead);
    farthest = max(farthest, length(offset));
    planes = vec2(min(planes.x, ahead), max(planes.y, ahead));
    if (i == 0u) tile.depths.z = 1.0f / ahead;
    if (i == 4u) tile.depths.w = 1.0f / ahead;
    if (i < 4u) {
      rays[i] = normalize(offset);
      axis += rays[i];
      tile.rays[i] = vec4(offset / ahead, 0.0f);
    }
  }
  axis = normalize(axis);
  float cos_half = 1.0f;
  for (uint i = 0u; i < 4u; ++i) cos_half = min(cos_half, dot(axis, rays[i]));
  tile.apex_sin = vec4(apex, sqrt(max(1.0f - cos_half * cos_half, 0.0f)));
  tile.axis_cos = vec4(axis, cos_half);
  tile.shells = vec4(nearest, farthest, planes.x, planes.y);
  tile.forward = vec4(forward, 0.0f);
  return tile;
}

// Whether the sphere `bound` (xyz centre, w radius) can meet the tile's cone between its shells:
// its distance from the cone (from the cone's side, or from the apex where that is nearer) is at
// most its radius. It only grows with the cone and the shells, so a volume around several tiles
// passes every sphere that one of them passes.
bool sphere_meets_tile_cone(vec4 bound, TileVolume tile) {
  vec3 offset = vec3(bound) - vec3(tile.apex_sin);
  float distance = length(offset);
  if (distance < tile.shells.x - bound.w || distance > tile.shells.y + bound.w) return false;
  float along = dot(offset, vec3(tile.axis_cos));
  float across = sqrt(max(distance * distance - along * along, 0.0f));
  float cos_half = tile.axis_cos.w;
  float sin_half = tile.apex_sin.w;
  float beyond = along * cos_half + across * sin_half < 0.0f ? distance : across * cos_half - along * sin_half;
  return beyond <= bound.w;
}


// Whether `light` can reach anything inside `sphere` (xyz centre, w radius): the point light's
// sphere of range, the spot light's cone (its sphere of range cut by the outer angle), the
// cylinder light's beam of outer radius in front of the light; a directional light reaches
// everything.
bool light_reaches_sphere(Light light, vec4 sphere) {
  uint type = light.info.x;
  if (type == LIGHT_DIRECTIONAL) return true;
  vec3 offset = vec3(sphere) - vec3(light.position_range);
  if (type == LIGHT_CYLINDER) {
    vec3 axis = vec3(light.direction_type);
    float along = dot(offset, axis);
    return along >= -sphere.w && length(cross(axis, offset)) <= light.shape.w + sphere.w;
  }
  float range = light.position_range.w;
  float distance = length(offset);
  if (distance > range + sphere.w) return false;
  if (type == LIGHT_POINT) return true;
  // Spot: the sphere against the cone (apex at the light, half angle `outer`).
  vec3 axis = vec3(light.direction_type);
  float along = dot(offset, axis);
  float across = sqrt(max(distance * distance - along * along, 0.0f));
  float cos_outer = light.shape.y;
  float sin_outer = sqrt(max(1.0f - cos_outer * cos_outer, 0.0f));
  float beyond_cone = cos_outer * across - along * sin_outer;  // distance from the cone's side
  return beyond_cone <= sphere.w && along >= -sphere.w;
}

// Whether the sphere of `light`'s range, grown by `margin`, meets the tile's cone; directional and
// cylinder lights, which have no range, always do.
bool light_range_meets_tile_cone(Light light, TileVolume tile, float margin) {
  uint type = light.info.x;
  if (type == LIGHT_DIRECTIONAL || type == LIGHT_CYLINDER) return true;
  return sphere_meets_tile_cone(vec4(vec3(light.position_range), light.position_range.w + margin), tile);
}

// Where a surface of `tile` at `depth` (camera_depth.glsl) lies among the tile's depth slices: k
// and a fraction in slice k.
float depth_slice_position(TileVolume tile, float depth) {
  float span = tile.shells.w - tile.shells.z;
  if (span <= 0.0f || tile.depths.x == tile.depths.y) return 0.0f;
  float ahead = 1.0f / mix(tile.depths.z, tile.depths.w, (depth - tile.depths.x) / (tile.depths.y - tile.depths.x));
  return (ahead - tile.shells.z) * (float(DEPTH_SLICES) / span);
}

// The bit of the depth slice at `position`; positions a rounding beyond either end fall in the end slices.
uint depth_slice_bit(float position) {
  return 1u << uint(clamp(position, 0.0f, float(DEPTH_SLICES - 1u)));
}

// How much wider than a depth slice the tests take it on either side, so that a surface that
// rounding put in its neighbour keeps its lights.
float depth_slice_rounding(TileVolume tile) { return 1.0e-4f * tile.shells.w; }

// The depth slices from the one of bit `nearest` to the one of bit `farthest`, both included.
uint depth_slices_between(uint nearest, uint farthest) { return (farthest | (farthest - 1u)) & ~(nearest - 1u); }

// A spot light against the parts of a tile's slice of the view frustum between two depth planes
// (spot_cone_misses_part): the products of the camera's offset from the light and of the tile's
// corner rays that every part's test is made of, taken once.
struct SpotAgainstTile {
  vec4 rays_across;   // each corner ray's product with the part across the cone's axis of the camera's offset
  vec4 rays_middle;   // and with that of the tile's middle ray
  vec4 rays_ahead;    // and with the axis
  vec3 camera_terms;  // the camera's offset's products with those three
  vec3 lengths;       // the squared length across the axis of camera + z middle, in powers of z
  vec2 cos_sin;       // the cone's outer angle
};

SpotAgainstTile spot_against_tile(Light light, TileVolume tile) {
  vec3 apex = vec3(light.position_range);
  vec3 axis = vec3(light.direction_type);
  vec3 camera = vec3(tile.apex_sin) - apex;
  vec3 middle = 0.25f * vec3(tile.rays[0] + tile.rays[1] + tile.rays[2] + tile.rays[3]);
  vec3 across = camera - dot(camera, axis) * axis;
  vec3 middle_across = middle - dot(middle, axis) * axis;
  mat4x3 rays = mat4x3(vec3(tile.rays[0]), vec3(tile.rays[1]), vec3(tile.rays[2]), vec3(tile.rays[3]));
  SpotAgainstTile spot;
  spot.rays_across = across * rays;
  spot.rays_middle = middle_across * rays;
  spot.rays_ahead = axis * rays;
  spot.camera_terms = vec3(dot(across, camera), dot(middle_across, camera), dot(axis, camera));
  spot.lengths = vec3(dot(across, across), 2.0f * dot(across, middle_across), dot(middle_across, middle_across));
  float cos_outer = light.shape.y;
  spot.cos_sin = vec2(cos_outer, sqrt(max(1.0f - cos_outer * cos_outer, 0.0f)));
  return spot;
}

// Whether the spot's cone misses, by more than `margin`, the part of the tile's slice of the view
// frustum between the planes `near` and `far` along the view direction: all eight corners of that
// part lie behind the light, or beyond the plane through the light tangent to its cone on the side
// that faces the part's middle (camera + middle ray * z, whose offset across the axis is across +
// z middle_across, so the plane's products follow from the spot's). The cone lies before the one
// plane and behind every such other, so this never drops a part it meets. Products taken once
// per spot brought the tiles' pass from 2.7 to 2.2 ms (H100, 100,000 lights from afar, 2026-12-05).
bool spot_cone_misses_part(SpotAgainstTile spot, float near, float far, float margin) {
  float towards = 0.5f * (near + far);
  float length_squared = spot.lengths.x + towards * (spot.lengths.y + towards * spot.lengths.z);
  float scale = length_squared > 0.0f ? spot.cos_sin.x / sqrt(length_squared) : 0.0f;
  float sine = length_squared > 0.0f ? spot.cos_sin.y : 1.0f;
  float base = (spot.camera_terms.x + towards * spot.camera_terms.y) * scale - spot.camera_terms.z * sine;
  vec4 rate = (spot.rays_across + towards * spot.rays_middle) * scale - spot.rays_ahead * sine;
  vec4 beyond = min(base + near * rate, base + far * rate);
  vec4 ahead = max(spot.camera_terms.z + near * spot.rays_ahead, spot.camera_terms.z + far * spot.rays_ahead);
  return min(min(beyond.x, beyond.y), min(beyond.z, beyond.w)) > margin ||
         max(max(ahead.x, ahead.y), max(ahead.z, ahead.w)) < -margin;
}

// Whether a spot light's cone misses the tile's surfaces by more than `margin`: it misses the
// tile's whole slice of the view frustum, or, in a deep tile, each depth slice marked in `slices`
// (none marked: unknown, so not missed). Tests of spheres keep a spot around its pool of light, since a floor's
// tile's sphere reaches below the floor, where the cone is wider; and the whole slice of a deep
// tile meets cones that pass between its surfaces. Each depth slice is tested a rounding wider on
// either side (depth_slice_rounding).
bool spot_cone_misses_tile(Light light, TileVolume tile, uint slices, float margin) {
  if (light.info.x != LIGHT_SPOT) return false;
  SpotAgainstTile spot = spot_against_tile(light, tile);
  if (spot_cone_misses_part(spot, tile.shells.z, tile.shells.w, margin)) return true;
  if (tile.shells.w - tile.shells.z < SLICED_DEPTH_SPAN * tile.shells.w) return false;
  float step = (tile.shells.w - tile.shells.z) / float(DEPTH_SLICES);
  float rounding = depth_slice_rounding(tile);
  for (uint rest = slices; rest != 0u; rest &= rest - 1u) {
    float near = tile.shells.z + step * float(findLSB(rest)) - rounding;
    if (!spot_cone_misses_part(spot, near, near + step + 2.0f * rounding, margin)) return false;
  }
  return slices != 0u;
}

// The depth slices of `tile` that the sphere of `light`'s range, grown by `margin`, reaches into
// along the view direction (each slice a rounding wider on either side, depth_slice_rounding);
// every slice for directional and cylinder lights, which have no range. A point light between a
// column and the wall far behind it lights neither. Among 100,000 lights at eye height it took
// 0.3% of the pairs out of the lists, and the tiles' pass from 2.39 to 2.00 ms, the spots' slice
// loop running over the slices in reach only (H100, 1920x1080, 2026-12-05).
uint depth_slices_in_reach(Light light, TileVolume tile, float margin) {
  uint type = light.info.x;
  float span = tile.shells.w - tile.shells.z;
  if (type == LIGHT_DIRECTIONAL || type == LIGHT_CYLINDER || span <= 0.0f) return ~0u;
  float ahead = dot(vec3(light.position_range) - vec3(tile.apex_sin), vec3(tile.forward)) - tile.shells.z;
  float reach = light.position_range.w + margin + depth_slice_rounding(tile);
  float scale = float(DEPTH_SLICES) / span;
  return depth_slices_between(depth_slice_bit((ahead - reach) * scale), depth_slice_bit((ahead + reach) * scale));
}

// Whether `light` can reach anything in `volume`: its reach meets the volume's sphere, and the
// sphere of its range meets the volume's cone. Both tests only grow with the sphere, the cone and
// the shells, so they also bound a volume around several tiles (light_tiles_coarse.comp).
bool light_reaches_volume(Light light, TileVolume volume) {
  return light_reaches_sphere(light, volume.sphere) && light_range_meets_tile_cone(light, volume, 0.0f);
}

// Whether `light` can reach anything in `tile`: light_reaches_volume, its range reaches a depth
// slice that holds a surface, and a spot's cone does not miss those slices' surfaces.
bool light_reaches_tile(Light light, TileVolume tile) {
  if (!light_reaches_volume(light, tile)) return false;
  uint slices = tile.slices.x & depth_slices_in_reach(light, tile, 0.0f);
  return (slices != 0u || tile.slices.x == 0u) && !spot_cone_misses_tile(light, tile, slices, 0.0f);
}

#endif
