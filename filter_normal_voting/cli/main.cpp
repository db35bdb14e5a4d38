// nvv: Normal Vector Voting from the command line. Reads a mesh, runs the filter with the
// parameters of nvv::FilterParameterTable(), applies the results as the MeshLab plugin does
// and writes the full-result PLY (io/result_ply.h). See `nvv --help` and docs/cli.md.
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "cli/cli_mesh.h"  // vcg/complex/complex.h first, as vcglib requires
#include "cli/cli_options.h"
#include "cli/help_text.h"
#include "cli/load_mesh.h"

#include "apply/apply_results.h"
#include "core/normal_vector_voting.h"
#include "io/result_ply.h"

#ifndef NVV_VERSION
#define NVV_VERSION "unknown"
#endif

namespace {

enum ExitCode { kOk = 0, kBadArguments = 2, kBadInput = 3, kRefused = 4, kCannotWrite = 5 };

int Fail(int code, const std::string& message) {
  std::fprintf(stderr, "nvv: %s\n", message.c_str());
  return code;
}

// A one-line progress indicator, redrawn in place.
struct TerminalProgress {
  bool shown = false;
  bool operator()(int percent, const char* text) {
    std::fprintf(stderr, "\r%3d%% %-60.60s", percent, text ? text : "");
    std::fflush(stderr);
    shown = true;
    return true;
  }
  void Finish() {
    if (shown) std::fprintf(stderr, "\r%-66s\r", "");
  }
};

std::vector<std::string> HeaderComments(const nvv_cli::CliArgs& a) {
  std::vector<std::string> c;
  c.push_back(std::string("nvv ") + NVV_VERSION + " input " + a.input);
  for (const auto& p : nvv::FilterParameterTable()) {
    const double v = nvv::GetOption(a.options, p.name);
    std::string text;
    switch (p.type) {
      case nvv::ParamType::Bool: text = v != 0 ? "true" : "false"; break;
      case nvv::ParamType::Enum: text = p.tokens[int(v)]; break;
      case nvv::ParamType::Int: text = std::to_string(int(v)); break;
      case nvv::ParamType::Float: text = nvv_cli::FormatNumber(v); break;
    }
    c.push_back(std::string("nvv --") + p.name + " " + text);
  }
  return c;
}

// The input file, for the messages of main()'s last-resort handlers.
std::string gInput;

int Run(int argc, char** argv) {
  nvv_cli::CliArgs a;
  const std::string argError = nvv_cli::ParseArgs(argc, argv, a);
  if (!argError.empty()) return Fail(kBadArguments, argError);
  gInput = a.input;
  if (a.help) {
    std::fputs(nvv_cli::HelpText().c_str(), stdout);
    return kOk;
  }
  if (a.version) {
    std::printf("nvv (filter_normal_voting) %s\n", NVV_VERSION);
    return kOk;
  }

  typedef nvv_cli::CliMesh Mesh;
  Mesh m;
  nvv_cli::LoadInfo info;
  std::string error;
  if (!nvv_cli::LoadMesh(a.input, m, info, error)) return Fail(kBadInput, a.input + ": " + error);
  // Refuse an unwritable destination before spending time on the computation.
  const std::size_t slash = a.output.find_last_of('/');
  const std::string outDir = slash == std::string::npos ? "." : (slash == 0 ? "/" : a.output.substr(0, slash));
  if (access(outDir.c_str(), W_OK) != 0)
    return Fail(kCannotWrite, "cannot write '" + a.output + "': " + std::strerror(errno) + " (" + outDir + ")");
  struct stat outStat;
  if (::stat(a.output.c_str(), &outStat) == 0 && S_ISDIR(outStat.st_mode))
    return Fail(kCannotWrite, "cannot write '" + a.output + "': it is a directory");

  if (!a.quiet) {
    std::printf("input: %s (%s, %d vertices, %d faces%s)\n", a.input.c_str(), info.format.c_str(), m.vn, m.fn,
                info.weldedVertices > 0 ? (", welded " + std::to_string(info.weldedVertices) + " vertices").c_str()
                                        : "");
    if (!info.warning.empty()) std::printf("warning: %s\n", info.warning.c_str());
  }

  TerminalProgress terminal;
  nvv::Progress progress;
  if (!a.quiet && isatty(fileno(stderr))) progress = [&terminal](int p, const char* t) { return terminal(p, t); };
  std::vector<nvv::VertexResult> res;
  nvv::Summary sum;
  const nvv::Status st = vcg::tri::NormalVectorVoting<Mesh>::Compute(m, a.options.core, res, sum, progress);
  terminal.Finish();
  if (!st.ok) return Fail(kRefused, a.input + ": " + st.message);

  nvv::ApplyResults<Mesh>::Apply(m, res, a.options);
  if (!nvv::WriteResultPly(a.output, m, res, !a.ascii, HeaderComments(a), error))
    return Fail(kCannotWrite, error);

  if (!a.quiet) {
    std::printf("%s\n", nvv::SummaryLine(sum).c_str());
    for (const auto& w : sum.warnings) std::printf("warning: %s\n", w.c_str());
    std::printf("output: %s (%s)\n", a.output.c_str(), a.ascii ? "ascii" : "binary_little_endian");
  }
  return kOk;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return Run(argc, argv);
  } catch (const std::bad_alloc&) {
    return Fail(kRefused, (gInput.empty() ? std::string() : gInput + ": ") + "out of memory");
  } catch (const std::exception& e) {
    return Fail(kBadInput, (gInput.empty() ? std::string() : gInput + ": ") + e.what());
  }
}
