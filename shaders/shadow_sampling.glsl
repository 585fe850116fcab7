// SPDX-License-Identifier: MIT
// The five per-light shadow algorithms of docs/ALGORITHMS.md section 4, on 2D maps (spot,
// directional and cylinder lights: a square tile of one shadow_atlas layer) and on point
// lights' cube maps (six tiles of one layer, one per face). Entry point: light_shadow_as(). Every function returns the shadow factor
// `shade` in [0, 1], 1 = fully shadowed; a point outside the map or beyond its far plane is lit.
//
// Biases are *normalized linear depth*, so that a bias means the same distance anywhere in a
// map: view depth / far for perspective 2D maps, the stored depth itself for orthographic maps
// (linear over near..far), and distance / far for cube maps, which store exactly that
// (shadow_cube.frag). Kernel taps compare fetched depths as stored, with no conversion and no
// division per tap: a CPU driver's divider is what the kernels would otherwise wait on.
//
// Samplers (lights_interface.glsl): shadow_atlas plain reads with a NEAREST sampler; shadow_atlas_compare a comparison sampler over the same image with LINEAR filtering
// (each fetch is a 2x2 bilinear PCF) and VK_COMPARE_OP_LESS_OR_EQUAL (1 = lit). Every fetch has an
// explicit level of detail, as lights are evaluated in non-uniform control flow.
//
// Kernels, at their default sizes (each light may choose others, light_record.glsl's KERNEL_*):
// pcf a 3x3 grid (the source's), noise 16 Gaussian offsets (a stratified pattern turned randomly
// per shadow-map texel, map_texel_seed), pcss 16 blocker-search and 32 filter samples of a Poisson
// disk on 2D maps and the 20 directions of section 4 on cube maps, fewer where the kernel spans a
// texel or two (search_taps_by_footprint); pcss_noise the same kernels rotated randomly per
// shadow-map texel. Every kernel loop but the pcf grid's and the cube pcss filter's is marked [[unroll]]: left to
// itself the compiler kept the 32-tap pcss filter a loop, whose Poisson disk lookups with the
// loop counter llvmpipe does through memory, lane by lane (a fifth of the 2D pcss_noise pass);
// unrolled, the table entries are constants. The cube pcss filter is a loop that lit areas skip,
// its offsets worked out from the counter (cube_offset). The same for the 2D filter, its offsets
// picked from the table by selects in chunks of 8 taps, measured no faster on lavapipe.
#ifndef SG_SHADOW_SAMPLING_GLSL
#define SG_SHADOW_SAMPLING_GLSL

#extension GL_EXT_control_flow_attributes : require

#include "light_formulas.glsl"
#include "light_groups.glsl"
#include "lights_interface.glsl"

const uint NOISE_SAMPLES = 16u;
const uint PCSS_BLOCKER_SAMPLES = 16u;
const uint PCSS_FILTER_SAMPLES = 32u;

// Mitchell's best-candidate points in the unit disk: every prefix is well spread, so the
// blocker search uses the first 16 and the filter all 32.
const vec2 POISSON_DISK[32] = vec2[](
    vec2(0.5867, 0.6439), vec2(-0.6497, -0.6319), vec2(-0.7711, 0.6312), vec2(0.6956, -0.6727),
    vec2(0.0117, -0.0660), vec2(-0.1406, 0.9737), vec2(0.0031, -0.9956), vec2(0.9012, 0.0402),
    vec2(-0.9934, -0.0583), vec2(-0.2636, 0.4069), vec2(0.1924, -0.5298), vec2(-0.5277, -0.1600),
    vec2(0.4234, 0.1911), vec2(0.5643, -0.2443), vec2(0.1106, 0.6065), vec2(-0.2136, -0.6078),
    vec2(-0.6894, 0.2220), vec2(0.3802, -0.9181), vec2(0.3466, 0.9328), vec2(0.9297, -0.3571),
    vec2(-0.4298, 0.7374), vec2(-0.3782, -0.9227), vec2(0.8772, 0.4355), vec2(-0.9085, -0.3986),
    vec2(0.0279, 0.2665), vec2(-0.3129, 0.0729), vec2(-0.2628, -0.3027), vec2(0.3059, -0.1001),
    vec2(-0.9655, 0.2401), vec2(-0.5435, 0.4605), vec2(0.7017, 0.2276), vec2(0.3719, 0.4599));

// Taps by footprint: how many of the PCSS blocker search's nearest fetches a disk
// `radius_texels` map texels wide needs. A few texels hold a few distinct depths, which a 4- or
// 8-tap prefix of the well-spread disk already reads; the small maps of distant or demoted lights
// mostly search over a texel or two. The filter keeps more (shadow_2d_pcss): its bilinear
// comparisons against the receiver plane average away the plane's mismatch, and a quarter of
// them raised acne on lit surfaces at 32-64 texel maps (docs/QUALITY.md).
uint search_taps_by_footprint(float radius_texels) {
  if (radius_texels <= 1.25) return PCSS_BLOCKER_SAMPLES / 4u;
  return radius_texels <= 2.5 ? PCSS_BLOCKER_SAMPLES / 2u : PCSS_BLOCKER_SAMPLES;
}

