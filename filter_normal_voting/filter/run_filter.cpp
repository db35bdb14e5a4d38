#include "run_filter.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace nvv {

std::string CheckOutputPath(const std::string& path, const std::string& what) {
  const std::string prefix = "cannot write " + what + " '" + path + "': ";
  const std::size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
  if (::access(dir.c_str(), W_OK) != 0) return prefix + std::strerror(errno) + " (" + dir + ")";
  struct stat st;
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) return prefix + "it is a directory";
  return std::string();
}

std::string SettingsLine(const FilterOptions& o, const Summary& s) {
  char buf[640];
  std::snprintf(buf, sizeof buf,
                "Normal vector voting: neighbourhood k = %g mean edge lengths%s -> absolute radius %g; "
                "crease angle %g deg (epsilon %.4g), corner angle %g deg (eta %.4g), %s; noise along the normals "
                "estimated at %.2g %% of the mean edge length",
                s.k, s.autoK ? " (chosen from the noise)" : "", s.radius, o.core.creaseAngleDeg, s.epsilon,
                o.core.cornerAngleDeg, s.eta, s.signAwareUsed ? "sign-aware rule" : "paper's rule",
                100.0 * s.noiseOverEdge);
  return buf;
}

}  // namespace nvv
