#pragma once
// Pedestrians tracked in video (ETH and UCY, ../shared/data/trajectories): per person, a list
// of timed ground-plane positions in metres. Two text formats:
//   * "frame ped_id x y", tab- or space-separated (the Social-GAN / Trajectron++ files). Frame
//     numbers step by a fixed amount per annotation (10) with gaps where nobody was annotated;
//     one step is 0.4 s, except biwi_eth whose step is 0.667 s.
//   * ETH's obsmat.txt: "frame ped x z y vx vz vy" in scientific notation (z unused), one
//     annotation every 0.4 s (the frame step differs per sequence: 6 for seq_eth, 10 for hotel).
//   * PedPy's text format (what `--trajectories-out FILE.txt` writes): a "# framerate: F"
//     comment, then "id frame x y z" (further columns ignored), metres unless a comment says
//     "x/cm" or "in cm"; the ground plane is (x, y) and one frame is 1/F s.
// Time of a sample = frame · secondsPerFrame, secondsPerFrame = step time / modal frame step,
// in double: frame numbers up to 1e9 (≈ 4e7 s) keep their 0.04 s steps apart (a float's step
// there is 4 s). A person's annotations more than kMaxTrackGapSeconds apart are two tracks:
// nobody is interpolated across a long absence, and a file's time span cannot make the
// per-second resampling unbounded.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace throng::crowd {

enum class TrajectoryFormat { Auto, FramePedXY, EthObsmat, PedPy };

struct TrajectoryOptions {
  TrajectoryFormat format = TrajectoryFormat::Auto;  // Auto: by file name, else column count
  // Seconds between two annotations; 0: by dataset (biwi_eth 0.667 s, every other set 0.4 s).
  // PedPy files take their frame time from their framerate comment instead.
  float secondsPerStep = 0.0f;
};

inline constexpr double kMaxTrackGapSeconds = 10.0;

struct TrackPoint {
  double time = 0.0;      // seconds
  glm::vec2 position{0};  // metres on the ground plane (data x, data y)
};

struct Track {
  int id = 0;                      // the person (split tracks of one person share it)
  std::vector<TrackPoint> points;  // increasing time, consecutive ones ≤ kMaxTrackGapSeconds apart
  double duration() const {
    return points.empty() ? 0.0 : points.back().time - points.front().time;
  }
};

struct Trajectories {
  std::string source;  // file name, for messages
  TrajectoryFormat format = TrajectoryFormat::FramePedXY;
  int frameStep = 0;            // modal difference between consecutive annotated frame numbers
  double secondsPerStep = 0.0;  // seconds per annotation step
  double secondsPerFrame = 0.0;
  size_t sampleCount = 0;     // data lines read
  size_t gapSplits = 0;       // tracks split at an absence longer than kMaxTrackGapSeconds
  std::vector<Track> tracks;  // by increasing id, a split person's tracks in time order
  double startTime() const;   // earliest sample time
};

// Throws Error "<source>:<line>: ..." naming what was expected for a malformed line, a
// duplicate (frame, person) pair or a file without samples.
Trajectories parseTrajectories(std::string_view text, const std::string& source,
                               const TrajectoryOptions& options = {});
Trajectories loadTrajectories(const std::filesystem::path& path,
                              const TrajectoryOptions& options = {});

// Step time a dataset's file name implies (0.667 s for biwi_eth, else 0.4 s).
float defaultSecondsPerStep(const std::string& source);

}  // namespace throng::crowd