// NOISE_SAMPLES points of a 2D standard normal distribution, stratified: the k-th at the radius
// where the Rayleigh distribution's CDF is (k + 0.5) / 16, sqrt(-2 ln(1 - (k + 0.5) / 16)), and
// k golden angles around (mean squared radius 1.96 against the distribution's 2).
const vec2 GAUSSIAN_DISK[16] = vec2[](
    vec2(0.2520, 0.0000), vec2(-0.3272, 0.2997), vec2(0.0510, -0.5807), vec2(0.4275, 0.5576),
    vec2(-0.8003, -0.1416), vec2(0.7744, -0.4926), vec2(-0.2651, 0.9861), vec2(-0.5184, -0.9982),
    vec2(1.1563, 0.4223), vec2(-1.2407, 0.5121), vec2(0.6194, -1.3236), vec2(0.4767, 1.5198),
    vec2(-1.5085, -0.8742), vec2(1.8819, -0.4137), vec2(-1.2514, 1.7800), vec2(-0.3383, -2.6109));

// NOISE_SAMPLES points of a 3D standard normal distribution, stratified likewise: the k-th at the
// radius where the chi distribution's CDF (3 degrees of freedom) is (k + 0.5) / 16, in the
// direction of point 7k mod 16 of a 16-point Fibonacci sphere (mean squared radius 2.95 against
// the distribution's 3).
const vec3 GAUSSIAN_BALL[16] = vec3[](
    vec3(0.1748, 0.0000, 0.4708), vec3(-0.3432, -0.6609, 0.0466), vec3(-0.3043, 0.4329, -0.7375),
    vec3(0.8340, -0.5305, 0.3252), vec3(-0.8293, -0.4806, -0.6521), vec3(0.6391, 0.8336, 0.7146),
    vec3(0.5547, -1.1855, -0.4306), vec3(-0.6381, 0.5845, 1.2061), vec3(1.4930, 0.5453, -0.0995),
    vec3(-0.0762, -0.5884, -1.5983), vec3(-0.4652, 1.7305, 0.3421), vec3(1.3867, -0.3049, -1.3442),
    vec3(-1.8634, -0.3296, 0.9207), vec3(0.6150, 1.9607, -0.9998), vec3(0.1606, -1.8299, 1.7391),
    vec3(-2.7022, 1.1154, -0.5580));

// Section 4's 20 offsets around fragToLight for cube maps: the 8 (+-1, +-1, +-1), then the 12 with
// one zero coordinate. Worked out from k rather than read from a table, so that a loop whose
// counter is k (shadow_cube_pcss's filter) reads no memory: a CPU driver reads a table indexed by
// a loop counter lane by lane. With a literal k it folds to a constant.
const uint CUBE_OFFSET_COUNT = 20u;
const uint CUBE_CORNER_COUNT = 8u;  // the first eight, a kernel symmetric about fragToLight itself
vec3 cube_offset(uint k) {
  uint i = k & 3u;
  float a = i < 2u ? 1.0 : -1.0;                // 1, 1, -1, -1
  float b = (i == 0u || i == 3u) ? 1.0 : -1.0;  // 1, -1, -1, 1
  uint four = k >> 2u;
  if (four < 2u) return vec3(a, b, four == 0u ? 1.0 : -1.0);
  if (four == 2u) return vec3(a, b, 0.0);
  if (four == 3u) return vec3((i & 1u) == 0u ? 1.0 : -1.0, 0.0, a);
  return vec3(0.0, b, a);
}

// ---- randomness, stable on the surface ----

// The noise algorithms draw their random rotation per shadow-map texel: the texel holding the
// receiver, in the map (or cube face) whose tile starts at `origin` in atlas layer `layer`. Drawn
// per screen pixel, a pattern swam over still surfaces as the camera moved; a texel stays where
// the map puts it. The texel's cell and a hash of its map, for cell_random (light_formulas.glsl).
uvec3 map_texel_seed(vec2 origin, uint layer, vec2 uv, float texel_uv) {
  float texels = 1.0 / texel_uv;
  uvec2 texel = uvec2(clamp(floor(uv * texels), vec2(0.0), vec2(texels - 1.0)));
  return uvec3(texel, pcg3d(uvec3(floatBitsToUint(origin), layer)).x);
}

mat2 random_rotation_2d(uvec3 seed) {
  float angle = 6.28318531 * cell_random(seed.xy, seed.z ^ 1000u).x;
  float c = cos(angle), s = sin(angle);
  return mat2(c, s, -s, c);
}

// A uniformly random rotation, as a unit quaternion from four Gaussian numbers.
vec4 random_rotation_3d(uvec3 seed) {
  vec3 u = cell_random(seed.xy, seed.z ^ 1000u);
  vec3 w = cell_random(seed.xy, seed.z ^ 1001u);
  return normalize(vec4(gaussian_pair(u.xy), gaussian_pair(vec2(u.z, w.x))));
}

vec3 rotate(vec4 q, vec3 v) {
  return v + 2.0 * cross(q.xyz, cross(q.xyz, v) + q.w * v);
}

// ---- 2D maps ----

