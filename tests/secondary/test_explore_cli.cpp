// throng cloth explore / info on the toy garment: the .tsg and its info, resume through the
// command line, the MPI run (mpirun -np 2) giving the threaded run's file byte for byte, and
// clear errors for damaged files and contradictory options.
#include <doctest/doctest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "cli_support.h"

using namespace throng::test;

namespace {
const std::string kToy = "cloth explore --garment toy --quiet --checkpoint-every 7 ";

std::vector<char> bytesOf(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

CommandResult runShell(const std::string& command) {
  CommandResult result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  REQUIRE(pipe != nullptr);
  char buffer[4096];
  size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, n);
  const int status = pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}
}  // namespace

TEST_CASE("cloth explore writes a .tsg that cloth info describes") {
  const auto dir = freshDirectory("cloth_explore_cli");
  const auto file = dir / "toy.tsg";
  const CommandResult r = runThrong(kToy + "--budget-expansions 40 --json --out " + file.string());
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  const nlohmann::json run = nlohmann::json::parse(r.output);
  CHECK(run["expansions"] == 40);
  CHECK(run["dead_ends"] == 0);
  CHECK(run["frames_per_second"].get<double>() > 0.0);

  const CommandResult info = runThrong("cloth info --json --history " + file.string());
  INFO(info.output);
  REQUIRE(info.exitCode == 0);
  const nlohmann::json j = nlohmann::json::parse(info.output);
  CHECK(j["kind"] == "secondary graph");
  CHECK(j["states"] == run["states"]);
  CHECK(j["primary_nodes"] == 14);
  CHECK(j["dead_ends"] == 0);
  CHECK(j["max_merge_error_m"] == run["max_merge_error_m"]);
  CHECK(j["bytes"] == std::filesystem::file_size(file));
  CHECK(j["error_history"].size() == 41);
  CHECK(j["garment"] == "toy");

  const CommandResult text = runThrong("cloth info " + file.string());
  CHECK(text.exitCode == 0);
  CHECK(contains(text.output, "dead_ends"));
}

TEST_CASE("explore --resume continues to the uninterrupted graph, byte for byte") {
  const auto dir = freshDirectory("cloth_explore_resume");
  const auto whole = dir / "whole.tsg", parts = dir / "parts.tsg";
  REQUIRE(runThrong(kToy + "--budget-expansions 45 --threads 2 --out " + whole.string()).exitCode ==
          0);
  REQUIRE(runThrong(kToy + "--budget-expansions 20 --threads 1 --out " + parts.string()).exitCode ==
          0);
  CHECK(bytesOf(parts) != bytesOf(whole));
  const CommandResult r =
      runThrong(kToy + "--resume --budget-expansions 45 --threads 2 --out " + parts.string());
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK(bytesOf(parts) == bytesOf(whole));

  // A run killed while writing a checkpoint leaves "<out>.tmp-PID": the next run removes it.
  const auto stale = dir / "parts.tsg.tmp-999999999";
  std::ofstream(stale, std::ios::binary) << "half a checkpoint";
  const CommandResult again =
      runThrong(kToy + "--resume --budget-expansions 46 --threads 1 --out " + parts.string());
  INFO(again.output);
  CHECK(again.exitCode == 0);
  CHECK_FALSE(std::filesystem::exists(stale));
  std::ofstream(dir / "whole.tsg.tmp-999999999", std::ios::binary) << "half a checkpoint";
  CHECK(runThrong(kToy + "--budget-expansions 2 --out " + whole.string()).exitCode == 0);
  CHECK_FALSE(std::filesystem::exists(dir / "whole.tsg.tmp-999999999"));
  const CommandResult toDir = runThrong(kToy + "--budget-expansions 2 --out " + dir.string());
  CHECK(toDir.exitCode != 0);
  CHECK(contains(toDir.output, "is a directory, expected a file to write"));

  const CommandResult seed = runThrong(kToy + "--resume --seed 9 --out " + parts.string());
  CHECK(seed.exitCode != 0);
  CHECK(contains(seed.output, "--seed 9 differs from the resumed file's 1"));
  const CommandResult missing = runThrong(kToy + "--resume --out " + (dir / "none.tsg").string());
  CHECK(missing.exitCode != 0);
  CHECK(contains(missing.output, "--resume needs an existing graph"));
}

TEST_CASE("cloth info rejects damaged and foreign files clearly") {
  const auto dir = freshDirectory("cloth_info_errors");
  const auto file = dir / "toy.tsg";
  REQUIRE(runThrong(kToy + "--budget-expansions 5 --out " + file.string()).exitCode == 0);
  std::vector<char> bytes = bytesOf(file);

  const auto cut = dir / "cut.tsg";
  std::ofstream(cut, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size() / 2));
  CommandResult r = runThrong("cloth info " + cut.string());
  CHECK(r.exitCode == 1);
  CHECK(contains(r.output, "error: " + cut.string() + ": truncated at byte " +
                               std::to_string(bytes.size() / 2)));

  bytes[bytes.size() / 3] ^= 0x08;
  const auto flipped = dir / "flipped.tsg";
  std::ofstream(flipped, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
  r = runThrong("cloth info --json " + flipped.string());
  CHECK(r.exitCode == 1);
  CHECK(contains(r.output, "checksum mismatch"));
  r = runThrong(kToy + "--resume --out " + flipped.string());
  CHECK(r.exitCode == 1);
  CHECK(contains(r.output, "checksum mismatch"));

  const auto text = dir / "notes.txt";
  std::ofstream(text) << "just some text\n";
  r = runThrong("cloth info " + text.string());
  CHECK(r.exitCode == 1);
  CHECK(contains(r.output, "not a secondary graph (.tsg) or compressed cloth (.tsc) file"));
}

TEST_CASE("explore --mpi under mpirun -np 2 writes the threaded run's graph") {
  if (runShell("command -v mpirun").exitCode != 0) {
    MESSAGE("SKIPPED: mpirun is not installed (Debian: openmpi-bin)");
    return;
  }
  const auto dir = freshDirectory("cloth_explore_mpi");
  const auto threaded = dir / "threads.tsg", distributed = dir / "mpi.tsg";
  REQUIRE(
      runThrong(kToy + "--budget-expansions 60 --threads 2 --out " + threaded.string()).exitCode ==
      0);
  // Open MPI refuses root without the flag; its leaks are not ours to report under ASan.
  const CommandResult r = runShell(
      "ASAN_OPTIONS=detect_leaks=0 OMPI_MCA_rmaps_base_oversubscribe=1 timeout 120 mpirun "
      "--allow-run-as-root --oversubscribe -np 2 " +
      throngBinary() + " " + kToy + "--budget-expansions 60 --mpi --out " + distributed.string());
  INFO(r.output);
  if (contains(r.output, "no Open MPI support")) {
    MESSAGE("SKIPPED: this throng was built without Open MPI");
    return;
  }
  REQUIRE(r.exitCode == 0);
  CHECK(bytesOf(distributed) == bytesOf(threaded));
}
