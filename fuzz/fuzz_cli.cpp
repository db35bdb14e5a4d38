// libFuzzer target over the whole command-line path of `nvv` (cli/cli_main.h): arguments,
// reader, filter and result PLY, as a user runs them. The input is
//   byte 0            the file's format: its low two bits pick .ply, .obj, .off or .stl
//   bytes 1 .. '\n'   the options, split at spaces (at most kMaxOptions of them)
//   the rest          the mesh file's bytes
// Each run writes the file into a private folder, calls nvv_cli::Main with
// `--threads 1 --quiet <options> <file> <out.ply>`, and checks what docs/cli.md promises:
// an exit code of 0, 2, 3, 4 or 5, and on 0 a result file (--help and --version, which write
// none, are left out of the options). Any crash, sanitizer report, hang or
// other exit code is a finding.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli/cli_main.h"

namespace {

constexpr std::size_t kMaxOptions = 12;

const std::string& Folder() {
  static const std::string dir = [] {
    char tmpl[] = "/tmp/nvv_fuzz_cli.XXXXXX";
    const char* d = mkdtemp(tmpl);
    if (!d) std::abort();
    return std::string(d);
  }();
  return dir;
}

bool WriteFile(const std::string& path, const std::uint8_t* data, std::size_t size) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return false;
  const bool ok = size == 0 || std::fwrite(data, 1, size, f) == size;
  return std::fclose(f) == 0 && ok;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  static const char* const kExtensions[] = {".ply", ".obj", ".off", ".stl"};
  const std::string input = Folder() + "/mesh" + kExtensions[data[0] & 3];
  const std::string output = Folder() + "/out.ply";
  std::size_t i = 1;
  std::vector<std::string> args = {"nvv", "--threads", "1", "--quiet"};
  std::string token;
  auto take = [&] {
    if (!token.empty() && token != "--help" && token != "--version" && args.size() < 4 + kMaxOptions)
      args.push_back(token);
    token.clear();
  };
  for (; i < size && data[i] != '\n'; ++i) {
    if (data[i] == ' ') take();
    else if (data[i] != 0) token += char(data[i]);
  }
  take();
  if (i < size) ++i;  // the newline
  if (!WriteFile(input, data + i, size - i)) std::abort();
  unlink(output.c_str());
  args.push_back(input);
  args.push_back(output);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(&a[0]);
  argv.push_back(nullptr);
  const int code = nvv_cli::Main(int(args.size()), argv.data());
  if (code != 0 && code != 2 && code != 3 && code != 4 && code != 5) std::abort();
  if (code == 0) {
    struct stat st;
    if (stat(output.c_str(), &st) != 0 || st.st_size == 0) std::abort();
  }
  return 0;
}
