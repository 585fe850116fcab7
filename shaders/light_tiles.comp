#version 460
#extension GL_GOOGLE_include_directive : require
// variant transparent TRANSPARENT_BOUNDS
// Light culling on GPUs (light_tiles_interface.glsl says what it writes): one workgroup per
// screen tile, its threads reading the tile's depths and testing the lights side by side.
#include "light_tiles_interface.glsl"

// SIDE x SIDE threads, each reading a block of the tile's depth: a GPU wants threads to test many
// lights at once. At least 4, so that every light group has a thread.
const uint SIDE = 8u;
layout(local_size_x = SIDE, local_size_y = SIDE) in;
const uint THREADS = SIDE * SIDE;
const uint BLOCK = LIGHT_TILE_SIZE / SIDE;  // pixels per thread side

shared float thread_nearest[THREADS];
shared float thread_farthest[THREADS];
shared vec4 tile_sphere;
shared bool has_surfaces;
shared uint first_slot[THREADS];  // per thread: how many it found, then where its lights go
shared uint total;
shared uint entries[MAX_LIGHTS_PER_TILE];
shared uint group_first[LIGHT_GROUP_COUNT];
shared uint group_end[LIGHT_GROUP_COUNT];

void main() {
  uint local = gl_LocalInvocationIndex;
  uint tile = gl_WorkGroupID.y * frame.screen.z + gl_WorkGroupID.x;
  if (local < LIGHT_GROUP_COUNT) {
    group_first[local] = 0u;
    group_end[local] = 0u;
  }
  // Each thread reduces its block, then one thread their results and the tile's bound:
  // shared-memory atomics and 64 copies of the same sphere cost a CPU driver more than a short
  // serial loop.
  // Reversed depths (camera_depth.glsl): the nearest surface has the greatest.
  float nearest = CAMERA_FAR_DEPTH;
  float farthest = 1.0;
  for (uint k = 0u; k < BLOCK * BLOCK; ++k) {
    ivec2 pixel =
        ivec2(gl_WorkGroupID.xy * LIGHT_TILE_SIZE + gl_LocalInvocationID.xy * BLOCK + uvec2(k % BLOCK, k / BLOCK));
    if (pixel.x < int(frame.screen.x) && pixel.y < int(frame.screen.y)) bound_by_pixel(pixel, nearest, farthest);
  }
  thread_nearest[local] = nearest;
  thread_farthest[local] = farthest;
  barrier();
  if (local == 0u) {
    for (uint t = 1u; t < THREADS; ++t) {
      nearest = max(nearest, thread_nearest[t]);
      farthest = min(farthest, thread_farthest[t]);
    }
    bound_by_transparent_surfaces(tile, nearest, farthest);
    has_surfaces = !is_background_depth(nearest);
    tile_sphere = visible_sphere_of_tile(gl_WorkGroupID.xy, nearest, farthest);
  }
  barrier();

  // Lights in ordered chunks, one per thread: count, place the chunks one after another, then
  // write in order, so the list is sorted by light index and the same every frame.
  uint light_count = has_surfaces ? frame.counts.x : 0u;
  vec4 sphere = tile_sphere;
  uint chunk = (light_count + THREADS - 1u) / THREADS;
  uint first = min(local * chunk, light_count);
  uint last = min(first + chunk, light_count);
  uint mine = 0u;
  for (uint i = first; i < last; ++i) {
    if (light_reaches_sphere(lights[i], sphere)) ++mine;
  }
  first_slot[local] = mine;
  barrier();
  if (local == 0u) {
    uint sum = 0u;
    for (uint t = 0u; t < THREADS; ++t) {
      uint count = first_slot[t];
      first_slot[t] = sum;
      sum += count;
    }
    total = min(sum, MAX_LIGHTS_PER_TILE);
    count_dropped(sum, total);
  }
  barrier();
  uint slot = first_slot[local];
  for (uint i = first; i < last && slot < MAX_LIGHTS_PER_TILE; ++i) {
    if (light_reaches_sphere(lights[i], sphere)) {
      entries[slot] = i;
      tile_lights[tile * MAX_LIGHTS_PER_TILE + slot] = i;
      ++slot;
    }
  }
  barrier();

  // Groups are contiguous in the list: find where each begins and ends.
  for (uint j = local; j < total; j += THREADS) {
    uint group = group_of(entries[j]);
    if (j == 0u || group_of(entries[j - 1u]) != group) group_first[group] = j;
    if (j + 1u == total || group_of(entries[j + 1u]) != group) group_end[group] = j + 1u;
  }
  barrier();
  if (local < LIGHT_GROUP_COUNT) {
    publish_group_range(tile, local, group_first[local], group_end[local] - group_first[local]);
  }
}
