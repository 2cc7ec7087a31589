#include "crowd/trajectories.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>

#include "core/error.h"
#include "core/file_io.h"

namespace throng::crowd {
namespace {

// Frame numbers up to 1e12: times (frame · seconds per frame, in double) keep sub-millisecond
// resolution there.
constexpr double kMaxFrameNumber = 1e12;

struct Sample {
  long long frame;
  int ped;
  glm::vec2 position;
  size_t line;
};

std::vector<std::string_view> splitFields(std::string_view line) {
  std::vector<std::string_view> fields;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) fields.push_back(line.substr(start, i - start));
  }
  return fields;
}

bool parseNumber(std::string_view s, double& value) {
  if (!s.empty() && s[0] == '+') s.remove_prefix(1);  // from_chars rejects a leading '+'
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  return ec == std::errc() && end == s.data() + s.size() && std::isfinite(value);
}

const char* columnsText(TrajectoryFormat format) {
  switch (format) {
    case TrajectoryFormat::EthObsmat:
      return "8 numbers 'frame ped x z y vx vz vy' (ETH obsmat)";
    case TrajectoryFormat::PedPy:
      return "5 numbers 'id frame x y z' (PedPy)";
    default:
      return "4 numbers 'frame ped_id x y'";
  }
}

// Which fields hold the frame, the person and the ground position (x, y).
struct Columns {
  size_t count, frame, ped, x, y;
};

Columns columnsOf(TrajectoryFormat format) {
  switch (format) {
    case TrajectoryFormat::EthObsmat:
      return {8, 0, 1, 2, 4};  // x, z (height, unused), y
    case TrajectoryFormat::PedPy:
      return {5, 1, 0, 2, 3};
    default:
      return {4, 0, 1, 2, 3};
  }
}

class LineParser {
 public:
  LineParser(const std::string& source, TrajectoryFormat format)
      : source_(source), format_(format) {}

  Sample parse(std::string_view text, size_t line) const {
    std::vector<std::string_view> fields = splitFields(text);
    const Columns c = columnsOf(format_);
    // PedPy files may carry further columns after x y z.
    const bool countOk =
        format_ == TrajectoryFormat::PedPy ? fields.size() >= c.count : fields.size() == c.count;
    if (!countOk)
      fail(source_, ":", line, ": expected ", columnsText(format_), ", got ", fields.size(),
           " field", fields.size() == 1 ? "" : "s");
    double v[8] = {};
    for (size_t k = 0; k < c.count; ++k)
      if (!parseNumber(fields[k], v[k]))
        fail(source_, ":", line, ": field ", k + 1, " '", fields[k],
             "' is not a finite number (expected ", columnsText(format_), ")");
    Sample s{integer(v[c.frame], "frame number", kMaxFrameNumber, line),
             int(integer(v[c.ped], "person id", 1e9, line)),
             {},
             line};
    if (s.frame < 0) fail(source_, ":", line, ": frame number ", s.frame, " is negative");
    s.position = glm::vec2(v[c.x] * scale_, v[c.y] * scale_);
    if (!std::isfinite(s.position.x) || !std::isfinite(s.position.y) ||
        std::abs(s.position.x) > 1e6f || std::abs(s.position.y) > 1e6f)
      fail(source_, ":", line, ": position (", v[c.x], ", ", v[c.y], ") is not within 1e6 metres");
    return s;
  }

  void setScale(double metresPerUnit) { scale_ = metresPerUnit; }

 private:
  long long integer(double value, const char* what, double limit, size_t line) const {
    if (value != std::floor(value) || std::abs(value) > limit)
      fail(source_, ":", line, ": ", what, " ", value, " is not an integer within +-", limit,
           " (expected ", columnsText(format_), ")");
    return (long long)value;
  }

  const std::string& source_;
  TrajectoryFormat format_;
  double scale_ = 1.0;  // metres per file unit
};

std::vector<std::pair<std::string_view, size_t>> dataLines(std::string_view text) {
  std::vector<std::pair<std::string_view, size_t>> lines;
  size_t number = 0, pos = 0;
  while (pos <= text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    ++number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    size_t first = line.find_first_not_of(" \t");
    if (first != std::string_view::npos && line[first] != '#') lines.emplace_back(line, number);
    if (end == text.size()) break;
    pos = end + 1;
  }
  return lines;
}

// PedPy's header: "# framerate: F" (frames per second) and the unit ("x/cm" or "in cm": cm).
struct PedPyHeader {
  double framerate = 0.0;  // 0: no framerate comment (not a PedPy file)
  size_t line = 0;
  double metresPerUnit = 1.0;
};

PedPyHeader pedPyHeader(std::string_view text, const std::string& source) {
  PedPyHeader header;
  size_t number = 0, pos = 0;
  while (pos < text.size()) {
    size_t end = std::min(text.find('\n', pos), text.size());
    std::string_view line = text.substr(pos, end - pos);
    ++number;
    pos = end + 1;
    size_t first = line.find_first_not_of(" \t");
    if (first == std::string_view::npos) continue;
    if (line[first] != '#') break;  // the header ends at the first data line
    std::string lower(line);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char ch) { return char(std::tolower(ch)); });
    if (lower.find("x/cm") != std::string::npos || lower.find("in cm") != std::string::npos)
      header.metresPerUnit = 0.01;
    size_t key = lower.find("framerate:");
    if (key == std::string::npos) continue;
    std::vector<std::string_view> rest = splitFields(line.substr(key + 10));
    double fps = 0.0;
    if (rest.empty() || !parseNumber(rest[0], fps) || !(fps > 0.0 && fps <= 10000.0))
      fail(source, ":", number,
           ": expected '# framerate: F' with 0 < F <= 10000 frames per second");
    header.framerate = fps;
    header.line = number;
  }
  return header;
}

