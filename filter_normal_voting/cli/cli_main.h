// The whole of `nvv` but main(): arguments, reading, the filter, the result PLY, and the exit
// codes of docs/cli.md. main.cpp calls it; so does the fuzz target over the whole command-line
// path (fuzz/fuzz_cli.cpp), with the same arguments a user could type.
#ifndef NVV_CLI_CLI_MAIN_H
#define NVV_CLI_CLI_MAIN_H

#include <unistd.h>

#include <cstdio>
#include <new>
#include <stdexcept>
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

namespace nvv_cli {

enum ExitCode { kOk = 0, kBadArguments = 2, kBadInput = 3, kRefused = 4, kCannotWrite = 5 };

namespace detail {

inline int Fail(int code, const std::string& message) {
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

inline std::vector<std::string> HeaderComments(const CliArgs& a) {
  std::vector<std::string> c;
  c.push_back(std::string("nvv ") + NVV_VERSION + " input " + a.input);
  for (const auto& p : nvv::FilterParameterTable()) {
    const double v = nvv::GetOption(a.options, p.name);
    std::string text;
    switch (p.type) {
      case nvv::ParamType::Bool: text = v != 0 ? "true" : "false"; break;
      case nvv::ParamType::Enum: text = p.tokens[int(v)]; break;
      case nvv::ParamType::Int: text = std::to_string(int(v)); break;
      case nvv::ParamType::Float: text = FormatNumber(v); break;
    }
    c.push_back(std::string("nvv --") + p.name + " " + text);
  }
  return c;
}

// `input` is set as soon as it is known, for the messages of Main()'s last-resort handlers.
inline int Run(int argc, char** argv, std::string& input) {
  CliArgs a;
  const std::string argError = ParseArgs(argc, argv, a);
  if (!argError.empty()) return Fail(kBadArguments, argError);
  input = a.input;
  if (a.help) {
    std::fputs(HelpText().c_str(), stdout);
    return kOk;
  }
  if (a.version) {
    std::printf("nvv (filter_normal_voting) %s\n", NVV_VERSION);
    return kOk;
  }

  typedef CliMesh Mesh;
  Mesh m;
  LoadInfo info;
  std::string error;
  if (!LoadMesh(a.input, m, info, error)) return Fail(kBadInput, a.input + ": " + error);
  // Refuse an unwritable destination before anything is printed or computed.
  std::string unwritable = nvv::CheckOutputPath(a.output);
  if (unwritable.empty() && !a.creaseLines.empty()) unwritable = nvv::CheckOutputPath(a.creaseLines, "the crease lines");
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
  request.creaseLines = a.creaseLines;
  const nvv::RunOutcome run = nvv::RunFilter(m, request, progress);
  terminal.Finish();
  switch (run.failure) {
    case nvv::RunOutcome::kNone: break;
    case nvv::RunOutcome::kCannotWrite: return Fail(kCannotWrite, run.error);
    default: return Fail(kRefused, a.input + ": " + run.error);
  }
  if (!a.quiet) {
    std::printf("%s\n", run.log.front().c_str());
    if (run.creaseNetwork) std::printf("%s\n", nvv::CreaseNetworkLine(run.crease).c_str());
    for (const auto& w : run.warnings) std::printf("warning: %s\n", w.c_str());
    std::printf("output: %s (%s)\n", a.output.c_str(), a.ascii ? "ascii" : "binary_little_endian");
    if (!a.creaseLines.empty()) std::printf("crease lines: %s\n", a.creaseLines.c_str());
  }
  return kOk;
}

}  // namespace detail

// Runs `nvv` with these arguments and returns its exit code; never throws.
inline int Main(int argc, char** argv) {
  std::string input;
  try {
    return detail::Run(argc, argv, input);
  } catch (const std::bad_alloc&) {
    return detail::Fail(kRefused, (input.empty() ? std::string() : input + ": ") + "out of memory");
  } catch (const std::exception& e) {
    return detail::Fail(kBadInput, (input.empty() ? std::string() : input + ": ") + e.what());
  }
}

}  // namespace nvv_cli

#endif