// The receiver in a 2D map, its depths as the map stores them (perspective depth for spot
// maps): a plane's stored depth is affine in the map's uv (for perspective maps because 1/z is),
// so the plane's depth at any tap is one dot product away.
struct MapPoint {
  bool orthographic;  // the map's projection (map_is_orthographic)
  vec2 uv;            // in the light's own square map, [0, 1]^2
  float depth;        // the receiver's stored depth
  float view_depth;   // its distance along the light's axis, world units
  vec2 depth_slope;   // d(stored depth)/d(uv) across the receiver's tangent plane (receiver-plane bias)
  float texel_slack;  // the most stored depth can change across one texel of that plane
  float per_linear;   // d(stored depth)/d(normalized linear depth) at the receiver: biases to stored units
};

// Directional and cylinder maps are orthographic, spot maps perspective: where the light types
// (`types`, LIGHT_TYPES' bits) say which the caller has, the other's code drops out.
bool map_is_orthographic(Light light, uint types) {
  const uint orthographic = (1u << LIGHT_DIRECTIONAL) | (1u << LIGHT_CYLINDER);
  uint only = light_types_only(types);
  if ((only & orthographic) == 0u) return false;
  if ((only & (1u << LIGHT_SPOT)) == 0u) return true;
  return light.shadow_depth.w > 0.5;
}

float map_linear_depth(Light light, float stored_depth, bool orthographic) {
  if (orthographic) return stored_depth;
  return perspective_view_depth(stored_depth, light.shadow_depth.x, light.shadow_depth.y) /
         light.shadow_depth.y;
}

float map_view_depth(Light light, float linear_depth, bool orthographic) {
  float near = light.shadow_depth.x, far = light.shadow_depth.y;
  return orthographic ? near + linear_depth * (far - near) : linear_depth * far;
}

// Section 3's lookup: proj = M_b * shadow_matrix * world, divided by w. Vulkan's NDC y points
// down like the framebuffer the map was rendered to, so M_b is (x + 1) / 2 on both axes.
//
// Filtering compares the receiver with texels away from its own uv, and a texel holds the depth
// at its centre: on a receiver tilted towards the light both differ from the receiver's depth
// by the plane's slope times the distance, which a constant or N.L bias cannot follow (acne on
// lit surfaces at grazing angles, growing with the kernel). So the receiver's tangent plane is
// carried into the map: the map's Jacobian at the point gives d(depth)/d(uv) on that plane, and
// every sample is compared with the plane's depth at the sample (receiver-plane depth bias).
bool project_to_map(Light light, vec3 world_pos, vec3 normal, uint types, out MapPoint point) {
  vec4 clip = light.shadow_matrix * vec4(world_pos, 1.0);
  point.orthographic = map_is_orthographic(light, types);
  point.uv = vec2(0.0);
  point.depth = 0.0;
  point.view_depth = 0.0;
  point.depth_slope = vec2(0.0);
  point.texel_slack = 0.0;
  point.per_linear = 1.0;
  if (clip.w <= 0.0) return false;  // behind a perspective light
  vec3 ndc = clip.xyz / clip.w;
  point.uv = ndc.xy * 0.5 + 0.5;
  if (any(lessThan(point.uv, vec2(0.0))) || any(greaterThan(point.uv, vec2(1.0))) ||
      ndc.z < 0.0 || ndc.z > 1.0) {
    return false;
  }
  point.depth = ndc.z;
  float linear_depth = map_linear_depth(light, ndc.z, point.orthographic);
  point.view_depth = map_view_depth(light, linear_depth, point.orthographic);
  if (!point.orthographic) {
    float near = light.shadow_depth.x, far = light.shadow_depth.y;
    point.per_linear = perspective_stored_depth_slope(point.view_depth, near, far) * far;
  }

  mat4 m = light.shadow_matrix;
  vec3 row_x = vec3(m[0][0], m[1][0], m[2][0]);
  vec3 row_y = vec3(m[0][1], m[1][1], m[2][1]);
  vec3 row_z = vec3(m[0][2], m[1][2], m[2][2]);
  vec3 row_w = vec3(m[0][3], m[1][3], m[2][3]);
  // uv = (clip.xy / clip.w + 1) / 2, stored depth = clip.z / clip.w (orthographic: row_w = 0, clip.w = 1).
  vec3 du = 0.5 * (row_x - ndc.x * row_w) / clip.w;
  vec3 dv = 0.5 * (row_y - ndc.y * row_w) / clip.w;
  vec3 dz = (row_z - ndc.z * row_w) / clip.w;
  vec3 t1 = normalize(abs(normal.y) < 0.9 ? cross(normal, vec3(0.0, 1.0, 0.0))
                                          : cross(normal, vec3(1.0, 0.0, 0.0)));
  vec3 t2 = cross(normal, t1);
  mat2 uv_per_tangent = mat2(dot(du, t1), dot(dv, t1), dot(du, t2), dot(dv, t2));
  float det = determinant(uv_per_tangent);
  // A plane seen edge-on from the light is unlit anyway (N.L = 0): no slope to follow.
  if (abs(det) > 1e-12) {
    vec2 depth_per_tangent = vec2(dot(dz, t1), dot(dz, t2));
    point.depth_slope = depth_per_tangent * inverse(uv_per_tangent);
    // Held to 10% of the (linear) depth range per texel, for planes nearly edge-on.
    float texel = light.shadow_depth.z;
    float most = 0.1 * point.per_linear / texel;
    point.depth_slope = clamp(point.depth_slope, vec2(-most), vec2(most));
    point.texel_slack = (abs(point.depth_slope.x) + abs(point.depth_slope.y)) * texel;
  }
  return true;
}

