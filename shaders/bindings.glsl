// Descriptor binding numbers of the engine's passes (set 0), declared once for the shaders and
// for the C++ that binds them (systems/shader_bindings.h includes this file): a `const int` reads
// the same in GLSL and C++. The forward pass binds instances, lights, the shadow images and the
// material textures; the shadow passes bind instances, cube faces and view instances.
#ifndef SG_BINDINGS_GLSL
#define SG_BINDINGS_GLSL

const int instances_binding = 0;             // scene_interface.glsl
const int lights_binding = 1;                // lights_interface.glsl
const int shadow_maps_binding = 2;           // lights_interface.glsl
const int shadow_maps_compare_binding = 3;   // lights_interface.glsl
const int shadow_cubes_binding = 4;          // lights_interface.glsl
const int cube_faces_binding = 5;            // shadow_cube_layered.vert
const int view_instances_binding = 6;        // shadow_casters.glsl
const int material_textures_binding = 7;     // scene.frag

#endif
