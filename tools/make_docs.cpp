// nvv_docgen: writes the parts of the documentation that come from the parameter table, between
// markers in a Markdown file:
//   <!-- generated:parameters -->  ...  <!-- end generated:parameters -->   the parameter table
//   <!-- generated:mlx -->         ...  <!-- end generated:mlx -->          the default .mlx script
//   <!-- generated:help -->        ...  <!-- end generated:help -->         `nvv --help`
//
// Usage: nvv_docgen FILE.md            rewrites the blocks in place
//        nvv_docgen --check FILE.md    exits 1 (and says which block) when a block is out of date
//        nvv_docgen --print parameters|mlx|help|json
// `--print json` is the MeshLab filter's parameter table as JSON, for programs outside C++ (the
// Python tests):
//   {"filter": ..., "python_name": ..., "parameters": [{"name", "type" (float|int|bool|enum),
//    "label", "help", "default", "min", "max", "choices", "tokens", "advanced"}, ...],
//    "save_file": {"name", "label", "help"}}
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/help_text.h"
#include "filter/filter_options.h"
#include "filter/mlx_script.h"

namespace {

// A default as a user types it: true/false, the enum's index and label, or the number.
std::string DefaultText(const nvv::ParamSpec& p) {
  std::ostringstream s;
  if (p.type == nvv::ParamType::Bool) return p.defaultValue != 0 ? "true" : "false";
  s << p.defaultValue;
  return s.str();
}

std::string RangeText(const nvv::ParamSpec& p) {
  std::ostringstream s;
  switch (p.type) {
    case nvv::ParamType::Bool: return "true / false";
    case nvv::ParamType::Enum:
      for (std::size_t i = 0; i < p.choices.size(); ++i)
        s << (i ? "; " : "") << i << " " << p.choices[i] << " (`" << p.tokens[i] << "`)";
      return s.str();
    default: s << p.minValue << " – " << p.maxValue; return s.str();
  }
}

std::string ParameterTable() {
  std::ostringstream s;
  s << "| name | label | default | values | meaning |\n|---|---|---|---|---|\n";
  for (const auto& p : nvv::MeshLabParameterTable())
    s << "| `" << p.name << "` | " << p.label << " | " << DefaultText(p) << " | " << RangeText(p) << " | " << p.help
      << (nvv::FindParam(p.name) ? "" : " MeshLab and scripts only.") << " |\n";
  const nvv::SaveFileSpec& save = nvv::ResultPlyParameter();
  s << "| `" << save.name << "` | " << save.label << " | (empty) | a file name | " << save.help
    << " MeshLab and scripts only: the command-line tool always writes this file. |\n";
  return s.str();
}

std::string JsonString(const char* text) {
  std::string s = "\"";
  for (const char* c = text; *c; ++c) {
    const unsigned char u = static_cast<unsigned char>(*c);
    if (*c == '"' || *c == '\\') s += std::string("\\") + *c;
    else if (u < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", u);
      s += buf;
    } else s += *c;
  }
  return s + "\"";
}

std::string JsonNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string JsonList(const std::vector<const char*>& items) {
  std::string s = "[";
  for (std::size_t i = 0; i < items.size(); ++i) s += (i ? ", " : "") + JsonString(items[i]);
  return s + "]";
}

std::string ParameterJson() {
  static const char* kTypes[] = {"float", "int", "bool", "enum"};
  std::ostringstream s;
  s << "{\n  \"filter\": " << JsonString(nvv::kFilterName) << ",\n  \"python_name\": "
    << JsonString(nvv::kPythonFilterName) << ",\n  \"parameters\": [\n";
  const auto& table = nvv::MeshLabParameterTable();
  for (std::size_t i = 0; i < table.size(); ++i) {
    const nvv::ParamSpec& p = table[i];
    s << "    {\"name\": " << JsonString(p.name) << ", \"type\": \"" << kTypes[int(p.type)] << "\", \"label\": "
      << JsonString(p.label) << ",\n     \"default\": " << JsonNumber(p.defaultValue) << ", \"min\": "
      << JsonNumber(p.minValue) << ", \"max\": " << JsonNumber(p.maxValue) << ", \"choices\": " << JsonList(p.choices)
      << ", \"tokens\": " << JsonList(p.tokens) << ", \"advanced\": " << (p.advanced ? "true" : "false")
      << ",\n     \"help\": " << JsonString(p.help) << "}" << (i + 1 < table.size() ? "," : "") << "\n";
  }
  const nvv::SaveFileSpec& save = nvv::ResultPlyParameter();
  s << "  ],\n  \"save_file\": {\"name\": " << JsonString(save.name) << ", \"label\": " << JsonString(save.label)
    << ", \"help\": " << JsonString(save.help) << "}\n}\n";
  return s.str();
}

std::string Block(const std::string& name) {
  if (name == "parameters") return ParameterTable();
  if (name == "mlx") return "```xml\n" + nvv::MlxScript() + "```\n";
  if (name == "help") return "```text\n" + nvv_cli::HelpText() + "```\n";
  return std::string();
}

// Replaces every generated block of `text`; `stale` gets the first block that changed.
std::string Regenerate(const std::string& text, std::string& stale) {
  std::string out;
  std::size_t pos = 0;
  const std::string open = "<!-- generated:", close = "<!-- end generated:";
  for (;;) {
    const std::size_t a = text.find(open, pos);
    if (a == std::string::npos) break;
    const std::size_t nameEnd = text.find(" -->", a);
    const std::string name = text.substr(a + open.size(), nameEnd - a - open.size());
    const std::size_t bodyStart = text.find('\n', nameEnd) + 1;
    const std::size_t b = text.find(close + name + " -->", bodyStart);
    if (nameEnd == std::string::npos || b == std::string::npos || Block(name).empty()) {
      std::fprintf(stderr, "nvv_docgen: unknown or unclosed generated block '%s'\n", name.c_str());
      std::exit(2);
    }
    const std::string body = Block(name);
    if (stale.empty() && text.compare(bodyStart, b - bodyStart, body) != 0) stale = name;
    out += text.substr(pos, bodyStart - pos) + body;
    pos = b;
  }
  return out + text.substr(pos);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "--print" && argc == 3) {
    const std::string out = std::string(argv[2]) == "json" ? ParameterJson() : Block(argv[2]);
    std::fputs(out.c_str(), stdout);
    return out.empty() ? 2 : 0;
  }
  const bool check = mode == "--check";
  if (argc != (check ? 3 : 2)) {
    std::fprintf(stderr, "usage: nvv_docgen [--check] FILE.md | nvv_docgen --print parameters|mlx|help|json\n");
    return 2;
  }
  const std::string path = argv[check ? 2 : 1];
  std::ifstream in(path);
  if (!in) {
    std::fprintf(stderr, "nvv_docgen: cannot read %s\n", path.c_str());
    return 2;
  }
  std::stringstream buf;
  buf << in.rdbuf();
  std::string stale;
  const std::string fresh = Regenerate(buf.str(), stale);
  if (check) {
    if (stale.empty()) return 0;
    std::fprintf(stderr, "nvv_docgen: the '%s' block of %s is out of date: run nvv_docgen %s\n", stale.c_str(),
                 path.c_str(), path.c_str());
    return 1;
  }
  std::ofstream(path) << fresh;
  return 0;
}
