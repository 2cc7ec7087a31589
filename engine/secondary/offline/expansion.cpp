#include "secondary/offline/expansion.h"

#include "core/binary_io.h"
#include "core/error.h"

namespace throng::secondary {
namespace {
constexpr char kTaskMagic[] = "THRNGXTK";
constexpr char kResultMagic[] = "THRNGXRS";

void checkCloth(const ClothState& c, size_t vertices, uint32_t node) {
  if (c.positions.size() != vertices || c.velocities.size() != vertices)
    fail("simulator returned ", c.positions.size(), " positions and ", c.velocities.size(),
         " velocities at primary node ", node, ", expected ", vertices);
}

// Frames laid end to end: the cloth of each record, then split again on decode.
void addFrames(ChunkWriter& w, const char* posTag, const char* velTag,
               const std::vector<const ClothState*>& frames) {
  std::vector<glm::vec3> p, v;
  for (const ClothState* c : frames) {
    p.insert(p.end(), c->positions.begin(), c->positions.end());
    v.insert(v.end(), c->velocities.begin(), c->velocities.end());
  }
  w.add(posTag, p);
  w.add(velTag, v);
}

ClothState sliceFrame(const std::vector<glm::vec3>& p, const std::vector<glm::vec3>& v, size_t i,
                      size_t vertices) {
  ClothState c;
  c.positions.assign(p.begin() + i * vertices, p.begin() + (i + 1) * vertices);
  c.velocities.assign(v.begin() + i * vertices, v.begin() + (i + 1) * vertices);
  return c;
}
}  // namespace

ExpansionResult simulateExpansion(const PrimaryGraph& primary, const StepFunction& step,
                                  const ExpansionTask& task) {
  THRONG_CHECK(task.node < primary.nodes.size() && task.edge < primary.successors[task.node].size(),
               "expansion from node ", task.node, " edge ", task.edge);
  const size_t vertices = task.start.positions.size();
  ExpansionResult r;
  const uint32_t first = primary.successors[task.node][task.edge];
  r.states.push_back({first, kFromTaskStart, task.edge, step(task.start, task.node, first)});
  checkCloth(r.states[0].cloth, vertices, first);

  // BFS by levels; each state's children in successor order, so the result is deterministic.
  std::vector<std::vector<bool>> expanded(1);
  size_t levelBegin = 0;
  for (uint32_t level = 0; level < task.depth; ++level) {
    const size_t levelEnd = r.states.size();
    for (size_t i = levelBegin; i < levelEnd; ++i) {
      const uint32_t node = r.states[i].node;
      expanded[i].assign(primary.successors[node].size(), false);
      for (uint32_t k = 0; k < primary.successors[node].size() && r.states.size() < task.maxStates;
           ++k) {
        const uint32_t next = primary.successors[node][k];
        ClothState cloth = step(r.states[i].cloth, node, next);
        checkCloth(cloth, vertices, next);
        r.states.push_back({next, uint32_t(i), k, std::move(cloth)});
        expanded[i][k] = true;
      }
    }
    expanded.resize(r.states.size());
    levelBegin = levelEnd;
  }
  if (!task.deadEndFrames) return r;
  for (size_t i = 0; i < r.states.size(); ++i) {
    const uint32_t node = r.states[i].node;
    for (uint32_t k = 0; k < primary.successors[node].size(); ++k) {
      if (k < expanded[i].size() && expanded[i][k]) continue;
      const uint32_t next = primary.successors[node][k];
      ClothState cloth = step(r.states[i].cloth, node, next);
      checkCloth(cloth, vertices, next);
      r.deadEnds.push_back({uint32_t(i), k, std::move(cloth)});
    }
  }
  return r;
}

std::vector<uint8_t> encodeTask(const ExpansionTask& task) {
  ChunkWriter w(kTaskMagic, 1);
  const uint32_t header[5] = {task.node, task.edge, task.depth, task.maxStates,
                              task.deadEndFrames ? 1u : 0u};
  w.add("TASK", std::span<const uint32_t>(header));
  addFrames(w, "POSN", "VELO", {&task.start});
  return w.bytes();
}

ExpansionTask decodeTask(std::vector<uint8_t> bytes) {
  ChunkReader r = ChunkReader::fromBytes(std::move(bytes), "expansion task message", kTaskMagic, 1,
                                         "expansion task");
  const std::vector<uint32_t> h = r.vector<uint32_t>("TASK");
  r.expectCount(r.require("TASK"), 5);
  ExpansionTask t;
  t.node = h[0];
  t.edge = h[1];
  t.depth = h[2];
  t.maxStates = h[3];
  t.deadEndFrames = h[4] != 0;
  t.start.positions = r.vector<glm::vec3>("POSN");
  t.start.velocities = r.vector<glm::vec3>("VELO");
  return t;
}

std::vector<uint8_t> encodeResult(const ExpansionResult& result) {
  ChunkWriter w(kResultMagic, 1);
  std::vector<uint32_t> states, deadEnds;
  std::vector<const ClothState*> frames;
  for (const ExpansionState& s : result.states) {
    states.insert(states.end(), {s.node, s.parent, s.parentEdge});
    frames.push_back(&s.cloth);
  }
  for (const ExpansionDeadEnd& d : result.deadEnds) {
    deadEnds.insert(deadEnds.end(), {d.state, d.edge});
    frames.push_back(&d.cloth);
  }
  const uint32_t vertices =
      result.states.empty() ? 0 : uint32_t(result.states[0].cloth.positions.size());
  w.addScalar("VERT", vertices);
  w.add("STAT", states);
  w.add("DEAD", deadEnds);
  addFrames(w, "POSN", "VELO", frames);
  return w.bytes();
}

ExpansionResult decodeResult(std::vector<uint8_t> bytes) {
  ChunkReader r = ChunkReader::fromBytes(std::move(bytes), "expansion result message", kResultMagic,
                                         1, "expansion result");
  const uint32_t vertices = r.scalar<uint32_t>("VERT");
  const std::vector<uint32_t> states = r.vector<uint32_t>("STAT");
  const std::vector<uint32_t> deadEnds = r.vector<uint32_t>("DEAD");
  const std::vector<glm::vec3> p = r.vector<glm::vec3>("POSN");
  const std::vector<glm::vec3> v = r.vector<glm::vec3>("VELO");
  const size_t frames = states.size() / 3 + deadEnds.size() / 2;
  if (states.size() % 3 || deadEnds.size() % 2 || p.size() != frames * vertices ||
      v.size() != p.size())
    fail(r.name(), ": inconsistent record counts");
  ExpansionResult result;
  size_t f = 0;
  for (size_t i = 0; i < states.size(); i += 3)
    result.states.push_back(
        {states[i], states[i + 1], states[i + 2], sliceFrame(p, v, f++, vertices)});
  for (size_t i = 0; i < deadEnds.size(); i += 2)
    result.deadEnds.push_back({deadEnds[i], deadEnds[i + 1], sliceFrame(p, v, f++, vertices)});
  return result;
}

}  // namespace throng::secondary
