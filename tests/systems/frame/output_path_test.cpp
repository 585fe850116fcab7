// SPDX-License-Identifier: MIT
// Where an output file can be written, and the PNG writer's report of a disk that refuses it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "systems/frame/output_path.h"
#include "systems/frame/png.h"

namespace sg {
namespace {

// `path` in quotes, as the messages name it.
std::string quoted(const std::filesystem::path& path) {
  return std::string(1, '"').append(path.string()).append(1, '"');
}

std::filesystem::path fresh_folder(const std::string& name) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

TEST(OutputPath, NamesWhatStandsInTheWay) {
  const std::filesystem::path folder = fresh_folder("shadowgraph-output-path-test");
  const std::filesystem::path file = folder / "taken.txt";
  std::ofstream(file) << "x";

  EXPECT_EQ(output_path_problem((folder / "new.png").string()), std::nullopt);
  EXPECT_EQ(output_path_problem(file.string()), std::nullopt);  // an existing file is replaced
  EXPECT_EQ(output_path_problem("shadowgraph-output-path-test.png"), std::nullopt);  // the working folder

  EXPECT_EQ(output_path_problem((folder / "missing" / "new.png").string()),
            std::string("the folder ") + quoted(folder / "missing") + " does not exist");
  EXPECT_EQ(output_path_problem(folder.string()), quoted(folder) + " is a folder, not a file");
  EXPECT_EQ(output_path_problem((file / "new.png").string()), quoted(file) + " is not a folder");
  EXPECT_EQ(output_path_problem(""), "the path is empty");

  EXPECT_EQ(optional_output_problem(""), std::nullopt);  // left out
  EXPECT_EQ(optional_output_problem(folder.string()), quoted(folder) + " is a folder, not a file");
}

// stbi_write_png does not check its writes: a full disk left a truncated file and no error.
TEST(WritePng, AFullDiskIsAnError) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  vk::Rgba8Image image;
  image.width = 64;
  image.height = 64;
  image.pixels.assign(size_t{64} * 64 * 4, 128);
  try {
    write_png("/dev/full", image);
    FAIL() << "a write to /dev/full succeeded";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("/dev/full"), std::string::npos) << error.what();
  }
  const std::filesystem::path written = fresh_folder("shadowgraph-png-test") / "grey.png";
  write_png(written.string(), image);
  EXPECT_GT(std::filesystem::file_size(written), 0u);
}

}  // namespace
}  // namespace sg
