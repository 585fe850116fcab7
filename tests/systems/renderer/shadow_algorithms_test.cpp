// SPDX-License-Identifier: MIT
// The five shadow algorithms on lavapipe against a CPU ray-cast reference (issue 6): a floor, a
// box and one light (tests/support/floor_box_scene.h); every render goes through the sandbox's frame graph
// with validation and synchronization validation on.
//
// The shadow factor of each pixel is measured, not guessed from colors: the scene is rendered
// with shadows (S), without (U) and with the light off (D), and in linear light
// shade = (U - S) / (U - D), which is the `shade` of docs/ALGORITHMS.md section 2 for a black shadow
// color and density 1 (the floor has no specular term, so the (1 - shade) * S term vanishes).
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "ecs/query.h"
#include "ecs/transform_system.h"
#include "rendergraph/device/frame_ring.h"
#include "rendergraph/device/readback.h"
#include "systems/frame/frame.h"
#include "systems/scene/lights.h"
#include "systems/scene/mesh_instance.h"
#include "systems/scene/primitive_meshes.h"
#include "systems/scene/scene_builder.h"
#include "systems/shadows/cascades.h"
#include "tests/support/floor_box_scene.h"
#include "tests/support/gpu_test.h"
#include "tests/support/shadow_reference.h"

namespace sg::test {
namespace {

constexpr uint32_t width = 160;
constexpr uint32_t height = 120;
// Pixels where the light adds less than this (linear) to the floor are not measured.
constexpr float min_light = 0.08f;

ecs::LocalTransform downward_light(glm::vec3 position) {
  return aimed_light(position, glm::vec3(0.0f, -1.0f, 0.001f));
}

CameraImage camera() { return floor_camera({width, height}); }

SceneView sandbox_scene(scene::Scene scene) {
  SceneView out{std::move(scene), camera().pose, camera().lens, "test"};
  return out;
}

SceneView build(const ShadowScene& s, float intensity) {
  return sandbox_scene(build_shadow_scene(s, intensity));
}

class ShadowAlgorithms : public GpuTest {
 protected:
  // Linear green channel of the last of `frames` frames.
  std::vector<float> render(const ShadowScene& s, float intensity, bool shadows, uint32_t frames = 1,
                            std::vector<uint8_t>* first_frame = nullptr) {
    SceneView scene = build(s, intensity);
    FrameSettings options;
    options.renderer.lights.shadows = shadows;
    return render(scene, options, frames, first_frame);
  }

  std::vector<float> render(SceneView& scene, const FrameSettings& options, uint32_t frames = 1,
                            std::vector<uint8_t>* first_frame = nullptr) {
    vk::FrameRing ring(context);
    Frame frame(context, scene, options, ring.frames_in_flight());
    frame.resize({width, height});
    std::vector<float> out(size_t{width} * height);
    for (uint32_t i = 0; i < frames; ++i) {
      vk::FrameSlot& slot = ring.begin_frame();
      frame.record(slot, 0.0);
      ring.submit();
      ring.wait_idle();
      if (i == 0 && first_frame) *first_frame = vk::read_rgba8(context, frame.image()).pixels;
    }
    const vk::Rgba8Image image = vk::read_rgba8(context, frame.image());
    last_pixels = image.pixels;
    last_cascades = frame.renderer().shadow_stats().cascades;
    last_lighting = frame.renderer().lighting();
    last_contact_skipped = frame.renderer().contact_shadows_skipped();
    for (uint32_t y = 0; y < height; ++y) {
      for (uint32_t x = 0; x < width; ++x) out[size_t{y} * width + x] = vk::srgb_to_linear(image.at(x, y)[1]);
    }
    return out;
  }

  // Measured shade per pixel; nullopt where the light barely reaches. The renders without
  // shadows and with the light off are kept for later calls on a scene whose shadow alone
  // differs: tests that measure every algorithm over one scene made three renderers each (thirty
  // in the slowest, 69 s on lavapipe, 2026-12-04).
  std::vector<std::optional<float>> shade(const ShadowScene& s) {
    const ShadowScene lit = unshadowed_scene(s);
    auto kept = std::find_if(unshadowed_.begin(), unshadowed_.end(),
                             [&](const Unshadowed& u) { return u.scene == lit; });
    if (kept == unshadowed_.end()) {
      unshadowed_.push_back({lit, render(s, s.intensity, false), render(s, 0.0f, false)});
      kept = unshadowed_.end() - 1;
    }
    return shade_of(render(s, s.intensity, true), kept->lit, kept->dark);
  }

  // `s` with what only shapes a drawn shadow (algorithm, kernel, biases, resolution, ...) left
  // at the defaults: what a render without shadows sees of it.
  static ShadowScene unshadowed_scene(ShadowScene s) {
    const scene::ShadowSettings shadow = s.shadow;
    s.shadow = {};
    s.shadow.light_mask = shadow.light_mask;
    s.shadow.contact_length = shadow.contact_length;
    s.shadow.casts_shadow = shadow.casts_shadow;
    return s;
  }

