// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// variant cut_out SHADOW_CUT_OUT
// Rasterizes the culled (caster, view) pairs in compute, for small views whose triangles the
// raster hardware of some GPUs sets up far slower than compute can (docs/PERFORMANCE.md): one
// workgroup per pair, its threads taking the caster's triangles. Each view's depths are a
// tile-sized square of `depths` (ShadowView::raster, row-major, filled with 1.0 beforehand),
// written with atomicMin on the float's bits (non-negative floats order as their bits); a copy
// moves them into the view's atlas tile afterwards. What is stored matches the raster path:
// projected depth for 2D maps, distance / far for cube faces (shadow_cube.frag), the nearest
// surface at each texel centre, both faces of every triangle, nothing nearer than the near plane
// or beyond far.
//
// llvmpipe ends every loop of an invocation once it has run 65,535 iterations in all, which a
// thread rasterizing large tiles passes: on CPU devices use the raster hardware path (the
// default there) or tiles of at most 512 texels.
//
// A triangle reaching out of the view is clipped to its near plane and sides first, so that its
// corners lie within the tile and edge functions are exact. A thread rasterizes a small triangle
// alone; one covering more than SMALL_TRIANGLE texels of bounding box goes to a queue that the
// whole workgroup then rasterizes together, so a floor filling the tile does not hold one thread
// for thousands of texels; past 16 texels, which measured best on the H200 (2026-12-01: 3.58-3.60
// ms against 3.87-3.88 at 64, 4.06-4.12 at 256 and 3.66-3.68 at 4 for 4,096 lights). 128 threads
// a workgroup: on the H200 the large triangles' texels outweigh the idle lanes of casters with
// fewer triangles (2026-11-30: 6.1 ms against 9.3 with 64 for 1,024 lights, docs/PERFORMANCE.md).
//
// Casters with a cut-out (shadow_cut_out.glsl) are the cut_out variant's: it carries each
// corner's uv through clipping and tests the material at every texel. Each variant passes over
// the other's pairs, so that opaque casters pay nothing for it.
#include "shadow_batch_compute.glsl"
#include "scene_instances.glsl"
#ifdef SHADOW_CUT_OUT
#include "shadow_cut_out.glsl"
#endif

layout(local_size_x = 128) in;

layout(std430, set = 0, binding = culled_pairs_binding) readonly buffer Pairs { uvec2 pairs[]; };
layout(std430, set = 0, binding = caster_meshes_binding) readonly buffer Meshes { CasterMesh meshes[]; };
layout(std430, set = 0, binding = mesh_vertices_binding) readonly buffer Vertices { float vertices[]; };
layout(std430, set = 0, binding = mesh_indices_binding) readonly buffer Indices { uint indices[]; };
layout(std430, set = 0, binding = shadow_depths_binding) buffer Depths { uint depths[]; };

const uint VERTEX_FLOATS = 8u;  // scene::Vertex: position, normal, uv
const float SMALL_TRIANGLE = 16.0;
// A triangle clipped by the near plane and the view's four sides has at most 3 + 5 corners;
// one more for rounding, which can make a polygon with nearly coincident corners cross a plane
// more than twice.
const uint MAX_CORNERS = 9u;
// The sides are moved out by this factor of w: a hair beyond the tile, so that clipping never
// removes a texel centre, and close enough that edge functions stay exact in float.
const float SIDE_MARGIN = 1.01;
// Large triangles queued for the workgroup at a time; past it a thread rasterizes its own.
const uint QUEUE = gl_WorkGroupSize.x;

// What a triangle's corner carries besides its position: its world position (for cube faces)
// and, cut out, its uv.
struct Corner {
  vec3 world;
#ifdef SHADOW_CUT_OUT
  vec2 uv;
#endif
};

Corner mix_corners(Corner a, Corner b, float s) {
  Corner m;
  m.world = mix(a.world, b.world, s);
#ifdef SHADOW_CUT_OUT
  m.uv = mix(a.uv, b.uv, s);
#endif
  return m;
}

// A triangle ready to rasterize: per corner, tile-space x, y (texels), depth (clip z / w) and
// 1 / w, and the rest of the corner.
struct Triangle {
  vec4 v[3];
  Corner corner[3];
};

#ifdef SHADOW_CUT_OUT
vec4 pair_material;  // the caster's Instance::material, the same for the whole workgroup
#endif

shared Triangle queue[QUEUE];
shared uint queued;

float edge(vec2 a, vec2 b, vec2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }

// The weights that interpolate `t`'s corners perspective-correctly at barycentric `bary`.
vec3 perspective_weights(Triangle t, vec3 bary) {
  vec3 w = bary * vec3(t.v[0].w, t.v[1].w, t.v[2].w);
  return w / (w.x + w.y + w.z);
}

