#version 460
#extension GL_GOOGLE_include_directive : require
// Light culling: one workgroup per screen tile of LIGHT_TILE_SIZE pixels. It bounds the tile's
// visible surfaces (nearest to farthest depth, background excluded) by a sphere, lists every
// light that reaches it in light-index order, and, since the records are sorted by light group
// (systems/shadows/frame_lights.h), finds each group's range in that list. Every tile with
// lights of a group is appended to that group's tile list, whose length is the group's
// indirect dispatch (tiled_lighting.comp) and the instance count of its indirect draw
// (tiled_lighting.vert).
#include "bindings.glsl"
#include "light_groups.glsl"
#include "light_record.glsl"
#include "light_tiles.glsl"

// SIDE x SIDE threads, each reading a block of the tile's depth, chosen per device
// (systems/light_tiles_pass.cpp): a GPU wants threads to test many lights at once; a CPU driver
// (one coroutine per SIMD batch, switched at every barrier) wants few threads. At least 4, so
// that every light group has a thread.
layout(constant_id = 0) const uint SIDE = 8u;
layout(local_size_x_id = 0, local_size_y_id = 0) in;
const uint THREADS = SIDE * SIDE;
const uint BLOCK = LIGHT_TILE_SIZE / SIDE;  // pixels per thread side

layout(std430, set = 0, binding = lights_binding) readonly buffer Lights { Light lights[]; };
layout(set = 0, binding = scene_depth_binding) uniform sampler2D scene_depth;
layout(std430, set = 0, binding = tile_lights_binding) writeonly buffer TileLights { uint tile_lights[]; };
// Per tile and group: x the first entry in tile_lights, y how many.
layout(std430, set = 0, binding = tile_ranges_binding) writeonly buffer TileRanges { uvec2 tile_ranges[]; };
// Per group, tile_count slots: the tiles that have lights of the group, in no particular order.
layout(std430, set = 0, binding = group_tiles_binding) writeonly buffer GroupTiles { uint group_tiles[]; };
// Per group a VkDispatchIndirectCommand (x counts the group's tiles; y = z = 1), then per group a
// VkDrawIndirectCommand (y counts them; 6 vertices, first instance the group's first slot in
// group_tiles), all at a 16-byte stride.
layout(std430, set = 0, binding = group_commands_binding) buffer GroupCommands { uvec4 group_commands[]; };

layout(push_constant) uniform Constants {
  mat4 inverse_view_projection;
  uvec4 screen;  // x width, y height, z tiles across, w tiles in all
  uvec4 counts;  // x lights
} frame;

shared float thread_nearest[THREADS];
shared float thread_farthest[THREADS];
shared vec4 tile_sphere;
shared bool has_surfaces;
shared uint first_slot[THREADS];  // per thread: how many it found, then where its lights go
shared uint total;
shared uint entries[MAX_LIGHTS_PER_TILE];
shared uint group_first[LIGHT_GROUP_COUNT];
shared uint group_end[LIGHT_GROUP_COUNT];

uint group_of(uint light) {
  Light l = lights[light];
  uint kind = l.info.w == NO_SHADOW_MAP ? SHADOW_KIND_NONE
                                        : (l.info.x == LIGHT_POINT ? SHADOW_KIND_CUBE : SHADOW_KIND_MAP);
  return light_group(kind, l.info.z);
}

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
  float nearest = 1.0;
  float farthest = 0.0;
  for (uint k = 0u; k < BLOCK * BLOCK; ++k) {
    ivec2 pixel =
        ivec2(gl_WorkGroupID.xy * LIGHT_TILE_SIZE + gl_LocalInvocationID.xy * BLOCK + uvec2(k % BLOCK, k / BLOCK));
    if (pixel.x < int(frame.screen.x) && pixel.y < int(frame.screen.y)) {
      float depth = texelFetch(scene_depth, pixel, 0).r;
      if (depth < 1.0) {  // background does not bound the tile
        nearest = min(nearest, depth);
        farthest = max(farthest, depth);
      }
    }
  }
  thread_nearest[local] = nearest;
  thread_farthest[local] = farthest;
  barrier();
  if (local == 0u) {
    for (uint t = 1u; t < THREADS; ++t) {
      nearest = min(nearest, thread_nearest[t]);
      farthest = max(farthest, thread_farthest[t]);
    }
    has_surfaces = farthest > 0.0;
    vec2 texel = 2.0 / vec2(frame.screen.xy);
    vec2 ndc_min = vec2(gl_WorkGroupID.xy * LIGHT_TILE_SIZE) * texel - 1.0;
    vec2 ndc_max = min(vec2((gl_WorkGroupID.xy + 1u) * LIGHT_TILE_SIZE) * texel - 1.0, vec2(1.0));
    tile_sphere = tile_bounding_sphere(frame.inverse_view_projection, ndc_min, ndc_max, nearest, farthest);
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
    uint count = group_end[local] - group_first[local];
    tile_ranges[tile * LIGHT_GROUP_COUNT + local] = uvec2(tile * MAX_LIGHTS_PER_TILE + group_first[local], count);
    if (count > 0u) {
      uint k = atomicAdd(group_commands[local].x, 1u);
      atomicAdd(group_commands[LIGHT_GROUP_COUNT + local].y, 1u);
      group_tiles[local * frame.screen.w + k] = tile;
    }
  }
}