// The receiver plane's stored depth at map uv point.uv + offset, less `bias` (normalized linear
// depth, turned into stored units at the receiver).
float plane_reference(MapPoint point, vec2 offset, float bias) {
  return point.depth + dot(point.depth_slope, offset) - bias * point.per_linear;
}

// Atlas coordinates of map uv `uv`, held half a texel inside the light's region so that
// filtered fetches never read a neighbour's texels.
vec3 atlas_coord(Light light, vec2 uv) {
  float half_texel = 0.5 * light.shadow_depth.z;
  vec2 inside = clamp(uv, vec2(half_texel), vec2(1.0 - half_texel));
  return vec3(light.shadow_rect.xy + inside * light.shadow_rect.zw, float(light.info.w));
}

float fetch_depth(Light light, vec2 uv) {
  return textureLod(shadow_atlas, atlas_coord(light, uv), 0.0).r;
}

// Bilinear 2x2 PCF of the hardware: the shadowed fraction around uv for a stored-depth reference.
float compare_filtered(Light light, vec2 uv, float reference) {
  vec4 coord = vec4(atlas_coord(light, uv), reference);
  return 1.0 - textureGrad(shadow_atlas_compare, coord, vec2(0.0), vec2(0.0));
}

// The centre of the map texel holding `uv` (clamped into the map). Nearest fetches read at texel
// centres, so the texel read is the one the receiver plane is taken at: fetched at uv itself, a
// point within the sampler's subtexel precision of a texel's edge could read the neighbour and
// compare it with the plane at the other centre (acne in single pixels on slanted receivers).
vec2 texel_centre(Light light, vec2 uv) {
  float texels = 1.0 / light.shadow_depth.z;
  return (clamp(floor(uv * texels), vec2(0.0), vec2(texels - 1.0)) + 0.5) * light.shadow_depth.z;
}

// 4.1: z - bias > depth(uv) ? 1 : 0, on the nearest texel (z taken where that texel's depth was).
float shadow_2d_hard(Light light, MapPoint point, float bias) {
  vec2 centre = texel_centre(light, point.uv);
  return plane_reference(point, centre - point.uv, bias) > fetch_depth(light, centre) ? 1.0 : 0.0;
}

// A hardware 2x2 comparison at uv + offset against the receiver plane there; the four texels'
// centres lie within a texel, so the plane's change across one texel is given as slack.
float compare_plane(Light light, MapPoint point, vec2 offset, float bias) {
  return compare_filtered(light, point.uv + offset, plane_reference(point, offset, bias) - point.texel_slack);
}

// The atlas texel, per axis, that a nearest fetch at map uv `uv` reads: the sampler's own
// arithmetic (clamp to the edge, scale, floor) on the same coordinate.
ivec2 nearest_atlas_texel(Light light, vec2 uv, vec2 atlas_size) {
  return ivec2(floor(atlas_coord(light, uv).xy * atlas_size));
}

// shadow_2d_pcf's 3x3 grid where each comparison reads one texel (NEAREST_COMPARISONS): the nine
// taps' texels lie in the 4x4 block from the first tap's wherever the grid spans at most three
// texels a side (pcfRadius up to 1.5), and four gathers read that block, where nine fetches read
// a texel each. The taps compare exactly what the comparison sampler would, so the picture is
// the same to the bit; on lavapipe the default scene's frame took 120.7-121.6 ms against
// 126.9-127.4, `spot-columns`' light 16.1-16.7 against 18.9-19.6 (2026-12-05,
// docs/PERFORMANCE.md). `spans_block` is false where the grid is wider.
float shadow_2d_pcf_gathered(Light light, MapPoint point, float bias, float step_uv, out bool spans_block) {
  vec2 atlas_size = vec2(textureSize(shadow_atlas, 0).xy);
  ivec2 first = nearest_atlas_texel(light, point.uv - vec2(step_uv), atlas_size);
  ivec2 middle = nearest_atlas_texel(light, point.uv, atlas_size) - first;
  ivec2 last = nearest_atlas_texel(light, point.uv + vec2(step_uv), atlas_size) - first;
  spans_block = all(lessThanEqual(last, ivec2(3))) && all(greaterThanEqual(middle, ivec2(0)));
  // A gather at a texel corner reads the 2x2 texels around it, as (0,1) (1,1) (1,0) (0,0).
  float layer = float(light.info.w);
  vec2 corner = vec2(first) + 1.0;
  vec4 top_left = textureGather(shadow_atlas, vec3(corner / atlas_size, layer), 0);
  vec4 top_right = textureGather(shadow_atlas, vec3((corner + vec2(2.0, 0.0)) / atlas_size, layer), 0);
  vec4 bottom_left = textureGather(shadow_atlas, vec3((corner + vec2(0.0, 2.0)) / atlas_size, layer), 0);
  vec4 bottom_right = textureGather(shadow_atlas, vec3((corner + vec2(2.0)) / atlas_size, layer), 0);
  vec4 block[4] = vec4[](vec4(top_left.wz, top_right.wz), vec4(top_left.xy, top_right.xy),
                         vec4(bottom_left.wz, bottom_right.wz), vec4(bottom_left.xy, bottom_right.xy));
  ivec3 columns = ivec3(0, middle.x, last.x);
  ivec3 rows = ivec3(0, middle.y, last.y);
  float sum = 0.0;
  // Texels picked by selects: a local array indexed per lane goes through memory on a CPU driver.
  [[unroll]] for (int y = 0; y < 3; ++y) {
    int r = rows[y];
    vec4 row = r == 0 ? block[0] : (r == 1 ? block[1] : (r == 2 ? block[2] : block[3]));
    [[unroll]] for (int x = 0; x < 3; ++x) {
      int c = columns[x];
      float depth = c == 0 ? row.x : (c == 1 ? row.y : (c == 2 ? row.z : row.w));
      float reference = plane_reference(point, vec2(x - 1, y - 1) * step_uv, bias) - point.texel_slack;
      sum += reference > depth ? 1.0 : 0.0;  // compare_plane's test, LESS_OR_EQUAL lit
    }
  }
  return sum / 9.0;
}

