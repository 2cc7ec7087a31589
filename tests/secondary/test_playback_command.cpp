// `throng render --cloth`: capes on a rendered crowd, and a bad database refused before any frame.
#include <doctest/doctest.h>

#include <filesystem>

#include "cli_support.h"
#include "core/file_io.h"

using namespace throng;

TEST_CASE("render --cloth: a crowd with capes renders with validation on; a bad .tsc is refused") {
  std::filesystem::path dir = test::freshDirectory("render_cloth");
  test::CommandResult r = test::runThrong(
      "cloth explore --garment-config '{\"cape\": {\"columns\": 8, \"rows\": 12}}' "
      "--budget-expansions 2 --quiet --out " +
      (dir / "cape.tsg").string());
  REQUIRE(r.exitCode == 0);
  r = test::runThrong("cloth compress " + (dir / "cape.tsg").string() + " --out " +
                      (dir / "cape.tsc").string() + " --quiet");
  REQUIRE(r.exitCode == 0);
  r = test::runThrong(
      "render -n 40 --frames 3 --size 160x90 --camera street --validation --cloth " +
      (dir / "cape.tsc").string() + " --out " + (dir / "frames").string());
  INFO(r.output);
  CHECK(r.exitCode == 0);
  CHECK(r.output.find("cloth (median") != std::string::npos);
  CHECK(std::filesystem::exists(dir / "frames" / "frame_0002.png"));

  writeTextFileAtomic(dir / "bad.tsc", "THRNGTSC but nothing after the magic");
  r = test::runThrong("render -n 10 --frames 1 --size 64x48 --cloth " + (dir / "bad.tsc").string() +
                      " --out " + (dir / "bad_frames").string());
  INFO(r.output);
  CHECK(r.exitCode != 0);
  CHECK(r.output.find("bad.tsc") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "bad_frames" / "frame_0000.png"));
}