  // The same from the three renders: with shadows, without, and with the light off.
  static std::vector<std::optional<float>> shade_of(const std::vector<float>& shadowed,
                                                    const std::vector<float>& unshadowed,
                                                    const std::vector<float>& dark) {
    std::vector<std::optional<float>> out(shadowed.size());
    for (size_t i = 0; i < out.size(); ++i) {
      const float light = unshadowed[i] - dark[i];
      if (light >= min_light) out[i] = std::clamp((unshadowed[i] - shadowed[i]) / light, 0.0f, 1.0f);
    }
    return out;
  }

  FloorPixels reference(const ShadowScene& s, int band) { return floor_reference(s, {width, height}, band); }

  struct Unshadowed {
    ShadowScene scene;  // unshadowed_scene's
    std::vector<float> lit;
    std::vector<float> dark;
  };
  std::vector<Unshadowed> unshadowed_;  // shade's, a few a test
  std::vector<uint8_t> last_pixels;
  uint32_t last_cascades = 0;  // the directional cascades of the last render's last frame
  LightingPath last_lighting = LightingPath::automatic;
  uint32_t last_contact_skipped = 0;
};

struct Classification {
  int measured = 0;                   // floor pixels outside the band with a measurement
  int misclassified = 0;              // measured shade on the other side of 0.5 from the reference
  int shadowed = 0;                   // reference says shadowed
  int intermediate_outside_band = 0;  // 0.1 < shade < 0.9 away from the edge
  int intermediate = 0;               // anywhere
  int lit_but_darkened = 0;           // reference lit, shade > 0.1 (acne)
};

Classification classify(const std::vector<std::optional<float>>& shade, const FloorPixels& reference) {
  Classification c;
  for (size_t i = 0; i < shade.size(); ++i) {
    if (!shade[i]) continue;
    const float value = *shade[i];
    const bool intermediate = value > 0.1f && value < 0.9f;
    c.intermediate += intermediate;
    const FloorPixel expected = reference.pixels[i];
    if (expected != FloorPixel::lit && expected != FloorPixel::shadowed) continue;
    ++c.measured;
    c.shadowed += expected == FloorPixel::shadowed;
    c.misclassified += (value > 0.5f) != (expected == FloorPixel::shadowed);
    c.intermediate_outside_band += intermediate;
    c.lit_but_darkened += expected == FloorPixel::lit && value > 0.1f;
  }
  return c;
}

ShadowScene with(LightKind kind, scene::ShadowAlgorithm algorithm, uint32_t resolution = 1024) {
  ShadowScene s;
  s.kind = kind;
  s.shadow.algorithm = algorithm;
  s.shadow.resolution = resolution;
  return s;
}

// A floor that receives no shadow (MeshInstance::receives_shadow, glTF's receiveShadows) is lit as
// if the box cast none, on the fused forward path a CPU device takes and on the deferred one;
// the box still casts: where the reference puts the floor in shadow the normal frame is darker.
TEST_F(ShadowAlgorithms, AFloorThatReceivesNoShadowIsLitAsWithoutShadows) {
  const ShadowScene s = with(LightKind::spot, scene::ShadowAlgorithm::pcf);
  const FloorPixels floor = reference(s, 1);
  for (const LightingPath path : {LightingPath::automatic, LightingPath::deferred}) {
    const auto render_floor = [&](bool floor_receives, bool shadows) {
      SceneView view = build(s, s.intensity);
      // The floor is the scene's first instance (floor_box_scene.h), the box the second.
      bool first = true;
      view.scene.world.query<scene::MeshInstance>().for_each([&](ecs::Entity, scene::MeshInstance& instance) {
        if (first) instance.receives_shadow = floor_receives;
        first = false;
      });
      FrameSettings options;
      options.renderer.lighting = path;
      options.renderer.lights.shadows = shadows;
      return render(view, options);
    };
    const std::vector<float> not_receiving = render_floor(false, true);
    const std::vector<float> unshadowed = render_floor(true, false);
    const std::vector<float> normal = render_floor(true, true);
    int shadowed = 0, darker = 0, differing = 0;
    for (size_t i = 0; i < floor.pixels.size(); ++i) {
      if (floor.pixels[i] != FloorPixel::shadowed) continue;
      ++shadowed;
      darker += normal[i] < unshadowed[i] - 0.05f ? 1 : 0;
      differing += std::abs(not_receiving[i] - unshadowed[i]) > 1.0f / 255.0f ? 1 : 0;
    }
    ASSERT_GT(shadowed, 100);
    EXPECT_GT(darker, shadowed * 9 / 10) << "the box shadows a receiving floor";
    EXPECT_EQ(differing, 0) << "a floor that receives no shadow is lit where the box would shadow it";
  }
}

// Layers (systems/scene/layers.h): the floor on layer 1, the box on layer 2. A light lights only
// the surfaces its light mask names, on every lighting path, and only the casters its caster mask
// names shadow it, on both shadow view paths, for maps and cubes.
class ShadowLayers : public ShadowAlgorithms {
 protected:
  static constexpr scene::LayerMask floor_layer = 0x02, box_layer = 0x04;

