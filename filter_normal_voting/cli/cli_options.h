// The command line of `nvv`: one option per entry of nvv::FilterParameterTable() plus the
// tool's own switches. Parsing never prints; it returns the first problem as one sentence.
#ifndef NVV_CLI_CLI_OPTIONS_H
#define NVV_CLI_CLI_OPTIONS_H

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "filter/filter_options.h"
#include "io/crease_lines_file.h"  // CreaseLinesNameError

namespace nvv_cli {

struct CliArgs {
  nvv::FilterOptions options = nvv::DefaultOptions();
  std::vector<std::string> given;  // "name value" of every table option set on the command line
  bool ascii = false;
  bool quiet = false;
  bool help = false;
  bool version = false;
  int threads = 0;  // 0: all cores
  std::string input, output;
  std::string creaseLines;  // --crease_lines: empty, or a .obj / .ply file
};

inline std::string Lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

// A number in the C locale's format, the whole string, finite.
// A decimal number as a user writes it (digits, sign, point, exponent): strtod alone would also
// take hexadecimal ("0x1p4"), "inf" and "nan".
inline bool ParseNumber(const std::string& s, double& v) {
  if (s.empty()) return false;
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c)) && c != '+' && c != '-' && c != '.' && c != 'e' && c != 'E')
      return false;
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end && *end == '\0' && std::isfinite(v) && !std::isspace(static_cast<unsigned char>(s[0]));
}

inline std::string FormatNumber(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// What an option's value may be, for messages and --help.
inline std::string AcceptedValues(const nvv::ParamSpec& p) {
  switch (p.type) {
    case nvv::ParamType::Bool: return "true or false (also 1/0, yes/no)";
    case nvv::ParamType::Enum: {
      std::string s;
      for (std::size_t i = 0; i < p.tokens.size(); ++i) s += (i ? ", " : "") + std::string(p.tokens[i]);
      return "one of " + s + " (or its index 0-" + std::to_string(p.tokens.size() - 1) + ")";
    }
    case nvv::ParamType::Int: {
      char buf[96];
      std::snprintf(buf, sizeof buf, "an integer from %.0f to %.0f", p.minValue, p.maxValue);
      return buf;
    }
    default:
      if (p.maxValue >= 1e29) return "a number >= " + FormatNumber(p.minValue);
      return "a number from " + FormatNumber(p.minValue) + " to " + FormatNumber(p.maxValue);
  }
}

// The table value of `text` for option p, or an error sentence.
inline std::string ParseValue(const nvv::ParamSpec& p, const std::string& text, double& value) {
  const std::string bad = "invalid value '" + text + "' for --" + p.name + ": expected " + AcceptedValues(p);
  const std::string t = Lower(text);
  switch (p.type) {
    case nvv::ParamType::Bool:
      if (t == "true" || t == "1" || t == "yes") value = 1;
      else if (t == "false" || t == "0" || t == "no") value = 0;
      else return bad;
      return std::string();
    case nvv::ParamType::Enum:
      for (std::size_t i = 0; i < p.tokens.size(); ++i)
        if (t == p.tokens[i]) { value = double(i); return std::string(); }
      if (!ParseNumber(text, value) || value != std::floor(value) || value < 0 || value >= double(p.tokens.size()))
        return bad;
      return std::string();
    case nvv::ParamType::Int:
      if (!ParseNumber(text, value) || value != std::floor(value) || value < p.minValue || value > p.maxValue)
        return bad;
      return std::string();
    default:
      if (!ParseNumber(text, value) || value < p.minValue || value > p.maxValue) return bad;
      return std::string();
  }
}

// Parses argv[1..]. Returns an error sentence (exit status 2), or empty.
inline std::string ParseArgs(int argc, const char* const* argv, CliArgs& a) {
  a = CliArgs();
  std::vector<std::string> files;
  bool optionsEnded = false;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (optionsEnded || arg.size() < 2 || arg.compare(0, 2, "--") != 0) {
      if (!optionsEnded && arg.size() > 1 && arg[0] == '-') return "unknown option '" + arg + "' (see nvv --help)";
      files.push_back(arg);
      continue;
    }
    if (arg == "--") { optionsEnded = true; continue; }
    std::string name = arg.substr(2), value;
    bool inlineValue = false;
    const std::size_t eq = name.find('=');
    if (eq != std::string::npos) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
      inlineValue = true;
    }
    auto takeValue = [&](std::string& out) -> bool {
      if (inlineValue) { out = value; return true; }
      if (i + 1 >= argc) return false;
      out = argv[++i];
      return true;
    };
    if (name == "help" || name == "version" || name == "ascii" || name == "quiet") {
      if (inlineValue) return "option --" + name + " takes no value";
      if (name == "help") a.help = true;
      else if (name == "version") a.version = true;
      else if (name == "ascii") a.ascii = true;
      else a.quiet = true;
      continue;
    }
    if (name == "threads") {
      std::string text;
      double v;
      if (!takeValue(text)) return "option --threads needs a value";
      if (!ParseNumber(text, v) || v != std::floor(v) || v < 0 || v > 4096)
        return "invalid value '" + text + "' for --threads: expected an integer from 0 (all cores) to 4096";
      a.threads = int(v);
      continue;
    }
    if (name == "crease_lines") {
      if (!takeValue(a.creaseLines)) return "option --crease_lines needs a value";
      const std::string bad = nvv::CreaseLinesNameError(a.creaseLines);
      if (!bad.empty()) return bad;
      continue;
    }
    const nvv::ParamSpec* spec = nvv::FindParam(name);
    if (!spec && name == "crease_lines_layer")
      return "--crease_lines_layer is the MeshLab filter's (a new layer); this tool writes the lines to a file: "
             "--crease_lines FILE.obj|.ply";
    if (!spec) return "unknown option '--" + name + "' (see nvv --help)";
    std::string text;
    if (!takeValue(text)) return "option --" + name + " needs a value";
    if (name == "neighbourhood_k" && Lower(text) == "auto") {  // the same as --auto_k true
      a.options.core.autoK = true;
      a.given.push_back(name + " " + text);
      continue;
    }
    double v = 0;
    std::string e = ParseValue(*spec, text, v);
    if (e.empty()) e = nvv::SetOption(a.options, name, v);
    if (!e.empty()) return e;
    a.given.push_back(name + " " + text);
  }
  if (a.help || a.version) return std::string();
  if (files.empty()) return "missing INPUT and OUTPUT file names (usage: nvv [options] INPUT OUTPUT.ply)";
  if (files.size() == 1) return "missing OUTPUT file name (usage: nvv [options] INPUT OUTPUT.ply)";
  if (files.size() > 2) return "too many file names: '" + files[2] + "' (usage: nvv [options] INPUT OUTPUT.ply)";
  a.input = files[0];
  a.output = files[1];
  const std::string out = Lower(a.output);
  if (out.size() < 4 || out.compare(out.size() - 4, 4, ".ply") != 0)
    return "the output file name must end in .ply (got '" + a.output + "')";
  a.options.core.threads = a.threads;
  const std::string invalid = nvv::ValidateOptions(a.options);
  if (!invalid.empty()) return invalid;
  return std::string();
}

}  // namespace nvv_cli

#endif
