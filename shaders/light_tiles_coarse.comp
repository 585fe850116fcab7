// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// variant transparent TRANSPARENT_BOUNDS
// The coarse pass of light culling on GPUs (light_tiles_coarse.glsl says what it writes): a
// workgroup per coarse tile and segment of the lights (frame.counts.w of them), each bounding the
// tiles' depths, then testing its segment's lights side by side against a volume around the
// tiles'. The coarse tiles alone are too few workgroups to fill a GPU: with 100,000 lights two
// segments took the pass from 0.62-0.63 ms to 0.48-0.51 from afar and from 0.83-0.85 to 0.82-0.83
// at eye height; among 1,024 lights from 0.059 to 0.082, so fewer lights take one (H100,
// 1920x1080, 2026-12-05).
#include "light_tile_bounds.glsl"
#include "light_tiles_coarse.glsl"

// SIDE x SIDE threads, each reading a block of BLOCK x BLOCK pixels: a tile is TILE_BLOCKS x
// TILE_BLOCKS of them. 1,024 threads test a coarse tile's lights side by side: with 100,000
// lights the pass took 1.14-1.19 ms at eye height and 0.76-0.87 from afar, against 1.90-2.03 and
// 1.26-1.47 with 256 (H200, 1920x1080, 2026-12-03).
const uint SIDE = 32u;
layout(local_size_x = SIDE, local_size_y = SIDE) in;
const uint THREADS = SIDE * SIDE;
const uint BLOCK = LIGHT_COARSE_SIDE * LIGHT_TILE_SIZE / SIDE;
const uint TILE_BLOCKS = LIGHT_TILE_SIZE / BLOCK;
const uint TILES = LIGHT_COARSE_SIDE * LIGHT_COARSE_SIDE;

#include "light_list_slots.glsl"

// First each block's nearest and farthest depth (floatBitsToUint, words [0, 2 THREADS)), then, once
// the tiles are bounded, a bit per light: whether it reaches the coarse volume, so that the lights
// are tested once, for the list's count, and its entries read the bits. With 100,000 lights the
// pass took 0.44 ms from afar and 0.63 at eye height, against 0.78 and 1.14 testing them twice
// (H200, 1920x1080, 2026-12-04). 16 KiB, 131,072 lights; past that the lights are tested again.
// With the tiles' volumes (176 bytes each) and the lists' slots the pass shares 32,136 of the
// 32,768 bytes that lavapipe's workgroups may: a field more in TileVolume needs the volumes kept
// elsewhere.
const uint SCRATCH_WORDS = 4096u;
shared uint scratch[SCRATCH_WORDS];
const uint BIT_LIGHTS = 32u * SCRATCH_WORDS;
// Each tile's volume; once the tiles are bounded, the first five hold the volumes around the
// coarse tile's quadrants' tiles (coarse_quadrant), then around all its tiles.
shared TileVolume volumes[TILES];
const uint WHOLE_COARSE_TILE = 4u;
shared uint tile_slices[TILES];  // each tile's depth slices with a surface (TileVolume.slices)
shared uint coarse_first;

// Whether this workgroup writes its tiles' volumes and depth slices: the first segment's does;
// the others bound the same tiles only for the volumes around them.
bool writes_tile_volumes() { return gl_WorkGroupID.z == 0u; }

// Thread `local` (< TILES), once every block is bounded: its tile's depth bounds from the tile's
// blocks, and the volume they bound, also written to tile_volumes.
TileVolume bound_tile(uint local) {
  TileVolume volume;
  volume.sphere.w = NO_SURFACES;
  uvec2 in_coarse = uvec2(local % LIGHT_COARSE_SIDE, local / LIGHT_COARSE_SIDE);
  uvec2 tile_xy = gl_WorkGroupID.xy * LIGHT_COARSE_SIDE + in_coarse;
  if (tile_xy.x >= frame.screen.z || tile_xy.y >= frame.screen.w / frame.screen.z) return volume;
  // Reversed depths (camera_depth.glsl): the nearest surface has the greatest.
  float nearest = CAMERA_FAR_DEPTH;
  float farthest = 1.0;
  for (uint k = 0u; k < TILE_BLOCKS * TILE_BLOCKS; ++k) {
    uvec2 block = in_coarse * TILE_BLOCKS + uvec2(k % TILE_BLOCKS, k / TILE_BLOCKS);
    nearest = max(nearest, uintBitsToFloat(scratch[block.y * SIDE + block.x]));
    farthest = min(farthest, uintBitsToFloat(scratch[THREADS + block.y * SIDE + block.x]));
  }
  uint tile = tile_xy.y * frame.screen.z + tile_xy.x;
  bound_by_transparent_surfaces(tile, nearest, farthest);
  if (!is_background_depth(nearest)) volume = visible_volume_of_tile(tile_xy, nearest, farthest);
  if (writes_tile_volumes()) tile_volumes[tile] = volume;
  return volume;
}