// Writes the depth of `t` at `texel` if the texel centre, with barycentric coordinates `bary`,
// lies inside it and between the planes.
void write_texel(Triangle t, vec3 bary, uvec2 texel, bool face, vec4 light, uvec2 place) {
  if (any(lessThan(bary, vec3(0.0)))) return;
  float z = dot(bary, vec3(t.v[0].z, t.v[1].z, t.v[2].z));
  if (z < 0.0 || z > 1.0) return;  // beyond the far plane (the near one is clipped)
#ifdef SHADOW_CUT_OUT
  vec3 u = perspective_weights(t, bary);
  vec2 uv = u.x * t.corner[0].uv + u.y * t.corner[1].uv + u.z * t.corner[2].uv;
  if (shadow_cut_out(pair_material, uv, texel)) return;
#endif
  float depth = z;
  if (face) {
    vec3 w = perspective_weights(t, bary);
    vec3 world = w.x * t.corner[0].world + w.y * t.corner[1].world + w.z * t.corner[2].world;
    depth = min(length(world - light.xyz) / light.w, 1.0);
  }
  atomicMin(depths[place.x + texel.y * place.y + texel.x], floatBitsToUint(depth));
}

// Rasterizes texels first, first + stride, ... of `t`'s bounding box (stride 1 for a thread
// alone, the workgroup size together).
void rasterize(Triangle t, uint view, uint first, uint stride) {
  uint size = views[view].info.z;
  vec4 v0 = t.v[0], v1 = t.v[1], v2 = t.v[2];
  vec2 lo = max(floor(min(min(v0.xy, v1.xy), v2.xy) - 0.5), vec2(0.0));
  vec2 hi = min(ceil(max(max(v0.xy, v1.xy), v2.xy) - 0.5), vec2(float(size) - 1.0));
  if (any(greaterThan(lo, hi))) return;
  float area = edge(v0.xy, v1.xy, v2.xy);
  if (area == 0.0) return;
  bool face = views[view].info.y == VIEW_KIND_FACE;
  vec4 light = views[view].position_far;
  uvec2 place = views[view].raster.xy;
  // The barycentric coordinates as planes over the box, from its corner: bary = base + across * x
  // + down * y at the texel centre x, y texels from it. Edge functions divided by the signed area,
  // so that inside is positive for both windings (both are drawn); a few multiply-adds a texel.
  vec2 a = v0.xy - lo, b = v1.xy - lo, c = v2.xy - lo;
  float inv_area = 1.0 / area;
  vec3 across = vec3(b.y - c.y, c.y - a.y, a.y - b.y) * inv_area;
  vec3 down = vec3(c.x - b.x, a.x - c.x, b.x - a.x) * inv_area;
  vec3 base = vec3(b.x * c.y - b.y * c.x, c.x * a.y - c.y * a.x, a.x * b.y - a.y * b.x) * inv_area;
  uvec2 corner = uvec2(lo);
  uint width = uint(hi.x - lo.x) + 1u;
  uint rows = uint(hi.y - lo.y) + 1u;
  if (stride == 1u) {
    for (uint y = 0u; y < rows; ++y) {
      vec3 row = base + down * (float(y) + 0.5);
      for (uint x = 0u; x < width; ++x) {
        write_texel(t, row + across * (float(x) + 0.5), corner + uvec2(x, y), face, light, place);
      }
    }
    return;
  }
  for (uint i = first; i < width * rows; i += stride) {
    uint y = i / width;
    uint x = i - y * width;
    vec3 bary = base + across * (float(x) + 0.5) + down * (float(y) + 0.5);
    write_texel(t, bary, corner + uvec2(x, y), face, light, place);
  }
}

vec4 to_tile(vec4 clip, float size) {
  float inv_w = 1.0 / clip.w;
  return vec4((clip.xy * inv_w * 0.5 + 0.5) * size, clip.z * inv_w, inv_w);
}

// Rasterizes the (clipped) triangle with clip positions c0..c2 now if it is small, else queues it
// for the workgroup (or, with the queue full, rasterizes it anyway).
void emit(vec4 c0, vec4 c1, vec4 c2, Corner a0, Corner a1, Corner a2, uint view) {
  float size = float(views[view].info.z);
  Triangle t;
  t.v = vec4[](to_tile(c0, size), to_tile(c1, size), to_tile(c2, size));
  t.corner = Corner[](a0, a1, a2);
  vec2 extent = max(max(t.v[0].xy, t.v[1].xy), t.v[2].xy) - min(min(t.v[0].xy, t.v[1].xy), t.v[2].xy);
  if (extent.x * extent.y > SMALL_TRIANGLE) {
    uint slot = atomicAdd(queued, 1u);
    if (slot < QUEUE) {
      queue[slot] = t;
      return;
    }
  }
  rasterize(t, view, 0u, 1u);
}

