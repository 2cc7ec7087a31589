#pragma once
// Pedestrians tracked in video (ETH and UCY, ../shared/data/trajectories): per person, a list
// of timed ground-plane positions in metres. Two text formats:
//   * "frame ped_id x y", tab- or space-separated (the Social-GAN / Trajectron++ files). Frame
//     numbers step by a fixed amount per annotation (10) with gaps where nobody was annotated;
//     one step is 0.4 s, except biwi_eth whose step is 0.667 s.
//   * ETH's obsmat.txt: "frame ped x z y vx vz vy" in scientific notation (z unused), one
//     annotation every 0.4 s (the frame step differs per sequence: 6 for seq_eth, 10 for hotel).
// Time of a sample = frame · secondsPerFrame, secondsPerFrame = step time / modal frame step.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace throng::crowd {

enum class TrajectoryFormat { Auto, FramePedXY, EthObsmat };

struct TrajectoryOptions {
  TrajectoryFormat format = TrajectoryFormat::Auto;  // Auto: by file name, else column count
  // Seconds between two annotations; 0: by dataset (biwi_eth 0.667 s, every other set 0.4 s).
  float secondsPerStep = 0.0f;
};

struct TrackPoint {
  float time = 0.0f;      // seconds
  glm::vec2 position{0};  // metres on the ground plane (data x, data y)
};

struct Track {
  int id = 0;
  std::vector<TrackPoint> points;  // increasing time
  float duration() const { return points.empty() ? 0.0f : points.back().time - points.front().time; }
};

struct Trajectories {
  std::string source;           // file name, for messages
  TrajectoryFormat format = TrajectoryFormat::FramePedXY;
  int frameStep = 0;            // modal difference between consecutive annotated frame numbers
  float secondsPerStep = 0.0f;  // seconds per annotation step
  float secondsPerFrame = 0.0f;
  size_t sampleCount = 0;       // data lines read
  std::vector<Track> tracks;    // by increasing id
  float startTime() const;      // earliest sample time
};

// Throws Error "<source>:<line>: ..." naming what was expected for a malformed line, a
// duplicate (frame, person) pair or a file without samples.
Trajectories parseTrajectories(std::string_view text, const std::string& source, const TrajectoryOptions& options = {});
Trajectories loadTrajectories(const std::filesystem::path& path, const TrajectoryOptions& options = {});

// Step time a dataset's file name implies (0.667 s for biwi_eth, else 0.4 s).
float defaultSecondsPerStep(const std::string& source);

}  // namespace throng::crowd
