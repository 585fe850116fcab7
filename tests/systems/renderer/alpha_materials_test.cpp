// SPDX-License-Identifier: MIT
// glTF's alphaMode and doubleSided on lavapipe, under validation: a masked card shows, and
// casts, the shape of its texture's alpha, on every lighting path and every way of drawing
// shadow views; a transparent pane casts a partial shadow, and never shuts in a light inside it;
// a double-sided card shows its back face, lit from its side.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "ecs/transform_system.h"
#include "rendergraph/device/frame_ring.h"
#include "rendergraph/device/readback.h"
#include "systems/frame/frame.h"
#include "systems/gpu/camera.h"
#include "systems/scene/lights.h"
#include "systems/scene/primitive_meshes.h"
#include "systems/scene/scene_builder.h"
#include "tests/support/gpu_test.h"

namespace sg::test {
namespace {

constexpr uint32_t width = 96;
constexpr uint32_t height = 96;

constexpr LightingPath every_path[] = {LightingPath::deferred, LightingPath::fused,
                                       LightingPath::every_light};

// The ways shadow views are drawn, each with its own cut-out shaders.
struct ShadowPath {
  const char* name;
  shadows::ShadowViewPath views;
  shadows::ShadowRaster raster;
};
constexpr ShadowPath every_shadow_path[] = {
    {"batched, hardware raster", shadows::ShadowViewPath::batched, shadows::ShadowRaster::hardware},
    {"batched, compute raster", shadows::ShadowViewPath::batched, shadows::ShadowRaster::compute},
    {"per light", shadows::ShadowViewPath::per_light, shadows::ShadowRaster::hardware}};

scene::Material matte(glm::vec4 color) {
  scene::Material m;
  m.base_color = color;
  m.specular = 0.0f;
  return m;
}

// A texture of `columns` texels in a row, opaque red on the left half, fully transparent red on
// the right.
scene::Texture half_transparent(uint32_t columns) {
  scene::Texture texture{"half", columns, 1, std::vector<uint8_t>(size_t{columns} * 4, 0)};
  for (uint32_t x = 0; x < columns; ++x) {
    texture.pixels[x * 4] = 255;
    texture.pixels[x * 4 + 3] = x < columns / 2 ? 255 : 0;
  }
  return texture;
}

// A scene whose meshes are a unit box (box_mesh) and a unit quad facing up (quad_mesh), with a
// 20 x 20 m floor of `floor_color`, its top at y = 0.
constexpr uint32_t box_mesh = 0;
constexpr uint32_t quad_mesh = 1;
SceneView floor_scene(const char* name, glm::vec4 floor_color) {
  SceneView scene;
  scene.scene.name = name;
  scene::add_box_mesh(scene.scene.meshes);
  scene::add_quad_mesh(scene.scene.meshes);
  scene::add_instance(scene.scene, box_mesh,
                      {{0.0f, -0.5f, 0.0f}, glm::quat(1, 0, 0, 0), {20.0f, 1.0f, 20.0f}}, matte(floor_color));
  return scene;
}

// A 2 x 2 m pane of alpha 0.5 facing up, 1 m above the origin, of `scene`'s mesh `quad`.
void add_glass_pane(SceneView& scene, uint32_t quad) {
  scene::Material glass = matte({0.9f, 0.9f, 0.9f, 0.5f});
  glass.alpha_mode = scene::AlphaMode::blend;
  scene::add_instance(scene.scene, quad, {{0.0f, 1.0f, 0.0f}, glm::quat(1, 0, 0, 0), {2.0f, 1.0f, 2.0f}},
                      glass);
}

scene::ShadowSettings unshadowed() {
  scene::ShadowSettings shadow;
  shadow.casts_shadow = false;
  return shadow;
}

class AlphaMaterials : public GpuTest {
 protected:
  // One frame of `scene` on `lighting`, its shadow views drawn by `shadow_path`.
  vk::Rgba8Image render(SceneView& scene, LightingPath lighting,
                        const ShadowPath& shadow_path = every_shadow_path[0]) {
    FrameSettings options;
    options.renderer.lighting = lighting;
    options.renderer.shadow_views = shadow_path.views;
    options.renderer.shadow_raster = shadow_path.raster;
    options.animate = false;
    vk::FrameRing frames(context);
    Frame frame(context, scene, options, frames.frames_in_flight());
    frame.resize({width, height});
    frame.record(frames.begin_frame(), 0.0);
    frames.submit();
    frames.wait_idle();
    return vk::read_rgba8(context, frame.image());
  }