// 4.2: the hard test averaged over a (2k+1)^2 grid of offsets (x, y) * texel * pcfRadius, k the
// light's (pcf_half_width, 1 to 3). Loops over the light's own bounds: every invocation of a pass
// shades the same light at once, so a CPU driver runs exactly its taps, and the offsets come from
// the counters, not from a table. Do-while loops: llvmpipe tests whether any lane continues at a
// loop's end, so a for loop, whose lanes leave at the top, runs its body once more, masked (16
// taps' work for a 3x3 grid; the default scene's 2D pcf pass took 87 ms against 99 on lavapipe,
// 2026-12-03). Where the grid's nine nearest texels are gathered, the loops run once, masked.
float shadow_2d_pcf(Light light, MapPoint point, float bias) {
  float step_uv = light.shadow_bias.z * light.shadow_depth.z;
  int k = pcf_half_width(light);
  if (NEAREST_COMPARISONS && k == 1) {
    bool spans_block;
    float gathered = shadow_2d_pcf_gathered(light, point, bias, step_uv, spans_block);
    if (spans_block) return gathered;
  }
  float sum = 0.0;
  int y = -k;
  do {
    int x = -k;
    do {
      sum += compare_plane(light, point, vec2(x, y) * step_uv, bias);
    } while (++x <= k);
  } while (++y <= k);
  return sum / float((2 * k + 1) * (2 * k + 1));
}

// The seed of the map texel holding `point` (map_texel_seed).
uvec3 map_point_seed(Light light, MapPoint point) {
  return map_texel_seed(light.shadow_rect.xy, light.info.w, point.uv, light.shadow_depth.z);
}

// 4.3: like pcf with Gaussian offsets (r1, r2) * sigma, sigma = pcfRadius texels: the
// standard normal pattern GAUSSIAN_DISK turned by a random angle per map texel (section 4.3).
// Drawing each offset with Box-Muller cost a logarithm, a square root, a sine and a cosine per tap.
float shadow_2d_noise(Light light, MapPoint point, float bias) {
  float sigma_uv = light.shadow_bias.z * light.shadow_depth.z;
  mat2 rotation = random_rotation_2d(map_point_seed(light, point)) * sigma_uv;
  // The light's taps: every stride-th of the radial strata, so fewer still span the distribution.
  uint stride = noise_tap_stride(light);
  float sum = 0.0;
  [[unroll]] for (uint i = 0u; i < NOISE_SAMPLES; ++i) {
    if (i % stride != 0u) continue;
    sum += compare_plane(light, point, rotation * GAUSSIAN_DISK[i], bias);
  }
  return sum * float(stride) / float(NOISE_SAMPLES);
}

// 4.4 and 4.5. Radii are chosen in world units on the receiver's plane (facing the light) and
// converted to map uv there (map_uv_per_world_unit). The blocker search covers light_size
// around the receiver, which finds every blocker whose penumbra reaches it from the far two
// thirds of the way to a perspective light (zBlocker >= zReceiver / 3); nearer blockers would need
// most of the map searched. The filter radius is half the penumbra width, so the transition
// from lit to shadowed is w wide, and at least one texel, so contact shadows stay antialiased.
float shadow_2d_pcss(Light light, MapPoint point, float bias, bool jitter) {
  bool orthographic = point.orthographic;
  float light_size = light.shadow_bias.w;
  float uv_per_unit = map_uv_per_world_unit(projection_x_scale(light.shadow_matrix),
                                            point.view_depth, orthographic);
  mat2 rotation = jitter ? random_rotation_2d(map_point_seed(light, point)) : mat2(1.0);

  float search_uv = light_size * uv_per_unit;
  uint search_taps = min(search_taps_by_footprint(search_uv / light.shadow_depth.z), pcss_blocker_taps(light));
  float blocker_sum = 0.0;
  float blockers = 0.0;
  [[unroll]] for (uint i = 0u; i < PCSS_BLOCKER_SAMPLES; ++i) {
    if (i >= search_taps) break;
    vec2 centre = texel_centre(light, point.uv + rotation * POISSON_DISK[i] * search_uv);
    float depth = fetch_depth(light, centre);
    if (depth < plane_reference(point, centre - point.uv, bias)) {
      blocker_sum += depth;
      blockers += 1.0;
    }
  }
  if (blockers == 0.0) return 0.0;

  // Section 4.4 (b): the view depth recovered from the blockers' average stored depth.
  float blocker_linear = map_linear_depth(light, blocker_sum / blockers, orthographic);
  float blocker = map_view_depth(light, blocker_linear, orthographic);
  float width = orthographic
                    ? orthographic_penumbra_width(point.view_depth, blocker, light_size)
                    : pcss_penumbra_width(point.view_depth, blocker, light_size);
  float radius_uv = max(0.5 * width * uv_per_unit, light.shadow_depth.z);
  // Half the filter where it spans a texel or so (search_taps_by_footprint).
  uint filter_taps = min(radius_uv <= 1.25 * light.shadow_depth.z ? PCSS_FILTER_SAMPLES / 2u : PCSS_FILTER_SAMPLES,
                         pcss_filter_taps(light));
  float sum = 0.0;
  [[unroll]] for (uint i = 0u; i < PCSS_FILTER_SAMPLES; ++i) {
    if (i >= filter_taps) break;
    sum += compare_plane(light, point, rotation * POISSON_DISK[i] * radius_uv, bias);
  }
  return sum / float(filter_taps);
}