  std::vector<float> render_layers(ShadowScene s, float intensity, const FrameSettings& options) {
    SceneView view = build(s, intensity);
    bool first = true;  // the floor is the scene's first instance (floor_box_scene.h), the box the second
    view.scene.world.query<scene::MeshInstance>().for_each([&](ecs::Entity, scene::MeshInstance& instance) {
      instance.light_layers = instance.shadow_layers = first ? floor_layer : box_layer;
      first = false;
    });
    return render(view, options);
  }
};

TEST_F(ShadowLayers, ALightLightsOnlyTheSurfacesOnItsLightMask) {
  ShadowScene s = with(LightKind::spot, scene::ShadowAlgorithm::pcf);
  const FloorPixels floor = reference(s, 1);
  for (const LightingPath path :
       {LightingPath::automatic, LightingPath::deferred, LightingPath::every_light}) {
    FrameSettings options;
    options.renderer.lighting = path;
    const std::vector<float> dark = render_layers(s, 0.0f, options);
    s.shadow.light_mask = floor_layer | box_layer;
    const std::vector<float> lit = render_layers(s, s.intensity, options);
    s.shadow.light_mask = box_layer;
    const std::vector<float> box_only = render_layers(s, s.intensity, options);
    int floor_pixels = 0, lit_floor = 0, unlit_floor = 0, lit_elsewhere = 0;
    for (size_t i = 0; i < floor.pixels.size(); ++i) {
      if (floor.pixels[i] == FloorPixel::not_floor) {
        lit_elsewhere += box_only[i] > dark[i] + 0.05f;
        continue;
      }
      ++floor_pixels;
      lit_floor += floor.pixels[i] == FloorPixel::lit && lit[i] > dark[i] + 0.05f;
      unlit_floor += std::abs(box_only[i] - dark[i]) <= 1.0f / 255.0f;
    }
    const std::string name(to_string(path));
    ASSERT_GT(floor_pixels, 2000) << name;
    EXPECT_GT(lit_floor, floor_pixels / 3) << name << ": a mask naming the floor's layer lights it";
    EXPECT_EQ(unlit_floor, floor_pixels) << name << ": a mask without the floor's layer leaves it dark";
    EXPECT_GT(lit_elsewhere, 20) << name << ": the box, on the mask's layer, is lit";
  }
}

TEST_F(ShadowLayers, OnlyCastersOnItsCasterMaskShadowALight) {
  for (const LightKind kind : {LightKind::spot, LightKind::point}) {
    for (const shadows::ShadowViewPath views :
         {shadows::ShadowViewPath::batched, shadows::ShadowViewPath::per_light}) {
      ShadowScene s = with(kind, scene::ShadowAlgorithm::pcf);
      if (kind == LightKind::point) s.light_position = {-2.5f, 4.0f, -1.5f};
      const FloorPixels floor = reference(s, 1);
      FrameSettings options;
      options.renderer.shadow_views = views;
      options.renderer.lights.shadows = false;
      const std::vector<float> unshadowed = render_layers(s, s.intensity, options);
      options.renderer.lights.shadows = true;
      s.shadow.caster_mask = floor_layer;
      const std::vector<float> floor_casts = render_layers(s, s.intensity, options);
      s.shadow.caster_mask = box_layer;
      const std::vector<float> box_casts = render_layers(s, s.intensity, options);
      int shadowed = 0, darker = 0, differing = 0;
      for (size_t i = 0; i < floor.pixels.size(); ++i) {
        if (floor.pixels[i] != FloorPixel::shadowed) continue;
        ++shadowed;
        darker += box_casts[i] < unshadowed[i] - 0.05f;
        differing += std::abs(floor_casts[i] - unshadowed[i]) > 1.0f / 255.0f;
      }
      const std::string name =
          std::string(kind == LightKind::spot ? "spot, " : "point, ") + std::string(to_string(views));
      ASSERT_GT(shadowed, 100) << name;
      EXPECT_GT(darker, shadowed * 9 / 10) << name << ": the box, on the caster mask's layer, casts";
      EXPECT_EQ(differing, 0) << name << ": the box, off the caster mask's layers, casts nothing";
    }
  }
}

// Contact shadows (shaders/contact_shadows.glsl): a box just above the floor that casts into no
// map still shadows the floor beside it through the depth buffer, within the light's contact
// length, where the ray-cast reference puts the floor in its shadow; the lit floor stays lit.
// A CPU device's automatic lighting takes the deferred path for them; fused lighting draws none
// and says so. A filtering light and a hard one: a hard light's shading skips the ranking that
// decides between kernels, which its contact shadow still reads.
TEST_F(ShadowAlgorithms, ContactShadowsDarkenTheFloorBesideABoxNoMapHolds) {
  for (const scene::ShadowAlgorithm algorithm : {scene::ShadowAlgorithm::pcf, scene::ShadowAlgorithm::hard}) {
    SCOPED_TRACE(std::string(to_string(algorithm)));
    ShadowScene s = with(LightKind::spot, algorithm);
    s.box_bottom = 0.05f;
    s.light_position = {-1.0f, 2.2f, -4.5f};  // low, behind the box: its shadow falls toward the camera
    s.aim = glm::normalize(glm::vec3(0.0f, 0.3f, 0.0f) - s.light_position);
    const FloorPixels floor = reference(s, 1);
    const auto render_contact = [&](float contact_length, LightingPath path) {
      s.shadow.contact_length = contact_length;
      SceneView view = build(s, s.intensity);
      bool first = true;  // the floor is the scene's first instance (floor_box_scene.h), the box the second
      view.scene.world.query<scene::MeshInstance>().for_each([&](ecs::Entity, scene::MeshInstance& instance) {
        if (!first) instance.casts_shadow = false;
        first = false;
      });
      FrameSettings options;
      options.renderer.lighting = path;
      return render(view, options);
    };
    const std::vector<float> without = render_contact(0.0f, LightingPath::automatic);
    EXPECT_EQ(last_lighting, LightingPath::fused) << "one light without contact shadows on lavapipe";
    const std::vector<float> with = render_contact(2.0f, LightingPath::automatic);
    EXPECT_EQ(last_lighting, LightingPath::deferred) << "contact shadows are deferred lighting's";
    EXPECT_EQ(last_contact_skipped, 0u);
    int shadowed = 0, darkened = 0, lit = 0, lit_darkened = 0;
    for (size_t i = 0; i < floor.pixels.size(); ++i) {
      if (floor.pixels[i] == FloorPixel::shadowed) {
        ++shadowed;
        darkened += with[i] < without[i] - 0.05f;
      } else if (floor.pixels[i] == FloorPixel::lit) {
        ++lit;
        lit_darkened += with[i] < without[i] - 0.05f;
      }
    }
    ASSERT_GT(shadowed, 50);
    EXPECT_GT(darkened, shadowed * 8 / 10) << "of " << shadowed << " floor pixels in the box's shadow";
    EXPECT_LE(lit_darkened, lit / 100) << "of " << lit << " lit floor pixels";

    const std::vector<float> fused = render_contact(2.0f, LightingPath::fused);
    EXPECT_EQ(last_contact_skipped, 1u) << "fused lighting draws no contact shadows, and counts the light";
    int differing = 0;
    for (size_t i = 0; i < fused.size(); ++i) differing += std::abs(fused[i] - without[i]) > 1.0f / 255.0f;
    EXPECT_EQ(differing, 0);
  }
}

TEST_F(ShadowAlgorithms, HardSpotShadowMatchesRayCastingAwayFromTheEdge) {
  const ShadowScene s = with(LightKind::spot, scene::ShadowAlgorithm::hard);
  const Classification c = classify(shade(s), reference(s, 2));
  ASSERT_GT(c.measured, 2000);
  ASSERT_GT(c.shadowed, 100) << "the box must cast a visible shadow";
  EXPECT_LE(c.misclassified, c.measured / 100) << c.misclassified << " of " << c.measured;
}

TEST_F(ShadowAlgorithms, HardPointShadowMatchesRayCastingAwayFromTheEdge) {
  ShadowScene s = with(LightKind::point, scene::ShadowAlgorithm::hard);
  s.light_position = {-2.5f, 4.0f, -1.5f};
  const Classification c = classify(shade(s), reference(s, 2));
  ASSERT_GT(c.measured, 2000);
  ASSERT_GT(c.shadowed, 100);
  EXPECT_LE(c.misclassified, c.measured / 100) << c.misclassified << " of " << c.measured;
}

TEST_F(ShadowAlgorithms, FilteredAlgorithmsAreIntermediateOnlyNearTheEdge) {
  for (const scene::ShadowAlgorithm algorithm :
       {scene::ShadowAlgorithm::pcf, scene::ShadowAlgorithm::noise}) {
    for (const LightKind kind : {LightKind::spot, LightKind::point}) {
      SCOPED_TRACE(std::string(to_string(algorithm)) + (kind == LightKind::spot ? " spot" : " point"));
      // A coarse map makes the filter several pixels wide on screen. Cube faces are coarser at
      // the floor's grazing angles, where a 128-texel face would need more than the default
      // bias: they get 512 texels and a wider kernel instead.
      ShadowScene s = with(kind, algorithm, kind == LightKind::spot ? 128 : 512);
      if (kind == LightKind::point) {
        s.light_position = {-2.5f, 4.0f, -1.5f};
        s.shadow.pcf_radius = 4.0f;
      }
      const std::vector<std::optional<float>> measured = shade(s);
      const Classification near_edge = classify(measured, reference(s, 1));
      const Classification wide = classify(measured, reference(s, 5));
      EXPECT_GT(near_edge.intermediate, 20) << "the filter softens the edge";
      EXPECT_LE(wide.intermediate_outside_band, wide.measured / 200);
      EXPECT_LE(wide.misclassified, wide.measured / 100);
    }
  }
}

// Per-light kernel sizes (scene::ShadowKernel): a wider pcf grid spreads a coarse map's edge over
// more pixels (as wide as 3 texels each side against 1); fewer noise or pcss taps change the
// picture but keep the shadow where the reference puts it.
TEST_F(ShadowAlgorithms, KernelSizesFollowTheLight) {
  const auto measured = [&](ShadowScene s) {
    const std::vector<std::optional<float>> shade_of_pixels = shade(s);
    return std::pair{classify(shade_of_pixels, reference(s, 1)), shade_of_pixels};
  };
  ShadowScene pcf = with(LightKind::spot, scene::ShadowAlgorithm::pcf, 128);
  const int narrow = measured(pcf).first.intermediate;
  pcf.shadow.kernel.pcf_half_width = 3;
  const int wide = measured(pcf).first.intermediate;
  EXPECT_GT(wide, narrow * 3 / 2) << "pixels between lit and shadowed: " << narrow << " with 3x3, " << wide
                                  << " with 7x7";
  for (const scene::ShadowAlgorithm algorithm :
       {scene::ShadowAlgorithm::noise, scene::ShadowAlgorithm::pcss}) {
    SCOPED_TRACE(std::string(to_string(algorithm)));
    ShadowScene s = with(LightKind::spot, algorithm, 256);
    const auto full = measured(s).second;
    s.shadow.kernel = {.pcf_half_width = 1, .blocker_taps = 4, .filter_taps = 4, .noise_taps = 4};
    const auto [few, few_shade] = measured(s);
    int differing = 0;
    for (size_t i = 0; i < full.size(); ++i) {
      differing += full[i] && few_shade[i] && std::abs(*full[i] - *few_shade[i]) > 0.02f;
    }
    EXPECT_GT(differing, 20) << "four taps are not the full kernel";
    ASSERT_GT(few.shadowed, 100);
    EXPECT_LE(few.misclassified, few.measured / 50) << few.misclassified << " of " << few.measured;
  }
}

TEST_F(ShadowAlgorithms, PcssPenumbraWidensWithTheBlockerDistance) {
  int penumbra[2] = {0, 0};
  const float heights[2] = {0.3f, 2.5f};
  for (int i = 0; i < 2; ++i) {
    ShadowScene s = with(LightKind::spot, scene::ShadowAlgorithm::pcss);
    s.shadow.light_size = 0.6f;
    s.box_bottom = heights[i];
    penumbra[i] = classify(shade(s), reference(s, 1)).intermediate;
  }
  EXPECT_GT(penumbra[1], penumbra[0] * 3 / 2) << "low " << penumbra[0] << ", high " << penumbra[1];
}

TEST_F(ShadowAlgorithms, HalfDensityDarkensHalfAsMuch) {
  ShadowScene full = with(LightKind::spot, scene::ShadowAlgorithm::hard);
  ShadowScene half = full;
  half.shadow.density = 0.5f;
  const std::vector<float> unshadowed = render(full, full.intensity, false);
  const std::vector<float> dark_full = render(full, full.intensity, true);
  const std::vector<float> dark_half = render(half, half.intensity, true);
  const FloorPixels expected = reference(full, 2);
  double sum_full = 0.0, sum_half = 0.0;
  int counted = 0;
  for (size_t i = 0; i < unshadowed.size(); ++i) {
    if (expected.pixels[i] != FloorPixel::shadowed) continue;
    sum_full += unshadowed[i] - dark_full[i];
    sum_half += unshadowed[i] - dark_half[i];
    ++counted;
  }
  ASSERT_GT(counted, 100);
  ASSERT_GT(sum_full / counted, 0.1);
  EXPECT_NEAR(sum_half / sum_full, 0.5, 0.05);
}

TEST_F(ShadowAlgorithms, DefaultBiasLeavesTheLitFloorClean) {
  for (const scene::ShadowAlgorithm algorithm : scene::all_shadow_algorithms) {
    for (const LightKind kind : {LightKind::spot, LightKind::point}) {
      SCOPED_TRACE(std::string(to_string(algorithm)) + (kind == LightKind::spot ? " spot" : " point"));
      ShadowScene s = with(kind, algorithm);
      if (kind == LightKind::point) s.light_position = {-2.5f, 4.0f, -1.5f};
      const Classification c = classify(shade(s), reference(s, 4));
      ASSERT_GT(c.measured, 2000);
      EXPECT_LE(c.lit_but_darkened, c.measured / 1000) << "acne: lit floor pixels measured as shadowed";
    }
  }
}

// Acne is worst where light grazes a surface. A floor with nothing on it, lit from low at the
// side, must come out lit everywhere, whatever the algorithm: the kernels compare against the
// receiver's plane, and texel-sized slopes are within the bias.
TEST_F(ShadowAlgorithms, GrazingLightLeavesAnEmptyFloorLit) {
  for (const scene::ShadowAlgorithm algorithm : scene::all_shadow_algorithms) {
    for (const LightKind kind : {LightKind::spot, LightKind::point}) {
      SCOPED_TRACE(std::string(to_string(algorithm)) + (kind == LightKind::spot ? " spot" : " point"));
      ShadowScene s = with(kind, algorithm);
      s.with_box = false;
      s.light_position = {-7.0f, 1.5f, -1.0f};
      s.aim = glm::normalize(glm::vec3(1.0f, -0.35f, 0.1f));
      s.intensity = 3.0f;
      const Classification c = classify(shade(s), reference(s, 0));
      ASSERT_GT(c.measured, 1000);
      EXPECT_EQ(c.shadowed, 0);
      EXPECT_LE(c.lit_but_darkened, c.measured / 1000) << "acne at grazing incidence";
    }
  }
}

TEST_F(ShadowAlgorithms, NoiseIsStableFromFrameToFrame) {
  for (const scene::ShadowAlgorithm algorithm :
       {scene::ShadowAlgorithm::noise, scene::ShadowAlgorithm::pcss_noise}) {
    const ShadowScene s = with(LightKind::spot, algorithm, 128);
    std::vector<uint8_t> first;
    render(s, s.intensity, true, 3, &first);
    EXPECT_EQ(first, last_pixels) << to_string(algorithm);
  }
}

// The noise algorithms' patterns stay on the surface when the camera moves: a wall seen straight
// on, a box's noisy shadow on it, the camera moved sideways by exactly 5 pixels' width at the wall,
// so that each pixel of the wall shows what the pixel 5 columns to its right showed. Pixels that
// change also with the hard algorithm (the box itself, in front of the wall, seen from elsewhere)
// are left out; of the others, a noisy shadow changes none. Drawn per screen pixel, the pattern
// swam over the wall and this failed.
TEST_F(ShadowAlgorithms, NoiseStaysOnTheSurfaceWhenTheCameraMoves) {
  constexpr int shift = 5;
  const float distance = 5.0f;
  // Per pixel of the wall: whether it changed with the camera's move, under `algorithm`.
  const auto changed = [&](scene::ShadowAlgorithm algorithm, int& shadowed) {
    uint32_t box = 0;
    SceneView scene = sandbox_scene(floor_scene("noisy wall", box));
    scene::Material matte;  // no highlight, which would move with the camera
    matte.specular = 0.0f;
    scene::add_instance(scene.scene, box, {{0.0f, 2.0f, -0.5f}, glm::quat(1, 0, 0, 0), {20.0f, 8.0f, 1.0f}},
                        matte);
    scene::add_instance(scene.scene, box, {{0.2f, 2.1f, 1.5f}, glm::quat(1, 0, 0, 0), {0.5f, 0.5f, 0.5f}},
                        matte);
    scene::SpotLight spot;
    spot.range = 20.0f;
    spot.outer_cone = glm::radians(40.0f);
    scene::ShadowSettings noisy;
    noisy.algorithm = algorithm;
    noisy.pcf_radius = 4.0f;
    noisy.resolution = 128;
    noisy.light_size = 0.5f;
    scene::add_light(scene.scene, spot, aimed_light({0.0f, 2.0f, 4.0f}, {0.0f, 0.0f, -1.0f}), noisy, "spot");
    ecs::update_world_transforms(scene.scene.world, 0);
    FrameSettings options;
    options.renderer.shadow_resolution = shadows::ShadowResolution::requested;  // the same map
    const float pixel = 2.0f * distance * std::tan(0.5f * scene.lens.yfov) / float(height);
    scene.pose = {{0.0f, 2.0f, distance}, {0.0f, 2.0f, 0.0f}};
    const std::vector<float> before = render(scene, options);
    scene.pose = {{shift * pixel, 2.0f, distance}, {shift * pixel, 2.0f, 0.0f}};
    const std::vector<float> after = render(scene, options);
    const float brightest = *std::max_element(before.begin(), before.end());
    // Rows that see the wall (the floor below it is not parallel to the picture: it does not shift).
    const uint32_t wall_rows = std::min(height, uint32_t(0.5f * height + 1.9f / pixel));
    std::vector<bool> out;
    shadowed = 0;
    for (uint32_t y = 0; y < wall_rows; ++y) {
      for (uint32_t x = shift; x < width; ++x) {
        const float was = before[size_t{y} * width + x];
        out.push_back(std::abs(was - after[size_t{y} * width + x - shift]) > 0.01f);
        // The box's shadow, in the middle of the lit disc.
        const bool middle = x > width / 4 && x < 3 * width / 4 && y > height / 4 && y < 3 * height / 4;
        shadowed += middle && was < 0.5f * brightest;
      }
    }
    return out;
  };
  int shadowed = 0;
  const std::vector<bool> geometry = changed(scene::ShadowAlgorithm::hard, shadowed);
  for (const scene::ShadowAlgorithm algorithm :
       {scene::ShadowAlgorithm::noise, scene::ShadowAlgorithm::pcss_noise}) {
    const std::vector<bool> noisy = changed(algorithm, shadowed);
    EXPECT_GT(shadowed, 100) << to_string(algorithm) << ": no shadow on the wall";
    size_t moved = 0;
    for (size_t i = 0; i < noisy.size(); ++i) moved += noisy[i] && !geometry[i];
    EXPECT_LE(moved, noisy.size() / 1000) << to_string(algorithm) << ": of " << noisy.size() << " pixels";
  }
}

// A sun over a scene 1 km wide (two small boxes far out of sight widen it): its one fitted map
// has texels of about a metre, and the box's shadow on the floor is a few blocks (59 pixels
// misclassified of 81 in shadow, 2026-12-02); with cascades the nearest map covers a few tens of
// metres and every algorithm's shadow agrees with ray casting away from the edge (none).
ShadowScene sun_over_a_wide_scene(scene::ShadowAlgorithm algorithm, uint32_t cascades) {
  ShadowScene s = with(LightKind::directional, algorithm);
  s.aim = glm::normalize(glm::vec3(0.8f, -1.0f, 0.6f));
  s.box_bottom = 2.0f;  // its shadow falls beside it, in the camera's sight
  s.scene_half_extent = 500.0f;
  s.shadow.cascades = cascades;
  return s;
}

TEST_F(ShadowAlgorithms, CascadedSunShadowsMatchRayCastingWithEveryAlgorithm) {
  const ShadowScene single = sun_over_a_wide_scene(scene::ShadowAlgorithm::hard, 1);
  const FloorPixels floor = reference(single, 2);
  const Classification one_map = classify(shade(single), floor);
  for (const scene::ShadowAlgorithm algorithm : scene::all_shadow_algorithms) {
    SCOPED_TRACE(to_string(algorithm));
    const Classification c = classify(shade(sun_over_a_wide_scene(algorithm, shadows::max_cascades)), floor);
    EXPECT_GE(last_cascades, 2u) << "the view needs more than one map";
    ASSERT_GT(c.measured, 2000);
    ASSERT_GT(c.shadowed, 50) << "the box must cast a visible shadow";
    EXPECT_LE(c.misclassified, c.measured / 100) << c.misclassified << " of " << c.measured;
    EXPECT_LT(c.misclassified * 3, one_map.misclassified)
        << "cascaded " << c.misclassified << ", one map " << one_map.misclassified;
  }
}

// Cascades are snapped to whole texels: a camera looking straight down, moved by one pixel of the
// floor (a fifth of a texel of the nearest cascade), sees every shadowed floor point as it was,
// one pixel over, with the hard test and both noise kernels (anchored to the map's texels). Only
// pixels whose unshadowed picture moved otherwise (the box's top, nearer the camera) are left out.
TEST_F(ShadowAlgorithms, ACameraMovedLessThanATexelLeavesCascadedShadowsInPlace) {
  const float height_above = 6.0f;
  const auto changed = [&](scene::ShadowAlgorithm algorithm, bool shadows, int& shadowed) {
    ShadowScene s = sun_over_a_wide_scene(algorithm, shadows::max_cascades);
    s.shadow.resolution = 256;
    SceneView scene = build(s, s.intensity);
    FrameSettings options;
    options.renderer.lights.shadows = shadows;
    options.renderer.shadow_resolution = shadows::ShadowResolution::requested;  // the same tiles
    const float pixel = 2.0f * height_above * std::tan(0.5f * scene.lens.yfov) / float(height);
    const auto look_down_from = [&](float x) {
      scene.pose = {{x, height_above, 0.4f}, {x, 0.0f, 0.4f}, {0.0f, 0.0f, -1.0f}};
    };
    look_down_from(0.3f);
    const std::vector<float> before = render(scene, options);
    if (shadows) {
      EXPECT_GE(last_cascades, 2u);
    }
    look_down_from(0.3f + pixel);
    const std::vector<float> after = render(scene, options);
    const float brightest = *std::max_element(before.begin(), before.end());
    std::vector<bool> out;
    shadowed = 0;
    for (uint32_t y = 0; y < height; ++y) {
      for (uint32_t x = 1; x < width; ++x) {
        const float was = before[size_t{y} * width + x];
        out.push_back(std::abs(was - after[size_t{y} * width + x - 1]) > 0.01f);
        shadowed += was < 0.5f * brightest;
      }
    }
    return out;
  };
  int shadowed = 0;
  const std::vector<bool> geometry = changed(scene::ShadowAlgorithm::hard, false, shadowed);
  for (const scene::ShadowAlgorithm algorithm :
       {scene::ShadowAlgorithm::hard, scene::ShadowAlgorithm::noise, scene::ShadowAlgorithm::pcss_noise}) {
    const std::vector<bool> moved_pixels = changed(algorithm, true, shadowed);
    EXPECT_GT(shadowed, 100) << to_string(algorithm) << ": no shadow below the camera";
    size_t moved = 0;
    for (size_t i = 0; i < moved_pixels.size(); ++i) moved += moved_pixels[i] && !geometry[i];
    EXPECT_LE(moved, moved_pixels.size() / 1000)
        << to_string(algorithm) << ": of " << moved_pixels.size() << " pixels";
  }
}

// Five spot lights side by side, each over its own box and floor disc, each with its own
// algorithm. Each disc must look exactly as when every light uses that disc's algorithm, and
// the discs of the filtered algorithms must differ from the hard one's.
TEST_F(ShadowAlgorithms, FiveLightsEachRenderWithTheirOwnAlgorithm) {
  constexpr float spacing = 4.0f;
  const auto build_row = [&]() {
    uint32_t box = 0;
    SceneView out = sandbox_scene(floor_scene("five lights", box));
    scene::Scene& scene = out.scene;
    for (int i = 0; i < 5; ++i) {
      const float x = (i - 2) * spacing;
      scene::add_instance(
          scene, box, {{x + 0.2f, 1.2f, 0.1f}, glm::angleAxis(0.4f, glm::vec3(0, 1, 0)), {0.7f, 0.3f, 0.6f}},
          scene::Material{});
      scene::SpotLight light;
      light.intensity = 1.6f;
      light.range = 8.0f;
      light.inner_cone = glm::radians(15.0f);
      light.outer_cone = glm::radians(22.0f);
      scene::ShadowSettings shadow;
      shadow.algorithm = scene::all_shadow_algorithms[i];
      shadow.resolution = 64;  // coarse, so that the filters differ by whole pixels
      shadow.light_size = 0.6f;
      scene::add_light(scene, light, downward_light({x, 4.0f, 0.0f}), shadow,
                       std::string(to_string(shadow.algorithm)));
    }
    ecs::update_world_transforms(scene.world, 0);
    out.pose = {{0.0f, 14.0f, 0.01f}, {0.0f, 0.0f, 0.0f}};
    return out;
  };
  SceneView mixed_scene = build_row();
  const std::vector<float> mixed = render(mixed_scene, FrameSettings{});

  // Which disc each pixel of the floor belongs to (-1: none).
  CameraImage view{mixed_scene.pose, mixed_scene.lens, {width, height}};
  std::vector<int> disc(mixed.size(), -1);
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      const std::optional<glm::vec3> p = hit_floor(pixel_ray(view, x, y));
      if (!p) continue;
      const int i = static_cast<int>(std::lround(p->x / spacing)) + 2;
      if (i >= 0 && i < 5 && glm::length(glm::vec2(p->x - (i - 2) * spacing, p->z)) < 1.8f) {
        disc[size_t{y} * width + x] = i;
      }
    }
  }

  std::vector<std::vector<float>> uniform(5);
  for (int a = 0; a < 5; ++a) {
    SceneView scene = build_row();
    scene.scene.world.query<scene::ShadowSettings>().for_each(
        [&](scene::ShadowSettings& shadow) { shadow.algorithm = scene::all_shadow_algorithms[a]; });
    uniform[a] = render(scene, FrameSettings{});
  }
  for (int i = 0; i < 5; ++i) {
    SCOPED_TRACE(to_string(scene::all_shadow_algorithms[i]));
    int pixels = 0, same_as_own = 0, differs_from_hard = 0;
    for (size_t p = 0; p < mixed.size(); ++p) {
      if (disc[p] != i) continue;
      ++pixels;
      same_as_own += std::abs(mixed[p] - uniform[i][p]) < 1e-6f;
      differs_from_hard += std::abs(mixed[p] - uniform[0][p]) > 0.01f;
    }
    ASSERT_GT(pixels, 100);
    EXPECT_EQ(same_as_own, pixels) << "the disc must look as with its own algorithm everywhere";
    if (i > 0) {
      EXPECT_GT(differs_from_hard, 5) << "the algorithm must be visible";
    }
  }
}

}  // namespace
}  // namespace sg::test
