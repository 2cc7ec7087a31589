#include "crowd/walls_file.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/error.h"

namespace throng::crowd {
namespace {

constexpr size_t kMaxWallsFileBytes = size_t(256) << 20;
constexpr size_t kMaxRasterCells = size_t(64) << 20;

std::vector<std::string_view> fields(std::string_view line) {
  std::vector<std::string_view> out;
  size_t k = 0;
  while (k < line.size()) {
    while (k < line.size() && (line[k] == ' ' || line[k] == '\t' || line[k] == '\r')) ++k;
    size_t end = k;
    while (end < line.size() && line[end] != ' ' && line[end] != '\t' && line[end] != '\r') ++end;
    if (end > k) out.push_back(line.substr(k, end - k));
    k = end;
  }
  return out;
}

float number(std::string_view field, std::string_view origin, size_t line) {
  float v = 0.0f;
  auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), v);
  if (ec != std::errc() || end != field.data() + field.size() || !std::isfinite(v) ||
      std::abs(v) > kMaxWallCoordinate)
    fail(origin, ":", line, ": expected a number within +-", kMaxWallCoordinate, ", got '", field,
         "'");
  return v;
}

class Parser {
 public:
  Parser(std::string_view text, std::string_view origin) : text_(text), origin_(origin) {}

  Obstacles run() {
    std::string_view line;
    while (next(line)) {
      const size_t hash = line.find('#');
      const std::vector<std::string_view> f = fields(line.substr(0, hash));
      if (f.empty()) continue;
      if (f[0] == "polyline" || f[0] == "polygon")
        polyline(f, f[0] == "polygon");
      else if (f[0] == "walkable")
        walkable(f);
      else
        fail(origin_, ":", line_, ": expected 'polyline', 'polygon' or 'walkable', got '", f[0],
             "'");
    }
    const std::vector<std::string> problems = validateObstacles(walls_);
    if (!problems.empty()) fail(origin_, ": ", problems.front());
    return std::move(walls_);
  }

 private:
  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    const size_t end = std::min(text_.find('\n', pos_), text_.size());
    line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    ++line_;
    return true;
  }

  void polyline(const std::vector<std::string_view>& f, bool closed) {
    const size_t least = closed ? 3 : 2;
    if (f.size() % 2 != 1 || (f.size() - 1) / 2 < least)
      fail(origin_, ":", line_, ": expected '", f[0], "' and at least ", least, " x z pairs, got ",
           f.size() - 1, " numbers");
    std::vector<glm::vec2> points;
    for (size_t k = 1; k + 1 < f.size(); k += 2)
      points.push_back({number(f[k], origin_, line_), number(f[k + 1], origin_, line_)});
    for (size_t k = 0; k + 1 < points.size(); ++k)
      if (glm::length(points[k + 1] - points[k]) < kMinSegmentLength)
        fail(origin_, ":", line_, ": points ", k + 1, " and ", k + 2,
             " coincide: expected distinct consecutive points");
    if (walls_.segments.size() + points.size() > kMaxSegments)
      fail(origin_, ":", line_, ": more than ", kMaxSegments, " wall segments");
    walls_.addPolyline(points, closed);
  }

  void walkable(const std::vector<std::string_view>& f) {
    if (f.size() != 4)
      fail(origin_, ":", line_, ": expected 'walkable X0 Z0 CELL', got ", f.size() - 1, " numbers");
    const size_t header = line_;
    WalkableGrid g;
    g.origin = {number(f[1], origin_, line_), number(f[2], origin_, line_)};
    g.cellSize = number(f[3], origin_, line_);
    if (!(g.cellSize > 0.0f)) fail(origin_, ":", line_, ": expected a positive cell size");
    std::string_view row;
    while (true) {
      if (!next(row)) fail(origin_, ":", header, ": expected raster rows and 'end'");
      const std::vector<std::string_view> r = fields(row);
      if (r.size() == 1 && r[0] == "end") break;
      if (r.size() != 1 || r[0].find_first_not_of(".#") != std::string_view::npos)
        fail(origin_, ":", line_, ": expected a raster row of '.' and '#', or 'end'");
      if (g.columns == 0) g.columns = uint32_t(std::min<size_t>(r[0].size(), UINT32_MAX));
      if (r[0].size() != g.columns)
        fail(origin_, ":", line_, ": expected ", g.columns, " cells like the first row, got ",
             r[0].size());
      if (g.walkable.size() + g.columns > kMaxRasterCells)
        fail(origin_, ":", line_, ": more than ", kMaxRasterCells, " raster cells");
      for (char c : r[0]) g.walkable.push_back(c == '.' ? 1 : 0);
      ++g.rows;
    }
    if (g.rows == 0) fail(origin_, ":", header, ": expected at least one raster row");
    walls_.addWalkableGrid(g);
    if (walls_.segments.size() > kMaxSegments)
      fail(origin_, ":", header, ": more than ", kMaxSegments, " wall segments");
  }

  std::string_view text_, origin_;
  size_t pos_ = 0, line_ = 0;
  Obstacles walls_;
};

}  // namespace

Obstacles parseWalls(std::string_view text, std::string_view origin) {
  return Parser(text, origin).run();
}

Obstacles loadWalls(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, ": cannot open the walls file");
  std::ostringstream text;
  text << in.rdbuf();
  if (text.str().size() > kMaxWallsFileBytes)
    fail(path, ": larger than ", kMaxWallsFileBytes, " bytes");
  return parseWalls(text.str(), path);
}

}  // namespace throng::crowd
