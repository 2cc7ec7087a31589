#include "secondary/mpi/explore_mpi.h"

#include <mpi.h>

#include <chrono>
#include <climits>
#include <string>
#include <thread>

#include "core/binary_io.h"
#include "core/error.h"
#include "secondary/offline/explore_file.h"
#include "secondary/offline/primary_graph.h"

namespace throng::secondary::mpi {
namespace {
enum Tag : int { kSetup = 1, kTask = 2, kResult = 3, kError = 4, kStop = 5 };
constexpr std::string_view kSetupMagic = "THRNGXSU";

void check(int code, const char* what) {
  if (code != MPI_SUCCESS) {
    char text[MPI_MAX_ERROR_STRING];
    int length = 0;
    MPI_Error_string(code, text, &length);
    fail("MPI ", what, " failed: ", std::string(text, size_t(length)));
  }
}

void sendBytes(const std::vector<uint8_t>& bytes, int dest, int tag) {
  if (bytes.size() > size_t(INT_MAX)) fail("MPI message of ", bytes.size(), " bytes is too large");
  check(MPI_Send(bytes.data(), int(bytes.size()), MPI_BYTE, dest, tag, MPI_COMM_WORLD), "send");
}

struct Message {
  int source = 0;
  int tag = 0;
  std::vector<uint8_t> bytes;
};

// Polls instead of blocking so an idle rank sleeps rather than spinning a core (Open MPI's
// blocking calls busy-wait), which matters when ranks share cores with the simulation.
Message receive(int source) {
  MPI_Status status;
  int ready = 0;
  const auto start = std::chrono::steady_clock::now();
  for (;;) {
    check(MPI_Iprobe(source, MPI_ANY_TAG, MPI_COMM_WORLD, &ready, &status), "probe");
    if (ready) break;
    if (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(2))
      std::this_thread::yield();
    else
      std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  int count = 0;
  check(MPI_Get_count(&status, MPI_BYTE, &count), "get count");
  Message m{status.MPI_SOURCE, status.MPI_TAG, std::vector<uint8_t>(size_t(count))};
  check(
      MPI_Recv(m.bytes.data(), count, MPI_BYTE, m.source, m.tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
      "receive");
  return m;
}

std::vector<uint8_t> encodeSetup(const Garment& garment) {
  ChunkWriter w(kSetupMagic, 1);
  w.addString("CONF", garment.config.dump());
  addPrimaryGraphChunks(w, *garment.primary);
  addClothMeshChunks(w, *garment.mesh);
  return w.bytes();
}

Garment decodeSetup(std::vector<uint8_t> bytes) {
  const ChunkReader r = ChunkReader::fromBytes(std::move(bytes), "MPI setup message", kSetupMagic,
                                               1, "exploration setup");
  return restoreGarment(nlohmann::json::parse(r.string("CONF")), readPrimaryGraphChunks(r),
                        readClothMeshChunks(r));
}

std::vector<uint8_t> textBytes(const std::string& text) {
  return {text.begin(), text.end()};
}
}  // namespace

MpiSession::MpiSession() {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) check(MPI_Init(nullptr, nullptr), "init");
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
  if (rank_ == 0)
    for (int r = 1; r < size_; ++r) MPI_Send(nullptr, 0, MPI_BYTE, r, kStop, MPI_COMM_WORLD);
  MPI_Finalize();
}

MpiRunner::MpiRunner(const MpiSession& session, const Garment& garment)
    : workers_(session.size() - 1) {
  if (session.rank() != 0) fail("the MPI runner lives on rank 0");
  if (workers_ < 1)
    fail(
        "--mpi needs at least 2 ranks (rank 0 owns the graph, the others simulate): mpirun -np 2 "
        "throng cloth explore --mpi …");
  const std::vector<uint8_t> setup = encodeSetup(garment);
  for (int r = 1; r <= workers_; ++r) sendBytes(setup, r, kSetup);
}

std::vector<ExpansionResult> MpiRunner::run(const std::vector<ExpansionTask>& tasks) {
  std::vector<ExpansionResult> results(tasks.size());
  std::vector<int64_t> holding(size_t(workers_) + 1, -1);
  size_t next = 0, outstanding = 0;
  std::string error;
  auto hand = [&](int rank) {
    if (next >= tasks.size() || !error.empty()) return;
    sendBytes(encodeTask(tasks[next]), rank, kTask);
    holding[size_t(rank)] = int64_t(next++);
    ++outstanding;
  };
  for (int r = 1; r <= workers_; ++r) hand(r);
  // Every task handed out is collected, even after an error, so no message is left in flight.
  while (outstanding) {
    Message m = receive(MPI_ANY_SOURCE);
    if (m.source < 1 || m.source > workers_ || holding[size_t(m.source)] < 0 ||
        (m.tag != kResult && m.tag != kError))
      fail("MPI: unexpected message (tag ", m.tag, ") from rank ", m.source);
    const size_t index = size_t(holding[size_t(m.source)]);
    holding[size_t(m.source)] = -1;
    --outstanding;
    if (m.tag == kResult)
      results[index] = decodeResult(std::move(m.bytes));
    else if (error.empty())
      error = concat("rank ", m.source, ": ", std::string(m.bytes.begin(), m.bytes.end()));
    hand(m.source);
  }
  if (!error.empty()) fail(error);
  return results;
}

void runWorker(const MpiSession& session) {
  std::unique_ptr<Garment> garment;
  std::string setupError;
  for (;;) {
    Message m = receive(0);
    if (m.tag == kStop) return;
    if (m.tag == kSetup) {
      try {
        garment = std::make_unique<Garment>(decodeSetup(std::move(m.bytes)));
      } catch (const std::exception& e) {
        setupError = e.what();
      }
      continue;
    }
    if (m.tag != kTask) fail("MPI rank ", session.rank(), ": unexpected message tag ", m.tag);
    try {
      if (!garment) fail(setupError.empty() ? "no garment received" : setupError);
      const ExpansionTask task = decodeTask(std::move(m.bytes));
      sendBytes(encodeResult(simulateExpansion(*garment->primary, garment->step, task)), 0,
                kResult);
    } catch (const std::exception& e) {
      sendBytes(textBytes(e.what()), 0, kError);
    }
  }
}

}  // namespace throng::secondary::mpi
