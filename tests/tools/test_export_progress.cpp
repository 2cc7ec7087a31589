// `throng export`: progress lines when not on a terminal, and --trajectories-out beside the
// animation.
#include <doctest/doctest.h>

#include <fstream>
#include <string>

#include "cli_support.h"

TEST_CASE("export: plain progress lines and the crowd's trajectories as CSV") {
  const auto dir = throng::test::freshDirectory("export_progress");
  const auto csv = dir / "crowd.csv";
  auto run =
      throng::test::runThrong("export --scene circle -n 20 --frames 30 --out " +
                              (dir / "crowd.glb").string() + " --trajectories-out " + csv.string());
  INFO(run.output);
  REQUIRE(run.exitCode == 0);
  CHECK(run.output.find("export 30/30") != std::string::npos);
  std::ifstream in(csv);
  std::string line;
  size_t rows = 0;
  std::getline(in, line);
  CHECK(line == "id,frame,time,x,y,z,heading,speed,group,state");
  while (std::getline(in, line)) ++rows;
  CHECK(rows == 20 * 30);
}
