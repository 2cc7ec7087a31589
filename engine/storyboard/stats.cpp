#include "storyboard/stats.h"

#include <cmath>
#include <cstdio>

#include "core/error.h"

namespace throng::storyboard {

StoryboardStats computeStats(std::span<const Glyph> glyphs, double area) {
  StoryboardStats stats;
  stats.agents = int(glyphs.size());
  stats.area = area;
  stats.density = area > 0 ? 1000.0 * double(glyphs.size()) / area : 0.0;
  if (glyphs.empty()) return stats;
  const double share = 1.0 / double(glyphs.size());
  for (const Glyph& g : glyphs) {
    stats.headings[int(g.heading)] += share;
    stats.states[int(g.state)] += share;
    stats.actions[int(g.action)] += share;
  }
  return stats;
}

double totalVariation(std::span<const double> a, std::span<const double> b) {
  THRONG_CHECK(a.size() == b.size(), "distributions of different sizes");
  double sum = 0;
  for (size_t i = 0; i < a.size(); ++i) sum += std::fabs(a[i] - b[i]);
  return 0.5 * sum;
}

namespace {
template <size_t N>
std::string shares(const char* title, const std::array<double, N>& values, const std::array<double, N>* reference,
                   std::string_view (*nameOf)(int)) {
  std::string line = concat("  ", title, ":");
  for (size_t i = 0; i < N; ++i) {
    char text[64];
    if (reference) std::snprintf(text, sizeof text, " %.0f%% (%.0f%%)", 100 * values[i], 100 * (*reference)[i]);
    else std::snprintf(text, sizeof text, " %.0f%%", 100 * values[i]);
    line += concat(" ", nameOf(int(i)), text);
  }
  if (reference) {
    char tv[48];
    std::snprintf(tv, sizeof tv, "  [TV distance %.3f]", totalVariation(values, *reference));
    line += tv;
  }
  return line + "\n";
}
}  // namespace

std::string formatStats(const StoryboardStats& stats, const StoryboardStats* reference) {
  char head[160];
  if (reference)
    std::snprintf(head, sizeof head, "  agents %d, density %.2f per 1000 px^2 (sample %.2f, %+.1f%%)\n", stats.agents,
                  stats.density, reference->density,
                  reference->density > 0 ? 100.0 * (stats.density / reference->density - 1.0) : 0.0);
  else
    std::snprintf(head, sizeof head, "  agents %d, density %.2f per 1000 px^2\n", stats.agents, stats.density);
  return head + shares("headings", stats.headings, reference ? &reference->headings : nullptr,
                       [](int i) { return headingName(Heading(i)); }) +
         shares("states", stats.states, reference ? &reference->states : nullptr,
                [](int i) { return stateName(State(i)); }) +
         shares("actions", stats.actions, reference ? &reference->actions : nullptr,
                [](int i) { return actionName(Action(i)); });
}

}  // namespace throng::storyboard
