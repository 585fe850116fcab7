// SPDX-License-Identifier: MIT
// The GPU-driven shadow views (systems/shadow_maps/shadow_view_batch.h): every shadow view re-rendered this
// frame (a 2D map or one cube face, each a tile of the shadow atlas) is a ShadowView record;
// shadow_cull.comp tests every caster against every view and keeps (caster, view) pairs,
// shadow_draws.comp turns their counts into one indirect draw per (view kind, mesh),
// shadow_scatter.comp sorts the pairs into those draws' instance ranges, and
// shadow_batch.vert draws them all into their tiles. Must match systems/shadow_maps/shadow_batch_records.cpp.
#ifndef SG_SHADOW_VIEWS_GLSL
#define SG_SHADOW_VIEWS_GLSL

#include "bindings.glsl"

const uint VIEW_KIND_MAP = 0u;   // 2D map: depth only
const uint VIEW_KIND_FACE = 1u;  // cube face: distance / far from shadow_cube.frag
const uint VIEW_KINDS = 2u;

struct ShadowView {
  mat4 view_projection;  // world -> the view's clip space
  vec4 tile;             // the view's clip xy -> the atlas page's: xy scale, zw offset (times w)
  vec4 position_far;     // cube faces: the light's position and far plane (shadow_cube.frag);
                         // 2D maps: the light's position and reach, w < 0 for none
  uvec4 info;            // x: atlas layer; y: VIEW_KIND_*; z: tile side, texels; w: the layers
                         // whose casters it draws (ShadowSettings::caster_mask)
  uvec4 raster;          // shadow_raster.comp: x where the tile's texel (0, 0) is in the depths,
                         // y the depths' row pitch there (tiles side by side share rows); z where
                         // it is in the static layers (shadow_static_layers.comp), w their pitch
};

struct ShadowCaster {
  vec3 lo;        // world bounds' minimum
  uint group;     // the caster's mesh (caster group), with CASTER_MOVING set for a moving caster
                  // and CASTER_BLENDED for a transparent one
  vec3 hi;        // world bounds' maximum
  uint instance;  // its index in Instances, below 2^24; above, its shadow layers
                  // (MeshInstance::shadow_layers)
};

// Casters a block record bounds (systems/shadow_maps/shadow_batch_records.h): after the casters,
// each list's casters in blocks of CASTER_BLOCK, each block a ShadowCaster holding their bounds
// and layers (no layers: none to keep), which shadow_cull.comp tests before their casters.
const uint CASTER_BLOCK = 64u;

const uint CASTER_MOVING = 0x80000000u;
const uint CASTER_BLENDED = 0x40000000u;

uint caster_group(ShadowCaster caster) { return caster.group & ~(CASTER_MOVING | CASTER_BLENDED); }
bool caster_moving(ShadowCaster caster) { return (caster.group & CASTER_MOVING) != 0u; }
bool caster_blended(ShadowCaster caster) { return (caster.group & CASTER_BLENDED) != 0u; }
uint caster_instance(ShadowCaster caster) { return caster.instance & 0xFFFFFFu; }
// Whether `view` draws `caster`: they share a layer.
bool caster_in_view(ShadowCaster caster, ShadowView view) { return ((caster.instance >> 24) & view.info.w) != 0u; }

// Geometry of caster group g: what its indirect commands draw.
struct CasterMesh {
  uint index_count;
  uint first_index;
  int vertex_offset;
  uint cut_out;  // 1 for masked or transparent materials (shadow_cut_out.glsl), else 0
};

// One indirect draw per (view kind k, caster group g), at k * groups + g.
struct DrawCommand {
  uint index_count;
  uint instance_count;
  uint first_index;
  int vertex_offset;
  uint first_instance;
};

layout(std430, set = 0, binding = shadow_views_binding) readonly buffer ShadowViews { ShadowView views[]; };

#endif
