// The core's OpenMP thread count and id, with serial fallbacks when built without OpenMP.
#ifndef NVV_CORE_THREADS_H
#define NVV_CORE_THREADS_H

#ifdef _OPENMP
#include <omp.h>
#endif

namespace nvv {

// `requested` threads, or all OpenMP offers when requested <= 0.
inline int ThreadCount(int requested) {
#ifdef _OPENMP
  return requested > 0 ? requested : omp_get_max_threads();
#else
  (void)requested;
  return 1;
#endif
}

inline int ThreadId() {
#ifdef _OPENMP
  return omp_get_thread_num();
#else
  return 0;
#endif
}

}  // namespace nvv

#endif
