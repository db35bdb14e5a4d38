// Statistics and table output of the accuracy benchmark: median / p90 / mean, markdown
// cells, and CSV files that scripts/run-accuracy.sh turns into plots.
#ifndef NVV_BENCH_REPORT_H
#define NVV_BENCH_REPORT_H

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace nvv_bench {

struct Stat3 {
  double median = NAN, p90 = NAN, mean = NAN;
  std::size_t n = 0;
};
inline Stat3 Stats(std::vector<double> v) {
  Stat3 s;
  s.n = v.size();
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  s.median = v[v.size() / 2];
  s.p90 = v[std::min(v.size() - 1, std::size_t(0.9 * v.size()))];
  double sum = 0;
  for (double x : v) sum += x;
  s.mean = sum / v.size();
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
    if (f_) std::fprintf(f_, "%s\n", header.c_str());
  }
  ~Csv() { if (f_) std::fclose(f_); }
  FILE* f() { return f_; }

 private:
  FILE* f_;
};

}  // namespace nvv_bench

#endif
