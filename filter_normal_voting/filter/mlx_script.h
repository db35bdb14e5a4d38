// A MeshLab 2020.09 filter script (.mlx) that runs the filter, written from the parameter table,
// so scripts always list every parameter (meshlabserver aborts on a script that omits one) with
// the names MeshLab expects.
#ifndef NVV_SCRIPTING_MLX_SCRIPT_H
#define NVV_SCRIPTING_MLX_SCRIPT_H

#include <map>
#include <sstream>
#include <string>

#include "filter/filter_options.h"

namespace nvv {

inline std::string XmlEscape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      default: o += c;
    }
  }
  return o;
}

// The <filter> element; `values` overrides defaults by parameter name (values as MeshLab writes
// them: numbers, true/false, enum indices). `extra` is inserted verbatim after the filter
// (other filters of a chain).
inline std::string MlxFilterElement(const std::map<std::string, std::string>& values = {}) {
  std::ostringstream x;
  x << " <filter name=\"" << XmlEscape(kFilterName) << "\">\n";
  for (const auto& p : MeshLabParameterTable()) {
    std::string v;
    const auto it = values.find(p.name);
    if (it != values.end()) {
      v = it->second;
    } else {
      std::ostringstream d;
      if (p.type == ParamType::Bool) d << (p.defaultValue != 0 ? "true" : "false");
      else d << p.defaultValue;
      v = d.str();
    }
    const char* type = p.type == ParamType::Float ? "RichFloat" : p.type == ParamType::Int ? "RichInt"
                     : p.type == ParamType::Bool ? "RichBool" : "RichEnum";
    x << "  <Param name=\"" << p.name << "\" type=\"" << type << "\" value=\"" << XmlEscape(v) << "\"";
    if (p.type == ParamType::Enum) {
      x << " enum_cardinality=\"" << p.choices.size() << "\"";
      for (std::size_t i = 0; i < p.choices.size(); ++i) x << " enum_val" << i << "=\"" << XmlEscape(p.choices[i]) << "\"";
    }
    x << " description=\"" << XmlEscape(p.label) << "\"/>\n";
  }
  const SaveFileSpec& save = ResultPlyParameter();
  const auto path = values.find(save.name);
  x << "  <Param name=\"" << save.name << "\" type=\"RichSaveFile\" value=\""
    << XmlEscape(path == values.end() ? std::string() : path->second) << "\" ext=\".ply\" description=\""
    << XmlEscape(save.label) << "\"/>\n";
  x << " </filter>\n";
  return x.str();
}

inline std::string MlxScript(const std::map<std::string, std::string>& values = {}, const std::string& after = "") {
  return "<!DOCTYPE FilterScript>\n<FilterScript>\n" + MlxFilterElement(values) + after + "</FilterScript>\n";
}

}  // namespace nvv

#endif