float shadow_2d_at(Light light, MapPoint point, float bias, uint algorithm) {
  if (algorithm == SHADOW_HARD) return shadow_2d_hard(light, point, bias);
  if (algorithm == SHADOW_PCF) return shadow_2d_pcf(light, point, bias);
  if (algorithm == SHADOW_NOISE) return shadow_2d_noise(light, point, bias);
  return shadow_2d_pcss(light, point, bias, algorithm == SHADOW_PCSS_NOISE);
}

float shadow_2d(Light light, vec3 world_pos, vec3 normal, float bias, uint algorithm, uint types) {
  MapPoint point;
  if (!project_to_map(light, world_pos, normal, types, point)) return 0.0;
  return shadow_2d_at(light, point, bias, algorithm);
}

// ---- cascades (directional lights, systems/shadows/cascades.h) ----

// sg::shadows::cascade_edge_uv and cascade_blend_uv.
const float CASCADE_EDGE_UV = 1.0 / 64.0;
const float CASCADE_BLEND_UV = 1.0 / 10.0;

// `light` with cascade k's map in its shadow fields.
Light cascade_of(Light light, uint k) {
  Light cascade = light_at(uint(light.shape.x) + k);
  light.info.w = cascade.info.w;
  light.shadow_rect = cascade.shadow_rect;
  light.shadow_depth = cascade.shadow_depth;
  light.shadow_matrix = cascade.shadow_matrix;
  return light;
}

// The nearest cascade whose map holds the point at least CASCADE_EDGE_UV inside its edge (any
// point of the last), faded into the next over CASCADE_BLEND_UV beyond that. What a fading
// cascade leaves goes to the next that holds the point; where none does, the shade is what the
// cascades that did hold it give. Lit where none holds it. A do-while, so that a CPU driver runs
// no masked kernel after the last cascade a lane needs (shadow_2d_pcf; the default scene's sun
// took 74 ms against 87 on lavapipe, 2026-12-03).
float shadow_cascades(Light light, vec3 world_pos, vec3 normal, float bias, uint algorithm, uint types) {
  uint count = uint(light.shape.y);
  float shade = 0.0;
  float owed = 1.0;  // the share of the shade not yet taken from a cascade
  uint k = 0u;
  do {
    Light cascade = cascade_of(light, k);
    MapPoint point;
    if (cascade.info.w == NO_SHADOW_MAP) continue;
    if (!project_to_map(cascade, world_pos, normal, types, point)) continue;
    vec2 to_edge = min(point.uv, 1.0 - point.uv);
    float inside = min(to_edge.x, to_edge.y) - CASCADE_EDGE_UV;
    bool last = k + 1u == count;
    if (inside < 0.0 && !last) continue;
    float share = last ? 1.0 : min(inside / CASCADE_BLEND_UV, 1.0);
    shade += owed * share * shadow_2d_at(cascade, point, bias, algorithm);
    owed *= 1.0 - share;
  } while (++k < count && owed > 0.0);
  return owed < 1.0 ? shade / (1.0 - owed) : 0.0;
}

// ---- cube maps (point lights) ----

// The uv offset of cube face `face`'s tile in the atlas layer (light_record.glsl: two faces a
// column of shadow_matrix). Chosen with selects, not shadow_matrix[face >> 1]: llvmpipe indexes
// a local array with a per-lane index through memory, which cost a sixth of the cube pcss pass.
vec2 cube_face_origin(Light light, int face) {
  vec4 pair = face < 2 ? light.shadow_matrix[0] : (face < 4 ? light.shadow_matrix[1] : light.shadow_matrix[2]);
  return (face & 1) == 0 ? pair.xy : pair.zw;
}

// Stored distance / far in direction `direction` from the light: its face's tile of the atlas
// (light_record.glsl), held half a texel inside the tile like atlas_coord. Every kernel tap
// selects its own face, so kernels straddling a cube edge read the neighbouring face's texels.
float fetch_cube_depth(Light light, vec3 direction) {
  vec3 face_uv = cube_face_uv(direction);
  vec2 origin = cube_face_origin(light, int(face_uv.z));
  float half_texel = 0.5 * light.shadow_depth.z;
  vec2 inside = clamp(face_uv.xy, vec2(half_texel), vec2(1.0 - half_texel));
  return textureLod(shadow_atlas, vec3(origin + inside * light.shadow_rect.zw, float(light.info.w)), 0.0).r;
}

