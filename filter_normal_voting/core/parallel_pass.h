// A pass of the core: a body run for every vertex in parallel (OpenMP), with progress, cancelling
// and out-of-memory handling shared by every stage. Used by the stages' .cpp files only.
#ifndef NVV_CORE_PARALLEL_PASS_H
#define NVV_CORE_PARALLEL_PASS_H

#include <algorithm>
#include <atomic>
#include <chrono>
#include <functional>

#include "surface_graph.h"
#include "threads.h"

namespace nvv {

// Progress in percent with a short text; return false to cancel. A vcg::CallBackPos*
// converts to it.
typedef std::function<bool(int, const char*)> Progress;

// How a pass ended.
enum class PassEnd { Done, Cancelled, OutOfMemory };

// Shared progress / cancellation state of one parallel pass, reported as `percentFrom` ..
// `percentTo` of the whole run. Only thread 0 (the caller's thread) calls the user's callback:
// GUIs pump their event loop inside it.
class PassProgress {
 public:
  PassProgress(const Progress& cb, int n, int percentFrom, int percentTo, const char* text)
      : cb_(cb), n_(n), from_(percentFrom), to_(percentTo), text_(text) {}
  bool Cancelled() const { return cancelled_.load(std::memory_order_relaxed); }
  void Cancel() { cancelled_.store(true); }
  // Called by each thread after every few vertices (`count` of them since its last call).
  void Tick(bool mainThread, int count) {
    const int done = done_.fetch_add(count, std::memory_order_relaxed) + count;
    if (!mainThread || !cb_) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    const int percent = from_ + int((to_ - from_) * double(done) / std::max(1, n_));
    if (!cb_(percent, text_)) Cancel();
  }

 private:
  const Progress& cb_;
  const int n_, from_, to_;
  const char* text_;
  std::atomic<int> done_{0};
  std::atomic<bool> cancelled_{false};
  std::chrono::steady_clock::time_point last_{};
};

// Runs body(v, scratch) for every vertex in parallel, one Scratch(g) per thread, in index
// order: consecutive vertices of scanned and generated meshes are near each other, so
// consecutive neighbourhoods reuse what the last one brought into cache.
template <class Scratch, class Body>
PassEnd ParallelOverVertices(const SurfaceGraph& g, int threads, PassProgress& progress, Body body) {
  const int n = g.VertexCount();
  std::atomic<bool> failed{false};
#pragma omp parallel num_threads(threads)
  {
    try {
      Scratch scratch(g);
      const bool mainThread = ThreadId() == 0;
      // Progress is counted in batches: one shared atomic add per vertex made the threads fight
      // over its cache line in passes where most vertices have nothing to do.
      constexpr int kTickBatch = 16;
      int pending = 0;
#pragma omp for schedule(dynamic, 64)
      for (int v = 0; v < n; ++v) {
        if (progress.Cancelled() || failed.load(std::memory_order_relaxed)) continue;
        body(v, scratch);
        if (++pending == kTickBatch) {
          progress.Tick(mainThread, pending);
          pending = 0;
        }
      }
      if (pending > 0) progress.Tick(mainThread, pending);
    } catch (...) {  // bad_alloc: never let an exception cross the OpenMP region
      failed.store(true);
    }
  }
  if (failed.load()) return PassEnd::OutOfMemory;
  return progress.Cancelled() ? PassEnd::Cancelled : PassEnd::Done;
}

}  // namespace nvv

#endif
