#include "synth/cpu_synth.h"

#include <exception>
#include <functional>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

#include "core/error.h"

namespace throng::synth {

void parallelFor(size_t count, unsigned threads, const std::function<void(size_t, size_t)>& body) {
  threads =
      std::max(1u, std::min<unsigned>(threads, static_cast<unsigned>(std::max<size_t>(count, 1))));
  if (threads == 1) {
    body(0, count);
    return;
  }
  // An exception may not leave a thread (std::terminate): the first is kept and rethrown here,
  // after every started thread has joined. A range whose thread could not start runs here.
  std::mutex mutex;
  std::exception_ptr error;
  const auto run = [&](size_t begin, size_t end) {
    try {
      body(begin, end);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(mutex);
      if (!error) error = std::current_exception();
    }
  };
  std::vector<std::thread> workers;
  std::vector<std::pair<size_t, size_t>> unstarted;
  workers.reserve(threads);  // no allocation failure once threads run
  unstarted.reserve(threads);
  const size_t chunk = (count + threads - 1) / threads;
  for (unsigned t = 0; t < threads; ++t) {
    const size_t begin = t * chunk, end = std::min(count, begin + chunk);
    if (begin >= end) break;
    try {
      workers.emplace_back(run, begin, end);
    } catch (const std::system_error&) {
      unstarted.emplace_back(begin, end);
    }
  }
  for (const auto& [begin, end] : unstarted) run(begin, end);
  for (std::thread& w : workers) w.join();
  if (error) std::rethrow_exception(error);
}

void stepCrowdCpu(const anim::MotionPair& pair, crowd::Crowd& crowd, float dt, unsigned threads,
                  const anim::SpeedRetarget& retarget) {
  stepCrowdCpu(pair, crowd, {0, crowd.size()}, dt, threads, retarget);
}

void stepCrowdCpu(const anim::MotionPair& pair, crowd::Crowd& crowd, CharacterRange range, float dt,
                  unsigned threads, const anim::SpeedRetarget& retarget) {
  THRONG_CHECK(range.first + range.count <= crowd.size(), "range runs past the crowd's ",
               crowd.size(), " characters");
  parallelFor(range.count, threads, [&](size_t begin, size_t end) {
    for (size_t i = range.first + begin; i < range.first + end; ++i)
      anim::stepCharacter(pair, crowd.placement[i], crowd.motion[i], dt, crowd.steering, retarget,
                          static_cast<uint32_t>(i));
  });
}

void poseCrowdCpu(const anim::MotionPair& pair, const crowd::Crowd& crowd,
                  std::span<JointPoint> out, unsigned threads) {
  poseCrowdCpu(pair, crowd, {0, crowd.size()}, out, threads);
}

void poseCrowdCpu(const anim::MotionPair& pair, const crowd::Crowd& crowd, CharacterRange range,
                  std::span<JointPoint> out, unsigned threads) {
  const size_t joints = static_cast<size_t>(pair.jointCount());
  const size_t end = range.first + range.count;
  THRONG_CHECK(end <= crowd.size(), "range runs past the crowd's ", crowd.size(), " characters");
  THRONG_CHECK(out.size() >= end * joints, "joint point output holds ", out.size(), ", needs ",
               end * joints);
  parallelFor(range.count, threads, [&](size_t begin, size_t stop) {
    for (size_t i = range.first + begin; i < range.first + stop; ++i) {
      auto* points = reinterpret_cast<glm::vec4*>(&out[i * joints]);
      anim::poseCharacter(pair, crowd.placement[i], crowd.motion[i],
                          std::span<glm::vec4>(points, joints));
    }
  });
}

}  // namespace throng::synth