TrajectoryFormat detectFormat(const std::string& source, std::string_view firstLine, size_t line) {
  if (source.find("obsmat") != std::string::npos) return TrajectoryFormat::EthObsmat;
  size_t fields = splitFields(firstLine).size();
  if (fields == 4) return TrajectoryFormat::FramePedXY;
  if (fields == 8) return TrajectoryFormat::EthObsmat;
  fail(source, ":", line,
       ": expected 4 numbers 'frame ped_id x y' or 8 (ETH obsmat 'frame ped x z y vx vz vy'), got ",
       fields, " fields");
}

// The most common difference between consecutive annotated frames of one person.
long long modalFrameStep(const std::map<int, std::vector<Sample>>& byPerson) {
  std::map<long long, size_t> histogram;
  for (const auto& [ped, samples] : byPerson)
    for (size_t k = 1; k < samples.size(); ++k)
      ++histogram[samples[k].frame - samples[k - 1].frame];
  long long best = 1;
  size_t bestCount = 0;
  for (auto [step, count] : histogram)
    if (count > bestCount) best = step, bestCount = count;
  return best;
}

// One person's samples as tracks, a new one after each absence longer than kMaxTrackGapSeconds.
void splitTrack(int ped, const std::vector<Sample>& samples, Trajectories& out) {
  Track track;
  track.id = ped;
  for (const Sample& s : samples) {
    const double time = double(s.frame) * out.secondsPerFrame;
    if (!track.points.empty() && time - track.points.back().time > kMaxTrackGapSeconds) {
      out.tracks.push_back(std::move(track));
      track = Track{ped, {}};
      ++out.gapSplits;
    }
    track.points.push_back({time, s.position});
  }
  out.tracks.push_back(std::move(track));
}

}  // namespace

float defaultSecondsPerStep(const std::string& source) {
  std::string name = std::filesystem::path(source).filename().string();
  return name.find("biwi_eth") != std::string::npos ? 0.667f : 0.4f;
}

double Trajectories::startTime() const {
  double t = std::numeric_limits<double>::infinity();
  for (const Track& track : tracks)
    if (!track.points.empty()) t = std::min(t, track.points.front().time);
  return std::isfinite(t) ? t : 0.0;
}

Trajectories parseTrajectories(std::string_view text, const std::string& source,
                               const TrajectoryOptions& options) {
  if (!(options.secondsPerStep >= 0.0f) || options.secondsPerStep > 60.0f)
    fail(source, ": seconds per step ", options.secondsPerStep,
         ": expected 0 (by dataset) or a positive time up to 60 s");
  const auto lines = dataLines(text);
  if (lines.empty())
    fail(source, ": no trajectory samples (expected lines of 'frame ped_id x y' or ETH obsmat)");
  Trajectories out;
  out.source = source;
  const PedPyHeader pedpy = pedPyHeader(text, source);
  out.format = options.format != TrajectoryFormat::Auto ? options.format
               : pedpy.framerate > 0.0                  ? TrajectoryFormat::PedPy
                                       : detectFormat(source, lines[0].first, lines[0].second);
  if (out.format == TrajectoryFormat::PedPy && pedpy.framerate == 0.0)
    fail(source, ":1: expected a '# framerate: F' comment before the data (PedPy format)");
  LineParser parser(source, out.format);
  parser.setScale(pedpy.metresPerUnit);
  std::map<int, std::vector<Sample>> byPerson;
  for (auto [line, number] : lines) {
    Sample s = parser.parse(line, number);
    byPerson[s.ped].push_back(s);
  }
  out.sampleCount = lines.size();
  for (auto& [ped, samples] : byPerson) {
    std::stable_sort(samples.begin(), samples.end(),
                     [](const Sample& a, const Sample& b) { return a.frame < b.frame; });
    for (size_t k = 1; k < samples.size(); ++k)
      if (samples[k].frame == samples[k - 1].frame)
        fail(source, ":", std::max(samples[k].line, samples[k - 1].line), ": person ", ped,
             " appears twice in frame ", samples[k].frame, " (first on line ",
             std::min(samples[k].line, samples[k - 1].line),
             "); expected one position per person per frame");
  }
  const long long step = modalFrameStep(byPerson);
  if (step > std::numeric_limits<int>::max())
    fail(source, ": the most common step between a person's annotated frames is ", step,
         " frames (expected at most ", std::numeric_limits<int>::max(), ")");
  out.frameStep = int(step);
  if (out.format == TrajectoryFormat::PedPy) {
    out.secondsPerFrame = 1.0 / pedpy.framerate;
    out.secondsPerStep = out.secondsPerFrame * double(out.frameStep);
  } else {
    out.secondsPerStep = double(options.secondsPerStep > 0.0f ? options.secondsPerStep
                                                              : defaultSecondsPerStep(source));
    out.secondsPerFrame = out.secondsPerStep / double(out.frameStep);
  }
  for (const auto& [ped, samples] : byPerson) splitTrack(ped, samples, out);
  return out;
}

Trajectories loadTrajectories(const std::filesystem::path& path, const TrajectoryOptions& options) {
  return parseTrajectories(readTextFile(path), path.string(), options);
}

}  // namespace throng::crowd
