#pragma once
// What a storyboard says about its crowd: density and the heading/state/action mix. Quilting
// reports these for the sample and the output so a person can see the mix is kept.
#include <array>
#include <span>
#include <string>

#include "storyboard/glyph.h"

namespace throng::storyboard {

struct StoryboardStats {
  int agents = 0;
  double area = 0;     // px²
  double density = 0;  // agents per 1000 px²
  // Shares summing to 1 (all 0 without agents).
  std::array<double, kHeadingCount> headings{};
  std::array<double, kStateCount> states{};
  std::array<double, kActionCount> actions{};
};

StoryboardStats computeStats(std::span<const Glyph> glyphs, double area);
// Half the L1 distance between two distributions: 0 identical, 1 disjoint.
double totalVariation(std::span<const double> a, std::span<const double> b);
// A few readable lines; with `reference`, each share is followed by the reference's.
std::string formatStats(const StoryboardStats& stats, const StoryboardStats* reference = nullptr);

}  // namespace throng::storyboard
