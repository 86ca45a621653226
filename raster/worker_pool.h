// A small pool of rasterizer threads. parallelFor hands out job indices (tiles) from an atomic
// counter; the calling thread works too. Jobs write disjoint memory (one tile each), so the
// result does not depend on which thread ran which tile: output is identical for any count.
#pragma once

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace pf {

class WorkerPool {
 public:
  // `threads` in all, the caller's included (>= 1); fewer where the system cannot start them all.
  explicit WorkerPool(int threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int threadCount() const { return static_cast<int>(workers_.size()) + 1; }
  // Runs fn(job, worker) for job in [0, jobs); worker in [0, threadCount()). Returns when all ran.
  // If a job throws, no further jobs start and the first exception is rethrown here.
  void parallelFor(int jobs, const std::function<void(int job, int worker)>& fn);

 private:
  void workerLoop(int worker);
  void drain(int worker);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(int, int)>* fn_ = nullptr;
  int jobs_ = 0;
  int next_job_ = 0;
  int busy_ = 0;
  unsigned generation_ = 0;
  bool stopping_ = false;
  std::exception_ptr failure_;  // the first job's exception in this parallelFor
};

// The thread count a context uses when it is not told: PF_NUM_THREADS, else all cores.
int defaultThreadCount();

}  // namespace pf
