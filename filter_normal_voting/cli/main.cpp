// nvv: Normal Vector Voting from the command line. Reads a mesh, runs the filter with the
// parameters of nvv::FilterParameterTable(), applies the results as the MeshLab plugin does
// and writes the full-result PLY (io/result_ply.h). See `nvv --help` and docs/cli.md.
#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

#include "cli/cli_mesh.h"  // vcg/complex/complex.h first, as vcglib requires
#include "cli/cli_options.h"
#include "cli/help_text.h"
#include "cli/load_mesh.h"

#include "filter/run_filter.h"

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
  // Refuse an unwritable destination before anything is printed or computed.
  const std::string unwritable = nvv::CheckOutputPath(a.output);
  if (!unwritable.empty()) return Fail(kCannotWrite, unwritable);
  if (!a.quiet) {
    std::printf("input: %s (%s, %d vertices, %d faces%s)\n", a.input.c_str(), info.format.c_str(), m.vn, m.fn,
                info.weldedVertices > 0 ? (", welded " + std::to_string(info.weldedVertices) + " vertices").c_str()
                                        : "");
    if (!info.warning.empty()) std::printf("warning: %s\n", info.warning.c_str());
  }

  TerminalProgress terminal;
  nvv::Progress progress;
  if (!a.quiet && isatty(fileno(stderr))) progress = [&terminal](int p, const char* t) { return terminal(p, t); };
  nvv::RunRequest request;
  request.options = a.options;
  request.resultPly = a.output;
  request.binaryPly = !a.ascii;
  request.plyComments = HeaderComments(a);
  const nvv::RunOutcome run = nvv::RunFilter(m, request, progress);
  terminal.Finish();
  switch (run.failure) {
    case nvv::RunOutcome::kNone: break;
    case nvv::RunOutcome::kCannotWrite: return Fail(kCannotWrite, run.error);
    default: return Fail(kRefused, a.input + ": " + run.error);
  }
  if (!a.quiet) {
    std::printf("%s\n", run.log.front().c_str());
    for (const auto& w : run.warnings) std::printf("warning: %s\n", w.c_str());
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
