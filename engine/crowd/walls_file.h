#pragma once
// The walls text format (docs/formats.md, "Walls"): one obstacle per line, `polyline` or
// `polygon` followed by x z pairs in metres, and `walkable X0 Z0 CELL` followed by raster rows
// of '.' (walkable) and '#' (blocked) up to `end`; '#' starts a comment elsewhere.
#include <string>
#include <string_view>

#include "crowd/obstacles.h"

namespace throng::crowd {

// Throws Error "ORIGIN:LINE: what was expected" for a malformed line, and for walls that fail
// validateObstacles.
Obstacles parseWalls(std::string_view text, std::string_view origin);
Obstacles loadWalls(const std::string& path);

}  // namespace throng::crowd
