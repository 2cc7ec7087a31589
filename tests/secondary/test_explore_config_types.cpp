// A .tsg's configuration is the file's own JSON: values of the wrong type are Errors naming the
// garment configuration or the file, never JSON library exceptions (found by the tsg fuzzer).
#include <doctest/doctest.h>
#include <unistd.h>

#include <filesystem>

#include "core/error.h"
#include "explore_fixtures.h"
#include "secondary/offline/explore_file.h"

using namespace throng;
using namespace throng::secondary;
namespace fs = std::filesystem;

TEST_CASE("explore file: a garment name that is not a string reads as no name") {
  Garment garment = fixtures::toyGarment();
  SecondaryGraph graph = fixtures::initializeToy(garment);
  nlohmann::json config = {{"garment", {{"name", 42}}}};
  fs::path path =
      fs::temp_directory_path() / ("throng_config_types_" + std::to_string(::getpid()) + ".tsg");
  saveExploreFile(path, config, *garment.primary, *garment.mesh, graph, garment.clips);
  nlohmann::json info;
  CHECK_NOTHROW(info = exploreFileInfo(path));
  CHECK(info["garment"] == "");
  config["garment"] = "cape";  // not even an object
  saveExploreFile(path, config, *garment.primary, *garment.mesh, graph, garment.clips);
  CHECK_NOTHROW(exploreFileInfo(path));
  fs::remove(path);
}

TEST_CASE("garment config: wrong types are Errors") {
  nlohmann::json config = defaultGarmentConfig("cape");
  config["slow"] = 5;
  config["fast"] = 6;
  CHECK_THROWS_WITH_AS(buildGarment(config), doctest::Contains("garment config"), Error);
}