// Whether tile `t` of the coarse tile lies in `quadrant` (WHOLE_COARSE_TILE: every tile does).
bool in_quadrant(uint t, uint quadrant) {
  return quadrant == WHOLE_COARSE_TILE ||
         coarse_quadrant(uvec2(t % LIGHT_COARSE_SIDE, t / LIGHT_COARSE_SIDE)) == quadrant;
}

// Once every tile is bounded: the volume around the volumes of the tiles in `quadrant`, or of all
// of them (WHOLE_COARSE_TILE): the sphere around their spheres, the cone around their cones, the
// shells around theirs, a hair wider so that rounding never lets a light reach a tile but miss
// this volume; sphere.w is NO_SURFACES where no such tile has any.
TileVolume volume_around_tiles(uint quadrant) {
  TileVolume around;
  around.sphere.w = NO_SURFACES;
  vec3 low = vec3(3.0e38);
  vec3 high = vec3(-3.0e38);
  vec3 axis = vec3(0.0);
  vec2 shells = vec2(3.0e38, 0.0);
  for (uint t = 0u; t < TILES; ++t) {
    TileVolume tile = volumes[t];
    if (tile.sphere.w < 0.0 || !in_quadrant(t, quadrant)) continue;
    low = min(low, tile.sphere.xyz - tile.sphere.w);
    high = max(high, tile.sphere.xyz + tile.sphere.w);
    axis += tile.axis_cos.xyz;
    shells = vec2(min(shells.x, tile.shells.x), max(shells.y, tile.shells.y));
    around.apex_sin.xyz = tile.apex_sin.xyz;
  }
  if (low.x > high.x) return around;
  vec3 centre = 0.5 * (low + high);
  axis = normalize(axis);
  float radius = 0.0;
  float half_angle = 0.0;
  for (uint t = 0u; t < TILES; ++t) {
    TileVolume tile = volumes[t];
    if (tile.sphere.w < 0.0 || !in_quadrant(t, quadrant)) continue;
    radius = max(radius, length(tile.sphere.xyz - centre) + tile.sphere.w);
    half_angle = max(half_angle, acos(clamp(dot(axis, tile.axis_cos.xyz), -1.0, 1.0)) + acos(tile.axis_cos.w));
  }
  // acos near 1 is good to about 4e-4 radians in floats.
  half_angle = min(half_angle + 1.0e-3, 3.14159);
  around.sphere = vec4(centre, radius * 1.0001 + 1.0e-4);
  around.apex_sin.w = sin(half_angle);
  around.axis_cos = vec4(axis, cos(half_angle));
  around.shells = vec4(shells.x * 0.9999 - 1.0e-4, shells.y * 1.0001 + 1.0e-4, 0.0, 0.0);
  return around;
}

