#include "crowd/trajectory_writer.h"

#include <algorithm>
#include <cstdio>

#include "core/error.h"
#include "core/file_io.h"

namespace throng::crowd {
namespace {

std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// Enough digits that positions round-trip within 1e-4 m up to 1e5 m from the origin.
template <typename... Args>
void append(std::string& text, const char* format, Args... args) {
  char line[256];
  int n = std::snprintf(line, sizeof line, format, args...);
  text.append(line, size_t(std::clamp(n, 0, int(sizeof line) - 1)));
}

}  // namespace

TrajectoryFileFormat trajectoryFileFormat(const std::filesystem::path& path,
                                          const std::string& option) {
  const std::string ext = lowerExtension(path);
  if (ext == ".txt") return TrajectoryFileFormat::PedPy;
  if (ext == ".csv") return TrajectoryFileFormat::Csv;
  fail(option, " ", path.string(), ": expected a .txt (PedPy 'id frame x y z') or .csv file name");
}

void checkTrajectoryOutput(const std::filesystem::path& path, uint64_t agents, uint64_t frames,
                           const std::string& option) {
  trajectoryFileFormat(path, option);
  if (agents * frames > kMaxTrajectoryRows)
    fail(option, " ", path.string(), ": ", agents, " agents x ", frames, " frames is more than ",
         kMaxTrajectoryRows, " rows; record fewer frames or agents");
  const std::filesystem::path dir = path.parent_path().empty() ? "." : path.parent_path();
  try {
    ensureWritableDirectory(dir);
  } catch (const Error& e) {
    fail(option, " ", path.string(), ": ", e.what());
  }
}

TrajectoryWriter::TrajectoryWriter(std::filesystem::path path, double framerate,
                                   std::vector<uint32_t> groups)
    : path_(std::move(path)),
      format_(trajectoryFileFormat(path_)),
      framerate_(framerate),
      groups_(std::move(groups)) {
  if (!(framerate > 0.0 && framerate <= 10000.0))
    fail(path_.string(), ": framerate ", framerate, ": expected 0 < frames per second <= 10000");
  if (format_ == TrajectoryFileFormat::PedPy) {
    append(text_, "# framerate: %.6g\n", framerate_);
    text_ +=
        "# throng trajectories in metres: x = engine x, y = engine z (the ground plane), "
        "z = engine y (height)\n# id frame x/m y/m z/m\n";
  } else {
    text_ += "id,frame,time,x,y,z,heading,speed,group,state\n";
  }
}

void TrajectoryWriter::addFrame(std::span<const glm::vec4> placement,
                                std::span<const uint8_t> active) {
  const size_t n = placement.size();
  if (frame_ > 0 && n != previous_.size())
    fail(path_.string(), ": frame ", frame_, " has ", n, " agents, earlier frames ",
         previous_.size());
  if (!active.empty() && active.size() != n)
    fail(path_.string(), ": ", active.size(), " activity flags for ", n, " agents");
  if (rows_ + n > kMaxTrajectoryRows)
    fail(path_.string(), ": more than ", kMaxTrajectoryRows, " rows (agents x frames)");
  const double time = double(frame_) / framerate_;
  for (size_t i = 0; i < n; ++i) {
    const glm::vec4 p = placement[i];
    const bool on = active.empty() || active[i] != 0;
    if (format_ == TrajectoryFileFormat::PedPy) {
      if (on)
        append(text_, "%zu %llu %.6f %.6f %.6f\n", i, (unsigned long long)frame_, p.x, p.z, p.y);
      continue;
    }
    const bool moved = frame_ > 0 && on && previousActive_[i];
    const float speed = moved ? glm::length(glm::vec2(p.x - previous_[i].x, p.z - previous_[i].z)) *
                                    float(framerate_)
                              : 0.0f;
    const uint32_t group = i < groups_.size() ? groups_[i] : 0u;
    append(text_, "%zu,%llu,%.6f,%.6f,%.6f,%.6f,%.5f,%.4f,%u,%s\n", i, (unsigned long long)frame_,
           time, p.x, p.y, p.z, p.w, speed, group, on ? "active" : "inactive");
  }
  rows_ += n;
  previous_.assign(placement.begin(), placement.end());
  previousActive_.assign(n, 1);
  if (!active.empty()) previousActive_.assign(active.begin(), active.end());
  ++frame_;
}

void TrajectoryWriter::finish() {
  writeTextFileAtomic(path_, text_);
}

}  // namespace throng::crowd