float cube_occluded(Light light, vec3 direction, float reference) {
  return reference > fetch_cube_depth(light, direction) ? 1.0 : 0.0;
}

// Where a wide kernel looks past the fragment, a flat receiver lies nearer or farther than the
// fragment itself, most at grazing angles, and comparing with the fragment's own distance would
// shadow the receiver with itself (acne spreading across lit floors). So each sample is compared
// with the distance, in its own direction, of the receiver's tangent plane (receiver-plane depth
// bias), held within half and twice the fragment's distance where the plane runs off.
struct CubeReceiver {
  vec3 to_fragment;  // fragWorld - P
  float distance;    // its length
  vec3 normal;       // the receiver's unit normal
  float along;       // dot(normal, to_fragment)
  float bias;        // the light's bias, in distance / far
  float far;
};

// Whether the receiver's tangent plane, in `direction` from the light, lies farther than
// `stored` (a fetched distance / far) plus the bias: whether the texel occludes it. The plane's
// distance in that direction is along * |direction| / dot(normal, direction) where that is
// positive (the fragment's own distance otherwise), held within half and twice the fragment's;
// compared squared, so a tap costs no square root and no division.
bool cube_plane_beyond(CubeReceiver r, vec3 direction, float stored) {
  float limit = (stored + r.bias) * r.far;  // the distance to exceed
  float facing = dot(r.normal, direction);
  bool planar_beyond = r.along * facing > 0.0
                           ? limit <= 0.0 || r.along * r.along * dot(direction, direction) > limit * limit * facing * facing
                           : r.distance > limit;
  return 2.0 * r.distance > limit && (0.5 * r.distance > limit || planar_beyond);
}

float cube_sample(Light light, CubeReceiver r, vec3 offset) {
  vec3 direction = r.to_fragment + offset;
  return cube_plane_beyond(r, direction, fetch_cube_depth(light, direction)) ? 1.0 : 0.0;
}

// PCSS's k-th kernel offset, optionally rotated (pcss_noise). Section 4's directions have
// lengths sqrt(2) and sqrt(3), which as they are would spread the kernel across fragToLight
// about 1.8 times as far as shadow_2d_pcss's Poisson disk of the same radius, and so draw
// penumbrae about twice as wide as a spot light's (measured against the ray-traced reference,
// docs/QUALITY.md). Scaled to length sqrt(3)/2 they spread as far as a uniform unit disk (RMS
// distance from the axis sqrt(1/2): a unit vector's is sqrt(2/3) on average over directions).
vec3 cube_pcss_offset(uint k, bool jitter, vec4 rotation) {
  vec3 offset = cube_offset(k) * (k < 8u ? 0.5 : 0.61237244);  // sqrt(3)/2 / |offset|
  return jitter ? rotate(rotation, offset) : offset;
}

// The seed of the cube texel in the receiver's direction (map_texel_seed).
uvec3 cube_point_seed(Light light, CubeReceiver r) {
  vec3 face_uv = cube_face_uv(r.to_fragment);
  return map_texel_seed(cube_face_origin(light, int(face_uv.z)), light.info.w, face_uv.xy, light.shadow_depth.z);
}

// PCSS on a cube map with shadow_2d_pcss's radii, in world units directly: an offset moves the
// lookup direction by its part perpendicular to fragToLight (the part along it only changes the
// length, which a cube lookup ignores), so radii act at the receiver's distance.
float shadow_cube_pcss(Light light, CubeReceiver r, bool jitter) {
  float far = light.shadow_depth.y;
  float light_size = light.shadow_bias.w;
  vec4 rotation = jitter ? random_rotation_3d(cube_point_seed(light, r)) : vec4(0.0, 0.0, 0.0, 1.0);
  float texel_world = cube_texel_world_size(r.distance, light.shadow_depth.z);

  // Over two texels or less the eight corners read what the twenty do (search_taps_by_footprint).
  // The light's own count: the corners alone below a full 2D search.
  uint search_taps = light_size <= 2.0 * texel_world || pcss_blocker_taps(light) < PCSS_BLOCKER_SAMPLES
                         ? CUBE_CORNER_COUNT
                         : CUBE_OFFSET_COUNT;
  float blocker_sum = 0.0;
  float blockers = 0.0;
  [[unroll]] for (uint k = 0u; k < CUBE_OFFSET_COUNT; ++k) {
    if (k >= search_taps) break;
    vec3 direction = r.to_fragment + cube_pcss_offset(k, jitter, rotation) * light_size;
    float depth = fetch_cube_depth(light, direction);
    if (cube_plane_beyond(r, direction, depth)) {
      blocker_sum += depth;
      blockers += 1.0;
    }
  }

  // No blockers means lit. A CPU driver runs a loop until none of its SIMD lanes continues, and
  // the body of an `if` always (masked): so the filter is a loop of no taps where no blocker was
  // found, which spares lit areas all but one masked tap (a sixth of the default scene's cube pcss
  // pass on lavapipe). As a do-while with the taps masked inside, it ran no faster there and 2%
  // slower on the H200 (1,024 and 100,000 lights, 2026-12-03).
  float blocker = blocker_sum / max(blockers, 1.0) * far;
  float width = pcss_penumbra_width(r.distance, blocker, light_size);
  float radius = max(0.5 * width, texel_world);
  float sum = 0.0;
  uint kernel = pcss_filter_taps(light) < CUBE_OFFSET_COUNT ? CUBE_CORNER_COUNT : CUBE_OFFSET_COUNT;
  uint taps = blockers > 0.0 ? kernel : 0u;
  [[dont_unroll]] for (uint k = 0u; k < taps; ++k) {
    sum += cube_sample(light, r, cube_pcss_offset(k, jitter, rotation) * radius);
  }
  return sum / float(kernel);
}

