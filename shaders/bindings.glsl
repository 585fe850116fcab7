// SPDX-License-Identifier: MIT
// Descriptor binding numbers of the engine's passes (set 0), declared once for the shaders and
// for the C++ that binds them (systems/gpu/shader_bindings.h includes this file): a `const int` reads
// the same in GLSL and C++. Each pass binds the subset it uses.
#ifndef SG_BINDINGS_GLSL
#define SG_BINDINGS_GLSL

// The scene's instances and lights, the shadow images, the material textures: forward and
// G-buffer passes, shadow passes, tiled lighting.
const int instances_binding = 0;            // scene_interface.glsl
const int lights_binding = 1;               // lights_interface.glsl
const int shadow_maps_binding = 2;          // lights_interface.glsl
const int shadow_maps_compare_binding = 3;  // lights_interface.glsl
const int shadow_views_binding = 4;         // shadow_views.glsl
const int cube_faces_binding = 5;           // shadow_cube_layered.vert
const int view_instances_binding = 6;       // shadow_casters.glsl
const int material_textures_binding = 7;    // material.glsl

// Tiled deferred lighting (light_tiles.glsl): the G-buffer, the sum being lit, the tile lists.
const int gbuffer_normal_binding = 9;
const int gbuffer_albedo_binding = 10;
const int hdr_binding = 11;  // the lit sum: a storage image while lighting, sampled by tone mapping
const int scene_depth_binding = 12;
const int tile_lights_binding = 13;
const int tile_ranges_binding = 14;
const int group_tiles_binding = 15;
const int group_commands_binding = 16;
// Transparent surfaces' depth bounds per tile (light_tiles_interface.glsl's transparent variant).
const int transparent_bounds_binding = 27;
// How many (tile, light) pairs did not fit a tile's list this frame (light_tiles_interface.glsl).
const int light_tiles_feedback_binding = 28;
// Each light's shade and weight at each pixel, for measuring the frame (shadow_probe.comp).
const int shadow_probe_binding = 29;
// The coarse pass of light culling (light_tiles_coarse.glsl): each tile's volume, each coarse
// tile's list of lights, and where each list lies.
const int tile_volumes_binding = 30;
const int coarse_lights_binding = 31;
const int coarse_ranges_binding = 32;

// GPU-driven shadow views (shadow_views.glsl): the casters' bounds, their meshes, the culled
// (caster, view) pairs, their counts per draw, and the indirect commands built from them.
const int shadow_casters_binding = 17;
const int caster_meshes_binding = 18;
const int culled_pairs_binding = 19;
const int draw_counts_binding = 20;
const int shadow_draws_binding = 21;
const int shadow_feedback_binding = 22;
// Compute rasterization of the due views (shadow_raster.comp): their depths, and the geometry.
const int shadow_depths_binding = 23;
const int mesh_vertices_binding = 24;
const int mesh_indices_binding = 25;
// The static layers of the shadow maps (shadow_static_layers.comp).
const int static_layers_binding = 26;

#endif
