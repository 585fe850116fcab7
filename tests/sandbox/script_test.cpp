// SPDX-License-Identifier: MIT
// --script's commands: what parses into what, and errors that name the file and line.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "sandbox/script.h"

namespace sg::sandbox {
namespace {

TEST(Script, ParsesEveryCommandAndSkipsCommentsAndBlankLines) {
  const std::vector<ScriptStep> steps = parse_script(
      "# a light, then a view\n"
      "select spot east   \n"
      "\n"
      "algorithm pcss_noise\n"
      "resolution 256  # texels\n"
      "move 1 2.5 -3\n"
      "camera 0,12,0,0,0,0\n"
      "wait 5\n"
      "screenshot shot one.png\n"
      "view shadows\n"
      "update on_demand\n"
      "priority -1.5\n"
      "redraw_shadow\n"
      "open models/a hall.glb\n",
      "test.txt");
  ASSERT_EQ(steps.size(), 12u);
  EXPECT_EQ(std::get<ScriptStep::Select>(steps[0].command).name, "spot east");
  EXPECT_EQ(steps[0].line, 2);
  EXPECT_EQ(std::get<ScriptStep::Algorithm>(steps[1].command).algorithm, scene::ShadowAlgorithm::pcss_noise);
  EXPECT_EQ(std::get<ScriptStep::Resolution>(steps[2].command).texels, 256u);
  EXPECT_EQ(std::get<ScriptStep::Move>(steps[3].command).position, glm::vec3(1.0f, 2.5f, -3.0f));
  EXPECT_EQ(std::get<ScriptStep::Camera>(steps[4].command).pose.eye, glm::vec3(0.0f, 12.0f, 0.0f));
  EXPECT_EQ(std::get<ScriptStep::Wait>(steps[5].command).frames, 5u);
  EXPECT_EQ(std::get<ScriptStep::Screenshot>(steps[6].command).path, "shot one.png");
  EXPECT_EQ(steps[6].line, 9);
  EXPECT_EQ(std::get<ScriptStep::View>(steps[7].command).view, LightingView::shadows);
  EXPECT_EQ(std::get<ScriptStep::Update>(steps[8].command).update, scene::ShadowUpdate::on_demand);
  EXPECT_FLOAT_EQ(std::get<ScriptStep::Priority>(steps[9].command).tiers, -1.5f);
  EXPECT_TRUE(std::holds_alternative<ScriptStep::RedrawShadow>(steps[10].command));
  EXPECT_EQ(std::get<ScriptStep::Open>(steps[11].command).path, "models/a hall.glb");
}

TEST(Script, ErrorsNameTheFileAndLine) {
  const auto error_of = [](const std::string& text) {
    try {
      parse_script(text, "run.txt");
    } catch (const std::runtime_error& error) {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(error_of("wait 1\nfly away\n"), "run.txt:2: unknown command \"fly\"");
  EXPECT_EQ(error_of("algorithm soft"), "run.txt:1: unknown shadow algorithm \"soft\"");
  EXPECT_EQ(error_of("wait 0"), "run.txt:1: wait takes a whole number of frames, 1 to 100,000, got \"0\"");
  EXPECT_EQ(error_of("wait 2.5"),
            "run.txt:1: wait takes a whole number of frames, 1 to 100,000, got \"2.5\"");
  EXPECT_EQ(error_of("resolution 8"),
            "run.txt:1: resolution takes a whole number of texels, 16 to 4096, got \"8\"");
  EXPECT_EQ(error_of("move 1 2"), "run.txt:1: move takes three numbers, got \"1 2\"");
  EXPECT_EQ(error_of("select"), "run.txt:1: select takes a light's name");
  EXPECT_EQ(error_of("update often"),
            "run.txt:1: update takes auto, every_frame or on_demand, got \"often\"");
  EXPECT_EQ(error_of("priority 5"), "run.txt:1: priority takes a number of tiers, -4 to 4, got \"5\"");
  EXPECT_EQ(error_of("priority nan"), "run.txt:1: priority takes a number of tiers, -4 to 4, got \"nan\"");
  EXPECT_EQ(error_of("redraw_shadow now"), "run.txt:1: redraw_shadow takes nothing, got \"now\"");
  EXPECT_EQ(error_of("view depth"), "run.txt:1: view takes lit or shadows, got \"depth\"");
  EXPECT_EQ(error_of("open"), "run.txt:1: open takes a .gltf or .glb path or a built-in scene's name");
  EXPECT_NE(error_of("camera 1,2,3,1,2,3").find("run.txt:1: "), std::string::npos);
  // Checked with the script, not when the step comes, after the frames before it.
  EXPECT_EQ(error_of("wait 1\nscreenshot /nonexistent/shot.png"),
            "run.txt:2: screenshot: the folder \"/nonexistent\" does not exist");
  EXPECT_THROW(load_script("/nonexistent/script.txt"), std::runtime_error);
}

}  // namespace
}  // namespace sg::sandbox
