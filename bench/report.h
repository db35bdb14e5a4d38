// Statistics and table output of the accuracy benchmark: median / p90 / mean, markdown
// cells, and CSV files that scripts/run-accuracy.sh turns into plots.
#ifndef NVV_BENCH_REPORT_H
#define NVV_BENCH_REPORT_H

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "test_support.h"

namespace nvv_bench {

// median / p90 / mean (and max) are the tests' nvv_test::StatsOf; an empty set has NaN in
// every field here, so tables print "–" and CSV files "nan" instead of a misleading 0.
typedef nvv_test::Stats Stat3;
inline Stat3 Stats(const std::vector<double>& v) {
  Stat3 s = nvv_test::StatsOf(v);
  if (s.n == 0) s.median = s.p90 = s.mean = s.max = NAN;
  return s;
}
inline std::string Num(double x) {
  char b[32];
  if (!std::isfinite(x)) return "–";
  std::snprintf(b, sizeof b, x >= 100 ? "%.0f" : x >= 10 ? "%.1f" : "%.2f", x);
  return b;
}
// "median / p90 / mean"
inline std::string Cell(const Stat3& s) {
  if (s.n == 0) return "–";
  return Num(s.median) + " / " + Num(s.p90) + " / " + Num(s.mean);
}

// Appends rows to a CSV file in the output folder (the folder is created by the caller).
class Csv {
 public:
  Csv(const std::string& dir, const std::string& name, const std::string& header)
      : f_(std::fopen((dir + "/" + name).c_str(), "w")) {
    if (!f_) {  // every section writes its rows unchecked: stop here, not in a null FILE*
      std::fprintf(stderr, "cannot write %s/%s (does the output folder exist?)\n", dir.c_str(), name.c_str());
      std::exit(2);
    }
    std::fprintf(f_, "%s\n", header.c_str());
  }
  ~Csv() { if (f_) std::fclose(f_); }
  FILE* f() { return f_; }

 private:
  FILE* f_;
};

}  // namespace nvv_bench

#endif
