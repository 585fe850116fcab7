// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_ARB_shader_viewport_layer_array : require
// The compute raster's depths into the atlas where its rectangles of due tiles are too small to
// copy (systems/shadow_maps/compute_shadow_raster.cpp says where): two triangles per view,
// instance k covering view k's tile (ShadowView::tile) on its atlas layer, shadow_depth_copy.frag
// writing each texel's depth from the view's square of the depth buffer. A buffer-to-image copy
// pays for each rectangle, and the due tiles of a frame with thousands of lights lie scattered.
//
// Device features: shaderOutputLayer (gl_Layer from a vertex shader), as the hardware raster.
#include "shadow_views.glsl"

layout(location = 0) noperspective out vec2 out_texel;  // texels from the tile's top-left corner
layout(location = 1) flat out uvec2 out_place;          // ShadowView::raster.xy

const vec2 CORNERS[6] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(-1.0, 1.0),
                               vec2(1.0, -1.0), vec2(1.0, 1.0));

void main() {
  vec2 corner = CORNERS[gl_VertexIndex];
  vec4 tile = views[gl_InstanceIndex].tile;
  // The view's clip square into its tile of the page, as shadow_batch.vert moves casters; texel
  // rows count from clip y = -1, as shadow_raster.comp's do.
  gl_Position = vec4(corner * tile.xy + tile.zw, 0.0, 1.0);
  gl_Layer = int(views[gl_InstanceIndex].info.x);
  out_texel = (corner * 0.5 + 0.5) * float(views[gl_InstanceIndex].info.z);
  out_place = views[gl_InstanceIndex].raster.xy;
}
