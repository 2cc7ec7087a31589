#include "synth/cpu_synth.h"

#include <functional>
#include <thread>
#include <vector>

#include "core/error.h"

namespace throng::synth {

void parallelFor(size_t count, unsigned threads, const std::function<void(size_t, size_t)>& body) {
  threads = std::max(1u, std::min<unsigned>(threads, static_cast<unsigned>(std::max<size_t>(count, 1))));
  if (threads == 1) {
    body(0, count);
    return;
  }
  std::vector<std::thread> workers;
  size_t chunk = (count + threads - 1) / threads;
  for (unsigned t = 0; t < threads; ++t) {
    size_t begin = t * chunk, end = std::min(count, begin + chunk);
    if (begin >= end) break;
    workers.emplace_back(body, begin, end);
  }
  for (std::thread& w : workers) w.join();
}

void stepCrowdCpu(const anim::MotionPair& pair, crowd::Crowd& crowd, float dt, unsigned threads,
                  const anim::SpeedRetarget& retarget) {
  parallelFor(crowd.size(), threads, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i)
      anim::stepCharacter(pair, crowd.placement[i], crowd.motion[i], dt, crowd.steering, retarget,
                          static_cast<uint32_t>(i));
  });
}

void poseCrowdCpu(const anim::MotionPair& pair, const crowd::Crowd& crowd, std::span<JointMatrix> out,
                  unsigned threads) {
  const size_t joints = static_cast<size_t>(pair.jointCount());
  THRONG_CHECK(out.size() >= crowd.size() * joints, "joint matrix output holds ", out.size(), ", needs ",
               crowd.size() * joints);
  parallelFor(crowd.size(), threads, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      auto* rows = reinterpret_cast<glm::vec4*>(&out[i * joints]);
      anim::poseCharacter(pair, crowd.placement[i], crowd.motion[i], std::span<glm::vec4>(rows, 3 * joints));
    }
  });
}

}  // namespace throng::synth