  // The linear color where `scene`'s camera sees world point `p`.
  static glm::vec3 seen(const vk::Rgba8Image& image, const SceneView& scene, glm::vec3 p) {
    const glm::vec4 clip =
        projection_matrix(scene.lens, float(width) / height) * view_matrix(scene.pose) * glm::vec4(p, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    const uint8_t* pixel =
        image.at(uint32_t((ndc.x * 0.5f + 0.5f) * width), uint32_t((ndc.y * 0.5f + 0.5f) * height));
    return {vk::srgb_to_linear(pixel[0]), vk::srgb_to_linear(pixel[1]), vk::srgb_to_linear(pixel[2])};
  }

  // The mean linear color over a horizontal 0.4 m square around `centre`.
  static glm::vec3 mean_seen(const vk::Rgba8Image& image, const SceneView& scene, glm::vec3 centre) {
    glm::vec3 sum(0.0f);
    for (int i = -2; i <= 2; ++i) {
      for (int k = -2; k <= 2; ++k) sum += seen(image, scene, centre + glm::vec3(0.1f * i, 0.0f, 0.1f * k));
    }
    return sum / 25.0f;
  }
};

// A 4 x 4 m red card 1 m above a green floor, its left half opaque and its right half cut out
// (alphaMode MASK), seen from straight above: through the hole the floor shows. Lit by a sun
// slanting towards +X, or by a point light (a cube shadow) up and to the left, the floor lies in
// the opaque half's shadow next to the hole's left edge and is lit a metre on, where a solid card
// would shade it too.
TEST_F(AlphaMaterials, AMaskedCardShowsAndCastsItsTexturesShape) {
  const auto masked_card = [](bool point_light) {
    SceneView scene = floor_scene("masked card", {0.1f, 0.8f, 0.1f, 1.0f});
    scene.scene.textures.textures.push_back(half_transparent(8));
    scene::Material card = matte(glm::vec4(1.0f));
    card.base_color_texture = 0;
    card.alpha_mode = scene::AlphaMode::mask;
    scene::add_instance(scene.scene, quad_mesh,
                        {{0.0f, 1.0f, 0.0f}, glm::quat(1, 0, 0, 0), {4.0f, 1.0f, 4.0f}}, card);
    scene::ShadowSettings hard;
    hard.algorithm = scene::ShadowAlgorithm::hard;
    hard.resolution = 512;  // the compute raster's largest on a CPU device
    if (point_light) {
      // From (-1.2, 2.5, 0) the card's opaque edge at x = 0 shades the floor up to x = 1.9.
      scene::add_light(scene.scene, scene::PointLight{glm::vec3(1.0f), 4.0f, 20.0f},
                       {glm::vec3(-1.2f, 2.5f, 0.0f), glm::quat(1, 0, 0, 0), glm::vec3(1.0f)}, hard, "bulb");
    } else {
      scene::add_light(
          scene.scene, scene::DirectionalLight{glm::vec3(1.0f), 0.8f},
          {glm::vec3(0.0f, 5.0f, 0.0f), scene::look_rotation({0, 5, 0}, {1, 4, 0}), glm::vec3(1.0f)}, hard,
          "sun");
    }
    ecs::update_world_transforms(scene.scene.world, 0);
    scene.pose = {{0.0f, 8.0f, 0.01f}, {0.0f, 0.0f, 0.0f}};
    return scene;
  };
  const auto check = [&](SceneView& scene, LightingPath lighting, const ShadowPath& shadow_path,
                         float lit_x) {
    const vk::Rgba8Image image = render(scene, lighting, shadow_path);
    const glm::vec3 opaque = seen(image, scene, {-1.0f, 1.0f, 0.0f});
    const glm::vec3 shadowed = seen(image, scene, {0.4f, 0.0f, 0.0f});
    const glm::vec3 lit = seen(image, scene, {lit_x, 0.0f, 0.0f});
    EXPECT_GT(opaque.r, 4.0f * opaque.g) << "the card's opaque half is red";
    EXPECT_GT(shadowed.g, 4.0f * shadowed.r) << "the green floor shows through the hole";
    EXPECT_GT(lit.g, 4.0f * lit.r) << "the green floor shows through the hole";
    EXPECT_GT(lit.g, 2.0f * shadowed.g)
        << "the floor is lit through the hole, in the opaque half's shadow beside";
  };
  SceneView sun = masked_card(false);
  for (const LightingPath path : every_path) {
    SCOPED_TRACE(std::string(to_string(path)));
    check(sun, path, every_shadow_path[0], 1.6f);
  }
  SceneView bulb = masked_card(true);
  for (const ShadowPath& shadow_path : every_shadow_path) {
    SCOPED_TRACE(shadow_path.name);
    check(sun, LightingPath::deferred, shadow_path, 1.6f);
    check(bulb, LightingPath::deferred, shadow_path, 2.4f);
  }
}

// A blue pane of alpha 0.5 (alphaMode BLEND) and an opaque card like it, 1 m above a grey floor,
// under a sun slanting towards +X with PCF: seen through the pane, the floor is half the floor's
// color and half the card's, on every lighting path; the floor in the pane's shadow (seen
// beside the pane) gets about half of what the card takes away, on every way of drawing shadow
// views.
TEST_F(AlphaMaterials, ATransparentPaneTintsWhatIsBehindAndCastsAPartialShadow) {
  SceneView scene = floor_scene("pane", glm::vec4(0.5f, 0.5f, 0.5f, 1.0f));
  scene::Material glass = matte({0.2f, 0.2f, 0.9f, 0.5f});
  glass.alpha_mode = scene::AlphaMode::blend;
  scene::add_instance(scene.scene, quad_mesh, {{0.0f, 1.0f, 0.0f}, glm::quat(1, 0, 0, 0), {2.0f, 1.0f, 2.0f}},
                      glass);
  scene::add_instance(scene.scene, quad_mesh,
                      {{0.0f, 1.0f, -4.0f}, glm::quat(1, 0, 0, 0), {2.0f, 1.0f, 2.0f}},
                      matte(glm::vec4(0.2f, 0.2f, 0.9f, 1.0f)));
  scene::ShadowSettings pcf;
  pcf.algorithm = scene::ShadowAlgorithm::pcf;
  pcf.resolution = 512;  // the compute raster's largest on a CPU device
  scene::add_light(scene.scene, scene::DirectionalLight{glm::vec3(1.0f), 0.8f},
                   {glm::vec3(0.0f, 5.0f, 0.0f), scene::look_rotation({0, 5, 0}, {1, 4, 0}), glm::vec3(1.0f)},
                   pcf, "sun");
  ecs::update_world_transforms(scene.scene.world, 0);
  scene.pose = {{0.0f, 9.0f, 0.01f}, {0.0f, 0.0f, -2.0f}};
  for (const LightingPath path : every_path) {
    SCOPED_TRACE(std::string(to_string(path)));
    const vk::Rgba8Image image = render(scene, path);
    const glm::vec3 open = mean_seen(image, scene, {3.5f, 0.0f, 0.0f});
    const glm::vec3 card = mean_seen(image, scene, {-0.5f, 1.0f, -4.0f});
    const glm::vec3 through = mean_seen(image, scene, {-0.5f, 1.0f, 0.0f});
    const glm::vec3 expected = 0.5f * card + 0.5f * open;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(through[c], expected[c], 0.03f) << "channel " << c;
  }
  for (const ShadowPath& shadow_path : every_shadow_path) {
    SCOPED_TRACE(shadow_path.name);
    const vk::Rgba8Image image = render(scene, LightingPath::deferred, shadow_path);
    // Each squares' shadows lie 1 m on in +X, at x in [0, 2]; the floor is read around x = 1.5,
    // beyond the squares' edge at x = 1, averaged over a patch as the shadow is dithered.
    const float open = mean_seen(image, scene, {3.5f, 0.0f, 0.0f}).g;
    const float pane = mean_seen(image, scene, {1.5f, 0.0f, 0.0f}).g;
    const float card = mean_seen(image, scene, {1.5f, 0.0f, -4.0f}).g;
    ASSERT_GT(open, card + 0.1f) << "the card casts a shadow";
    EXPECT_NEAR((open - pane) / (open - card), 0.5f, 0.15f) << "the pane takes half the light the card does";
  }
}

// A red pane 2 m up over a blue one 1 m up, both of alpha 0.5, over a grey floor, seen from above:
// blended back to front, the floor shows through both as half the red, a quarter of the blue and
// a quarter of the floor (blue over red would be the other way round), on every lighting path.
TEST_F(AlphaMaterials, OverlappingPanesBlendBackToFront) {
  SceneView scene = floor_scene("panes", glm::vec4(0.5f, 0.5f, 0.5f, 1.0f));
  const glm::vec4 red{0.9f, 0.1f, 0.1f, 0.5f};
  const glm::vec4 blue{0.1f, 0.1f, 0.9f, 0.5f};
  for (const auto& [color, height] : {std::pair{red, 2.0f}, std::pair{blue, 1.0f}}) {
    scene::Material glass = matte(color);
    glass.alpha_mode = scene::AlphaMode::blend;
    scene::add_instance(scene.scene, quad_mesh,
                        {{0.0f, height, 0.0f}, glm::quat(1, 0, 0, 0), {2.0f, 1.0f, 2.0f}}, glass);
    // The same color opaque, as a reference, 4 m off.
    scene::add_instance(scene.scene, quad_mesh,
                        {{4.0f, height, 0.0f}, glm::quat(1, 0, 0, 0), {2.0f, 1.0f, 2.0f}},
                        matte(glm::vec4(glm::vec3(color), 1.0f)));
  }
  scene::add_light(
      scene.scene, scene::DirectionalLight{glm::vec3(1.0f), 0.8f},
      {glm::vec3(0.0f, 5.0f, 0.0f), scene::look_rotation({0, 5, 0}, {0.0f, 4.0f, 0.01f}), glm::vec3(1.0f)},
      unshadowed(), "sun");
  ecs::update_world_transforms(scene.scene.world, 0);
  scene.pose = {{2.0f, 9.0f, 0.01f}, {2.0f, 0.0f, 0.0f}};
  for (const LightingPath path : every_path) {
    SCOPED_TRACE(std::string(to_string(path)));
    const vk::Rgba8Image image = render(scene, path);
    const glm::vec3 floor = mean_seen(image, scene, {-2.0f, 0.0f, 3.0f});
    const glm::vec3 opaque_red = mean_seen(image, scene, {4.0f, 2.0f, 0.0f});  // the red card over the blue
    const glm::vec3 through = mean_seen(image, scene, {0.0f, 2.0f, 0.0f});
    // The blue card's lit color, as the red's with the channels swapped (same light, same height).
    const glm::vec3 opaque_blue(opaque_red.b, opaque_red.g, opaque_red.r);
    const glm::vec3 expected = 0.5f * opaque_red + 0.25f * opaque_blue + 0.25f * floor;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(through[c], expected[c], 0.03f) << "channel " << c;
  }
}

// A pane of alpha 0.5 with nothing behind it, a point light of 3 m range half a metre above it:
// the tiles over the pane have no opaque surface, yet their lights for transparent surfaces
// include the light, on every lighting path.
TEST_F(AlphaMaterials, APaneOverTheBackgroundIsLitByTheLightsNearIt) {
  SceneView scene;
  scene.scene.name = "pane in the dark";
  const uint32_t quad = scene::add_quad_mesh(scene.scene.meshes);
  add_glass_pane(scene, quad);
  scene::add_light(scene.scene, scene::PointLight{glm::vec3(1.0f), 1.0f, 3.0f},
                   {glm::vec3(0.0f, 1.5f, 0.0f), glm::quat(1, 0, 0, 0), glm::vec3(1.0f)}, unshadowed(),
                   "bulb");
  ecs::update_world_transforms(scene.scene.world, 0);
  scene.pose = {{0.0f, 6.0f, 0.01f}, {0.0f, 0.0f, 0.0f}};
  for (const LightingPath path : every_path) {
    SCOPED_TRACE(std::string(to_string(path)));
    const vk::Rgba8Image image = render(scene, path);
    // Lit: about half of 0.9 times the light's 0.8 at that distance; by ambient alone, 0.07.
    EXPECT_GT(mean_seen(image, scene, {0.0f, 1.0f, 0.0f}).g, 0.25f);
  }
}

// A pane of alpha 0.5 1 m up, over a floor 11 m below it, lit by a spot light from the side whose
// cone meets the floor only far beyond the pane: the tiles over the pane hold opaque surfaces at
// the floor's depth alone, yet their lights for transparent surfaces include the spot (the culling
// marks the depths where transparent surfaces may lie). Deferred lighting's transparent pass reads
// the tiles' lists; unlit, the pane's green is 0.10.
TEST_F(AlphaMaterials, APaneFarBeforeTheFloorIsLitByASpotThatMissesTheFloorBehindIt) {
  SceneView scene;
  scene.scene.name = "pane over a deep floor";
  scene::add_box_mesh(scene.scene.meshes);
  const uint32_t quad = scene::add_quad_mesh(scene.scene.meshes);
  scene::add_instance(scene.scene, box_mesh,
                      {{0.0f, -10.5f, 0.0f}, glm::quat(1, 0, 0, 0), {40.0f, 1.0f, 40.0f}},
                      matte({0.5f, 0.5f, 0.5f, 1.0f}));
  add_glass_pane(scene, quad);
  const glm::vec3 spot_at(-1.5f, 2.0f, 0.0f);
  scene::add_light(scene.scene, scene::SpotLight{glm::vec3(1.0f), 2.0f, 4.0f, 0.25f, 0.3f},
                   {spot_at, scene::look_rotation(spot_at, {0.0f, 1.0f, 0.0f}), glm::vec3(1.0f)},
                   unshadowed(), "spot");
  ecs::update_world_transforms(scene.scene.world, 0);
  scene.pose = {{0.0f, 6.0f, 0.01f}, {0.0f, 0.0f, 0.0f}};
  const vk::Rgba8Image image = render(scene, LightingPath::deferred);
  EXPECT_GT(mean_seen(image, scene, {0.0f, 1.0f, 0.0f}).g, 0.25f);
}

// A point light inside a transparent box (alpha 0.9) lights the floor around the box as it does
// without the box: the box casts no shadow of the light it holds.
TEST_F(AlphaMaterials, ATransparentBoxShutsInNoLight) {
  const auto floor_lit = [&](bool boxed, const ShadowPath& shadow_path) {
    SceneView scene = floor_scene("lantern", glm::vec4(0.5f, 0.5f, 0.5f, 1.0f));
    if (boxed) {
      scene::Material glass = matte({0.9f, 0.9f, 0.9f, 0.9f});
      glass.alpha_mode = scene::AlphaMode::blend;
      scene::add_instance(scene.scene, box_mesh, {{0.0f, 1.5f, 0.0f}, glm::quat(1, 0, 0, 0), glm::vec3(1.0f)},
                          glass);
    }
    scene::ShadowSettings shadow;
    shadow.resolution = 512;  // the compute raster's largest on a CPU device
    scene::add_light(scene.scene, scene::PointLight{glm::vec3(1.0f), 3.0f, 20.0f},
                     {glm::vec3(0.0f, 1.5f, 0.0f), glm::quat(1, 0, 0, 0), glm::vec3(1.0f)}, shadow,
                     "lantern");
    ecs::update_world_transforms(scene.scene.world, 0);
    scene.pose = {{0.0f, 9.0f, 0.01f}, {0.0f, 0.0f, 0.0f}};
    const vk::Rgba8Image image = render(scene, LightingPath::deferred, shadow_path);
    return mean_seen(image, scene, {2.5f, 0.0f, 0.0f}).g;
  };
  for (const ShadowPath& shadow_path : every_shadow_path) {
    SCOPED_TRACE(shadow_path.name);
    const float open = floor_lit(false, shadow_path);
    EXPECT_GT(open, 0.1f) << "the light reaches the floor";
    EXPECT_NEAR(floor_lit(true, shadow_path), open, 0.02f) << "the box around the light casts no shadow";
  }
}

// A card 1 m up, facing up, seen from below with a sun shining up at it: single-sided, its back
// face is culled and the background shows; double-sided, the back face shows, lit through its
// flipped normal.
TEST_F(AlphaMaterials, ADoubleSidedCardShowsItsBackFaceLitFromItsSide) {
  const auto card_seen = [&](bool double_sided, LightingPath path) {
    SceneView scene;
    scene.scene.name = "card";
    const uint32_t quad = scene::add_quad_mesh(scene.scene.meshes);
    scene::Material card = matte({0.9f, 0.9f, 0.9f, 1.0f});
    card.double_sided = double_sided;
    scene::add_instance(scene.scene, quad, {{0.0f, 1.0f, 0.0f}, glm::quat(1, 0, 0, 0), {4.0f, 1.0f, 4.0f}},
                        card);
    scene::add_light(
        scene.scene, scene::DirectionalLight{glm::vec3(1.0f), 0.8f},
        {glm::vec3(0.0f, -5.0f, 0.0f), scene::look_rotation({0, -5, 0}, {0.1f, -4, 0}), glm::vec3(1.0f)},
        scene::ShadowSettings{}, "sun below");
    ecs::update_world_transforms(scene.scene.world, 0);
    scene.pose = {{0.0f, -6.0f, 0.01f}, {0.0f, 1.0f, 0.0f}};
    const vk::Rgba8Image image = render(scene, path);
    return seen(image, scene, {0.5f, 1.0f, 0.5f}).g;
  };
  for (const LightingPath path : every_path) {
    SCOPED_TRACE(std::string(to_string(path)));
    EXPECT_NEAR(card_seen(false, path), background_color.g, 0.01f) << "the background";
    EXPECT_GT(card_seen(true, path), 0.4f) << "the lit back face";
  }
}

}  // namespace
}  // namespace sg::test
