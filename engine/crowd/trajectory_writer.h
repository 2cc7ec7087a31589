#pragma once
// Every agent's ground position per frame, written for analysis tools (`--trajectories-out`):
//   * FILE.txt: PedPy's text format, "# framerate: F", then "id frame x y z" in metres, one line
//     per active agent per frame. PedPy's (x, y) is the ground plane: PedPy x = engine x,
//     PedPy y = engine z, PedPy z = engine y (height; the engine's y is up). `throng crowd
//     metrics --trajectories FILE.txt` reads it back.
//   * FILE.csv: "id,frame,time,x,y,z,heading,speed,group,state" for every agent in every frame,
//     in engine coordinates (y up), heading in radians, speed in m/s (the distance from the
//     previous frame's position over one frame's time), state "active" or "inactive" (not on
//     the scene yet, or any more).
// The text is kept in memory (bounded by kMaxTrajectoryRows) and written atomically by finish().
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace throng::crowd {

enum class TrajectoryFileFormat { PedPy, Csv };

// At most this many rows (agents × frames) per file: about 1 GB of text.
inline constexpr uint64_t kMaxTrajectoryRows = 20'000'000;

// By extension (.txt PedPy, .csv CSV); throws Error naming `option` for any other.
TrajectoryFileFormat trajectoryFileFormat(const std::filesystem::path& path,
                                          const std::string& option = "--trajectories-out");
// Checks before a run: the extension, a writable folder and agents × frames within
// kMaxTrajectoryRows. Throws Error naming `option`.
void checkTrajectoryOutput(const std::filesystem::path& path, uint64_t agents, uint64_t frames,
                           const std::string& option = "--trajectories-out");

class TrajectoryWriter {
 public:
  // `groups`: per agent (empty: every agent in group 0). Throws Error for a bad extension or a
  // framerate outside (0, 10000].
  TrajectoryWriter(std::filesystem::path path, double framerate, std::vector<uint32_t> groups);

  // One frame: placement (x, y, z, heading) of every agent; `active` per agent (empty: all).
  // Throws Error when the agent count changes or the rows would pass kMaxTrajectoryRows.
  void addFrame(std::span<const glm::vec4> placement, std::span<const uint8_t> active = {});
  // Writes the file (temporary name, then rename).
  void finish();

  uint64_t frames() const { return frame_; }
  uint64_t rows() const { return rows_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  TrajectoryFileFormat format_;
  double framerate_;
  std::vector<uint32_t> groups_;
  std::vector<glm::vec4> previous_;
  std::vector<uint8_t> previousActive_;
  std::string text_;
  uint64_t frame_ = 0, rows_ = 0;
};

}  // namespace throng::crowd
