#pragma once
// The exploration on Open MPI (issue 7 part 7): every rank runs the same command under
// mpirun; rank 0 owns the graph and the merge queue and hands expansion tasks (start cloth
// state + primary edge + depth) to the other ranks, which rebuild the simulator from the
// garment rank 0 sends them and return the simulated states. Results are applied on rank 0 in
// the sequential order, so the graph is the threaded run's for the same budget and seed.
#include <memory>

#include "secondary/offline/explore.h"
#include "secondary/offline/garment.h"

namespace throng::secondary::mpi {

// MPI_Init for the life of the object; on rank 0 the destructor also releases the workers
// (even when the run failed), then MPI_Finalize.
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  int rank_ = 0;
  int size_ = 1;
};

// Rank 0's runner: sends the garment (config, primary graph, mesh) to ranks 1…size−1, then runs
// each batch on them, one task per rank at a time.
class MpiRunner final : public ExpansionRunner {
 public:
  MpiRunner(const MpiSession& session, const Garment& garment);
  std::vector<ExpansionResult> run(const std::vector<ExpansionTask>& tasks) override;
  unsigned workers() const override { return unsigned(workers_); }

 private:
  int workers_ = 0;
};

// Ranks > 0: serve tasks until rank 0 releases them. Simulator errors go back to rank 0, which
// throws them.
void runWorker(const MpiSession& session);

}  // namespace throng::secondary::mpi