// Vertex `index`'s corner under `model`, and its clip position in `view_projection`.
Corner vertex_corner(uint index, mat4 model, mat4 view_projection, out vec4 clip) {
  uint v = index * VERTEX_FLOATS;
  Corner corner;
  corner.world = (model * vec4(vertices[v], vertices[v + 1u], vertices[v + 2u], 1.0)).xyz;
#ifdef SHADOW_CUT_OUT
  corner.uv = vec2(vertices[v + 6u], vertices[v + 7u]);
#endif
  clip = view_projection * vec4(corner.world, 1.0);
  return corner;
}

bool inside_view(vec4 c) { return c.z >= 0.0 && abs(c.x) <= c.w && abs(c.y) <= c.w; }

// The view's planes a triangle is clipped to, as dot(plane, clip position) >= 0: the near plane
// and the four sides.
const vec4 CLIP_PLANES[5] = vec4[](vec4(0.0, 0.0, 1.0, 0.0), vec4(1.0, 0.0, 0.0, SIDE_MARGIN),
                                   vec4(-1.0, 0.0, 0.0, SIDE_MARGIN), vec4(0.0, 1.0, 0.0, SIDE_MARGIN),
                                   vec4(0.0, -1.0, 0.0, SIDE_MARGIN));

// Emits the triangle (clip positions c0..c2, corners a0..a2) as it is when it lies in the view,
// which most do, else clipped to the view (Sutherland-Hodgman) as a fan.
void submit(vec4 c0, vec4 c1, vec4 c2, Corner a0, Corner a1, Corner a2, uint view) {
  if (inside_view(c0) && inside_view(c1) && inside_view(c2)) {
    emit(c0, c1, c2, a0, a1, a2, view);
    return;
  }
  vec4 c[MAX_CORNERS];
  Corner w[MAX_CORNERS];
  c[0] = c0;
  c[1] = c1;
  c[2] = c2;
  w[0] = a0;
  w[1] = a1;
  w[2] = a2;
  uint n = 3u;
  for (uint p = 0u; p < 5u && n >= 3u; ++p) {
    vec4 plane = CLIP_PLANES[p];
    vec4 kept_c[MAX_CORNERS];
    Corner kept_w[MAX_CORNERS];
    uint m = 0u;
    for (uint k = 0u; k < n; ++k) {
      uint next = k + 1u == n ? 0u : k + 1u;
      float dk = dot(plane, c[k]);
      float dn = dot(plane, c[next]);
      if (dk >= 0.0 && m < MAX_CORNERS) {
        kept_c[m] = c[k];
        kept_w[m] = w[k];
        ++m;
      }
      // Strictly across: a corner on the plane is kept once, not again as a crossing.
      if (((dk > 0.0 && dn < 0.0) || (dk < 0.0 && dn > 0.0)) && m < MAX_CORNERS) {
        float s = dk / (dk - dn);
        kept_c[m] = mix(c[k], c[next], s);
        kept_w[m] = mix_corners(w[k], w[next], s);
        ++m;
      }
    }
    c = kept_c;
    w = kept_w;
    n = m;
  }
  for (uint k = 1u; k + 1u < n; ++k) emit(c[0], c[k], c[k + 1u], w[0], w[k], w[k + 1u], view);
}

void main() {
  uint stored = min(pc.list == 0u ? total : moving_total, pc.capacity);
  for (uint p = gl_WorkGroupID.x; p < stored; p += gl_NumWorkGroups.x) {
    uvec2 pair = pairs[p];
    uint view = pair.y;
    uint group = caster_group(casters[pair.x]);
    CasterMesh mesh = meshes[group];
#ifdef SHADOW_CUT_OUT
    if (mesh.cut_out == 0u) continue;
    pair_material = instances[caster_instance(casters[pair.x])].material;
#else
    if (mesh.cut_out != 0u) continue;
#endif
    mat4 model = instances[caster_instance(casters[pair.x])].model;
    mat4 view_projection = views[view].view_projection;
    uint triangles = mesh.index_count / 3u;
    for (uint chunk = 0u; chunk < triangles; chunk += gl_WorkGroupSize.x) {
      if (gl_LocalInvocationIndex == 0u) queued = 0u;
      barrier();
      uint tri = chunk + gl_LocalInvocationIndex;
      if (tri < triangles) {
        uint first = mesh.first_index + 3u * tri;
        vec4 c0, c1, c2;
        Corner a0 = vertex_corner(uint(int(indices[first]) + mesh.vertex_offset), model, view_projection, c0);
        Corner a1 = vertex_corner(uint(int(indices[first + 1u]) + mesh.vertex_offset), model, view_projection, c1);
        Corner a2 = vertex_corner(uint(int(indices[first + 2u]) + mesh.vertex_offset), model, view_projection, c2);
        submit(c0, c1, c2, a0, a1, a2, view);
      }
      barrier();
      uint count = min(queued, QUEUE);
      for (uint q = 0u; q < count; ++q) rasterize(queue[q], view, gl_LocalInvocationIndex, gl_WorkGroupSize.x);
      barrier();
    }
  }
}
