// The rasterizer's thread pool (see worker_pool.h). Job indices are taken under the mutex:
// tiles are coarse (64x64 pixels), so the lock is never the bottleneck, and TSan sees plainly
// ordered accesses.
#include "raster/worker_pool.h"

#include <cstdlib>
#include <new>
#include <system_error>
#include <utility>

namespace pf {

int defaultThreadCount() {
  if (const char* env = std::getenv("PF_NUM_THREADS")) {
    char* end = nullptr;
    long n = std::strtol(env, &end, 10);
    if (end != env && n >= 1 && n <= 256) return static_cast<int>(n);
  }
  unsigned hc = std::thread::hardware_concurrency();
  return hc == 0 ? 1 : static_cast<int>(hc > 256 ? 256 : hc);
}

WorkerPool::WorkerPool(int threads) {
  if (threads < 1) threads = 1;
  // The system may refuse threads (a process or memory limit: std::system_error): the pool then
  // runs with those it could start -- the frames are the same with any number of threads.
  try {
    workers_.reserve(static_cast<size_t>(threads - 1));
    for (int i = 1; i < threads; ++i) workers_.emplace_back([this, i] { workerLoop(i); });
  } catch (const std::system_error&) {
  } catch (const std::bad_alloc&) {
  }
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : workers_) t.join();
}

void WorkerPool::drain(int worker) {
  for (;;) {
    int job;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (next_job_ >= jobs_) return;
      job = next_job_++;
    }
    try {
      (*fn_)(job, worker);
    } catch (...) {
      // The first failure (a failed allocation, say) stops the hand-out; parallelFor rethrows it
      // on the calling thread once every worker is idle. No exception leaves a worker thread.
      std::lock_guard<std::mutex> lock(mutex_);
      if (!failure_) failure_ = std::current_exception();
      next_job_ = jobs_;
    }
  }
}

void WorkerPool::workerLoop(int worker) {
  unsigned seen = 0;
  for (;;) {
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) return;
      seen = generation_;
      ++busy_;
    }
    drain(worker);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      --busy_;
    }
    done_.notify_all();
  }
}

void WorkerPool::parallelFor(int jobs, const std::function<void(int, int)>& fn) {
  if (jobs <= 0) return;
  if (workers_.empty() || jobs == 1) {
    for (int j = 0; j < jobs; ++j) fn(j, 0);
    return;
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    fn_ = &fn;
    jobs_ = jobs;
    next_job_ = 0;
    ++generation_;
  }
  wake_.notify_all();
  drain(0);
  std::unique_lock<std::mutex> lock(mutex_);
  done_.wait(lock, [&] { return next_job_ >= jobs_ && busy_ == 0; });
  fn_ = nullptr;
  if (failure_) std::rethrow_exception(std::exchange(failure_, nullptr));
}

}  // namespace pf
