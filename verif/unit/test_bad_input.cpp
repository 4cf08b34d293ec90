// Every file of the bad-input corpus is rejected by its loader with the message recorded in
// verif/bad_input/expected.tsv (the CLI cases, with exit status and no-output checks, run as
// separate ctest tests: cli_bad_input.*).
#include <gtest/gtest.h>

#include "common/error.hpp"
#include "frame/screen_frame.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

namespace cig {
namespace {

TEST(BadInput, EveryCorpusFileFailsWithItsMessage) {
  const auto cases = test::bad_input_cases();
  ASSERT_GE(cases.size(), 30u);
  int loader_cases = 0;
  for (const auto& c : cases) {
    if (c.command != "render" && c.command != "raster") continue;
    ++loader_cases;
    SCOPED_TRACE(c.name);
    const std::string path = test::source_path("verif/bad_input/" + c.file);
    try {
      if (c.command == "render") load_scene(path);
      else load_polygon_list(path);
      ADD_FAILURE() << c.file << " was accepted";
    } catch (const InputError& e) {
      EXPECT_TRUE(test::contains_pattern(e.what(), c.message))
          << "expected: " << c.message << "\n     got: " << e.what();
      EXPECT_FALSE(e.file().empty());
    }
  }
  EXPECT_GE(loader_cases, 25);
}

TEST(BadInput, WildcardMatchesThePiecesInOrder) {
  // expected.tsv's '*' (the signal a crashing reader raises is the platform's choice).
  const std::string got = "assimp crashed (signal 7, SIGBUS) reading the model; the file is refused";
  EXPECT_TRUE(test::contains_pattern(got, "assimp crashed (signal *) reading the model; the file is refused"));
  EXPECT_TRUE(test::contains_pattern(got, "crashed"));
  EXPECT_FALSE(test::contains_pattern(got, "reading the model*assimp crashed"));
  EXPECT_FALSE(test::contains_pattern(got, "assimp crashed (signal *) writing"));
}

TEST(BadInput, ValidBaseOfTheCorpusLoads) {
  // The mutations start from this scene; it must itself be valid, or every case proves nothing.
  EXPECT_NO_THROW(load_scene(test::source_path("verif/bad_input/option_valid_scene.json")));
}

}  // namespace
}  // namespace cig