void main() {
  uint local = gl_LocalInvocationIndex;
  float nearest = CAMERA_FAR_DEPTH;
  float farthest = 1.0;
  uvec2 origin = gl_WorkGroupID.xy * (SIDE * BLOCK) + gl_LocalInvocationID.xy * BLOCK;
  float depths[BLOCK * BLOCK];
  for (uint k = 0u; k < BLOCK * BLOCK; ++k) {
    ivec2 pixel = ivec2(origin + uvec2(k % BLOCK, k / BLOCK));
    bool inside = pixel.x < int(frame.screen.x) && pixel.y < int(frame.screen.y);
    depths[k] = inside ? texelFetch(scene_depth, pixel, 0).r : CAMERA_FAR_DEPTH;
    bound_by_depth(depths[k], nearest, farthest);
  }
  scratch[local] = floatBitsToUint(nearest);
  scratch[THREADS + local] = floatBitsToUint(farthest);
  if (local < TILES) tile_slices[local] = 0u;
  barrier();
  if (local < TILES) volumes[local] = bound_tile(local);
  barrier();
  // Each block marks its tile's depth slices that hold its pixels' surfaces.
  uvec2 in_coarse = gl_LocalInvocationID.xy / TILE_BLOCKS;
  uint tile_local = in_coarse.y * LIGHT_COARSE_SIDE + in_coarse.x;
  if (writes_tile_volumes() && volumes[tile_local].sphere.w >= 0.0) {
    uint slices = 0u;
    for (uint k = 0u; k < BLOCK * BLOCK; ++k) {
      slices |= depth_slice_of(volumes[tile_local], depths[k]);
    }
    if (slices != 0u) atomicOr(tile_slices[tile_local], slices);
  }
  TileVolume around;
  if (local <= WHOLE_COARSE_TILE) around = volume_around_tiles(local);
  for (uint word = local; word < SCRATCH_WORDS; word += THREADS) scratch[word] = 0u;
  barrier();
  if (writes_tile_volumes() && local < TILES && volumes[local].sphere.w >= 0.0) {
    uvec2 tile_xy = gl_WorkGroupID.xy * LIGHT_COARSE_SIDE + uvec2(local % LIGHT_COARSE_SIDE, local / LIGHT_COARSE_SIDE);
    uint tile = tile_xy.y * frame.screen.z + tile_xy.x;
    tile_volumes[tile].slices.x = tile_slices[local] | depth_slices_of_transparent_surfaces(tile, volumes[local]);
  }
  barrier();
  if (local <= WHOLE_COARSE_TILE) volumes[local] = around;
  barrier();

  // The workgroup's segment of the lights in ordered chunks, one per thread, as the tiles' pass
  // lists them.
  TileVolume volume = volumes[WHOLE_COARSE_TILE];
  uint segment_lights = (frame.counts.x + frame.counts.w - 1u) / frame.counts.w;
  uint segment_first = min(gl_WorkGroupID.z * segment_lights, frame.counts.x);
  uint lights_tested = volume.sphere.w < 0.0 ? 0u : min(segment_lights, frame.counts.x - segment_first);
  bool bits = lights_tested <= BIT_LIGHTS;
  uvec2 chunk = segment_first + thread_chunk(local, lights_tested);
  uint count = 0u;
  for (uint i = chunk.x; i < chunk.y; ++i) {
    if (light_reaches_volume(lights[i], volume)) {
      ++count;
      uint bit = i - segment_first;
      if (bits) atomicOr(scratch[bit / 32u], 1u << (bit % 32u));
    }
  }
  first_slot[local] = count;
  uint sum = place_thread_counts(local);
  if (local == 0u) {
    uint first = sum == 0u ? 0u : atomicAdd(coarse_wanted, sum);
    // Light indices past an entry's low bits, far beyond what the light records hold, would make
    // every tile test every light as a full pool does.
    bool fits = first <= frame.counts.z && sum <= frame.counts.z - first && frame.counts.x <= COARSE_ENTRY_LIGHT + 1u;
    uint coarse_tile = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    coarse_ranges[coarse_tile * LIGHT_COARSE_SEGMENTS + gl_WorkGroupID.z] =
        fits ? uvec2(first, sum) : uvec2(0u, EVERY_LIGHT);
    coarse_first = fits ? first : EVERY_LIGHT;
  }
  barrier();
  if (coarse_first == EVERY_LIGHT) return;
  uint slot = coarse_first + first_slot[local];
  for (uint i = chunk.x; i < chunk.y; ++i) {
    uint bit = i - segment_first;
    if (bits ? (scratch[bit / 32u] & (1u << (bit % 32u))) != 0u : light_reaches_volume(lights[i], volume)) {
      uint quadrants = 0u;
      for (uint q = 0u; q < WHOLE_COARSE_TILE; ++q) {
        if (volumes[q].sphere.w >= 0.0 && light_reaches_volume(lights[i], volumes[q])) quadrants |= 1u << q;
      }
      coarse_lights[slot++] = i | quadrants << COARSE_QUADRANT_SHIFT;
    }
  }
}