float shadow_cube(Light light, vec3 world_pos, vec3 normal, float bias, uint algorithm) {
  CubeReceiver r;
  // From where the cube was rendered, which lags the light while its map is cached.
  r.to_fragment = world_pos - light.shadow_matrix[3].xyz;
  r.distance = length(r.to_fragment);
  r.normal = normal;
  r.along = dot(normal, r.to_fragment);
  r.far = light.shadow_depth.y;
  // A texel holds the distance in the direction of its centre: across one texel a tilted
  // receiver's distance changes by the texel's width times tan(angle of incidence), which is
  // added to the light's bias (held at 10 texels for grazing receivers, which are barely lit).
  float n_dot_l = max(dot(normal, -r.to_fragment / max(r.distance, 1e-6)), 0.0);
  float tan_incidence = min(sqrt(max(1.0 - n_dot_l * n_dot_l, 0.0)) / max(n_dot_l, 1e-3), 10.0);
  float texel_world = cube_texel_world_size(r.distance, light.shadow_depth.z);
  r.bias = bias + texel_world * tan_incidence / light.shadow_depth.y;
  float depth = r.distance / light.shadow_depth.y;
  if (depth > 1.0) return 0.0;
  if (algorithm == SHADOW_HARD) return cube_occluded(light, r.to_fragment, depth - r.bias);

  // pcfRadius texels, measured where fragToLight meets its cube face.
  float radius = light.shadow_bias.z * texel_world;
  if (algorithm == SHADOW_PCF) {
    float sum = 0.0;
    [[unroll]] for (uint k = 0u; k < CUBE_OFFSET_COUNT; ++k) sum += cube_sample(light, r, cube_offset(k) * radius);
    return sum / float(CUBE_OFFSET_COUNT);
  }
  if (algorithm == SHADOW_NOISE) {
    // GAUSSIAN_BALL turned by a random rotation per cube texel, as shadow_2d_noise does in 2D.
    vec4 rotation = random_rotation_3d(cube_point_seed(light, r));
    uint stride = noise_tap_stride(light);
    float sum = 0.0;
    [[unroll]] for (uint i = 0u; i < NOISE_SAMPLES; ++i) {
      if (i % stride != 0u) continue;
      sum += cube_sample(light, r, rotate(rotation, GAUSSIAN_BALL[i]) * radius);
    }
    return sum * float(stride) / float(NOISE_SAMPLES);
  }
  return shadow_cube_pcss(light, r, algorithm == SHADOW_PCSS_NOISE);
}

// ---- entry points ----

// The shadow code `light` runs (light_groups.glsl).
uint light_shadow_kind(Light light) {
  if (light.info.w == NO_SHADOW_MAP) return SHADOW_KIND_NONE;
  return light.info.x == LIGHT_POINT ? SHADOW_KIND_CUBE : SHADOW_KIND_MAP;
}

// `light`'s shadow factor at world_pos; `normal` is the receiver's unit normal and n_dot_l is
// dot(N, L) for the slope-scaled bias. `shadow_kind` and `algorithm` must be the light's own
// (light_shadow_kind, info.z), and `types` (LIGHT_TYPES' bits) must hold its type: passed in,
// they can be compile-time constants, which leaves only that algorithm's and those types' code
// in the shader.
float light_shadow_as(Light light, vec3 world_pos, vec3 normal, float n_dot_l, uint shadow_kind,
                      uint algorithm, uint types) {
  if (shadow_kind == SHADOW_KIND_NONE) return 0.0;
  float bias = shadow_bias(n_dot_l, light.shadow_bias.x, light.shadow_bias.y);
  if (shadow_kind == SHADOW_KIND_CUBE) return shadow_cube(light, world_pos, normal, bias, algorithm);
  // Lights whose only 2D maps are cascades hold no single-map lookup: on the default scene's sun,
  // 68 ms against 74 on lavapipe (2026-12-03). Point lights have cubes, never 2D maps.
  const uint cascaded = 1u << CASCADED_TYPE_BIT;
  const uint other_maps = ~(cascaded | (1u << LIGHT_POINT));
  if ((types & cascaded) != 0u && ((types & other_maps) == 0u || light.info.w == CASCADED_SHADOW_MAPS)) {
    return shadow_cascades(light, world_pos, normal, bias, algorithm, types);
  }
  return shadow_2d(light, world_pos, normal, bias, algorithm, types);
}

#endif
