// nvv_mlx: prints a MeshLab 2020.09 filter script (.mlx) that runs the filter with every
// parameter at its default, or as given.
//
// Usage: nvv_mlx [name=value ...] > script.mlx     (e.g. nvv_mlx neighbourhood_k=5 color=1)
#include <cstdio>
#include <map>
#include <string>

#include "filter/mlx_script.h"

int main(int argc, char** argv) {
  std::map<std::string, std::string> values;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const std::size_t eq = a.find('=');
    if (eq == std::string::npos || !nvv::FindParam(a.substr(0, eq), nvv::MeshLabParameterTable())) {
      std::fprintf(stderr, "nvv_mlx: expected name=value with a parameter name of the filter, got '%s'\n", argv[i]);
      return 2;
    }
    values[a.substr(0, eq)] = a.substr(eq + 1);
  }
  std::fputs(nvv::MlxScript(values).c_str(), stdout);
  return 0;
}
