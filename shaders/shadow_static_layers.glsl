// SPDX-License-Identifier: MIT
// Moves views' depths between the compute raster's squares (ShadowView::raster.xy) and the
// static layers, which hold every map's tile as the atlas does (raster.zw): with SAVE
// (shadow_static_save.comp) the squares of views drawn with their still casters go into their
// layers; without (shadow_static_restore.comp) the layers of views whose still casters have not
// changed go into their squares, for the moving casters to be drawn over
// (systems/shadow_maps/shadow_view_batch.h). Workgroups (x, y) take the views view_base + x, x + the x
// count, ..., texels [y, y + 1) * TEXELS_PER_WORKGROUP of each: a large tile (a 1024-texel map
// holds a million) is shared by several. Two shaders rather than a flag, so that each declares
// only what it writes.
#ifndef SG_SHADOW_STATIC_LAYERS_GLSL
#define SG_SHADOW_STATIC_LAYERS_GLSL

#include "shadow_views.glsl"

layout(local_size_x = 256) in;

const uint TEXELS_PER_WORKGROUP = 65536u;  // layer_texels_per_workgroup in systems/shadow_maps/shadow_static_layers.cpp

#if SAVE
layout(std430, set = 0, binding = shadow_depths_binding) readonly buffer Depths { uint depths[]; };
layout(std430, set = 0, binding = static_layers_binding) writeonly buffer Layers { uint layers[]; };
#else
layout(std430, set = 0, binding = shadow_depths_binding) writeonly buffer Depths { uint depths[]; };
layout(std430, set = 0, binding = static_layers_binding) readonly buffer Layers { uint layers[]; };
#endif

layout(push_constant) uniform LayerConstants {
  uint view_base;
  uint view_count;
} pc;

void main() {
  for (uint v = gl_WorkGroupID.x; v < pc.view_count; v += gl_NumWorkGroups.x) {
    uint view = pc.view_base + v;
    uint size = views[view].info.z;
    uvec4 place = views[view].raster;
    uint shift = findLSB(size);  // tiles are powers of two
    uint end = min(size * size, (gl_WorkGroupID.y + 1u) * TEXELS_PER_WORKGROUP);
    for (uint i = gl_WorkGroupID.y * TEXELS_PER_WORKGROUP + gl_LocalInvocationIndex; i < end;
         i += gl_WorkGroupSize.x) {
      uint x = i & (size - 1u);
      uint y = i >> shift;
#if SAVE
      layers[place.z + y * place.w + x] = depths[place.x + y * place.y + x];
#else
      depths[place.x + y * place.y + x] = layers[place.z + y * place.w + x];
#endif
    }
  }
}

#endif
