// The text of `nvv --help`, in the layout of a manual page. The OPTIONS section is generated
// from nvv::FilterParameterTable(), so it always lists exactly what the tool accepts.
#ifndef NVV_CLI_HELP_TEXT_H
#define NVV_CLI_HELP_TEXT_H

#include <sstream>
#include <string>

#include "cli/cli_options.h"
#include "filter/filter_options.h"

namespace nvv_cli {

// `text` wrapped at `width` columns, every line indented by `indent` spaces.
inline std::string Wrap(const std::string& text, int indent, int width = 79) {
  std::istringstream words(text);
  std::string word, line, out;
  const std::string pad(indent, ' ');
  while (words >> word) {
    if (!line.empty() && int(pad.size() + line.size() + 1 + word.size()) > width) {
      out += pad + line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty()) out += pad + line + "\n";
  return out;
}

inline std::string DefaultText(const nvv::ParamSpec& p) {
  switch (p.type) {
    case nvv::ParamType::Bool: return p.defaultValue != 0 ? "true" : "false";
    case nvv::ParamType::Enum: return p.tokens[int(p.defaultValue)];
    default: return FormatNumber(p.defaultValue);
  }
}

inline const char* TypeText(const nvv::ParamSpec& p) {
  switch (p.type) {
    case nvv::ParamType::Bool: return "BOOL";
    case nvv::ParamType::Enum: return "CHOICE";
    case nvv::ParamType::Int: return "INT";
    default: return "NUMBER";
  }
}

// One option's entry: the synopsis line, then its help, values and default.
inline std::string OptionEntry(const nvv::ParamSpec& p) {
  std::string s = "  --" + std::string(p.name) + " " + TypeText(p) + "\n";
  s += Wrap(std::string(p.label) + ". " + p.help, 6);
  if (p.type == nvv::ParamType::Enum) {
    for (std::size_t i = 0; i < p.tokens.size(); ++i)
      s += "        " + std::string(p.tokens[i]) + " (" + std::to_string(i) + "): " + p.choices[i] + "\n";
  } else {
    s += Wrap("Values: " + AcceptedValues(p) + ".", 6);
  }
  s += "      Default: " + DefaultText(p) + "\n\n";
  return s;
}

inline std::string HelpText() {
  std::string s;
  s += "NAME\n"
       "  nvv - Normal Vector Voting: crease detection and curvature estimation on\n"
       "  triangle meshes\n\n"
       "SYNOPSIS\n"
       "  nvv [options] INPUT OUTPUT.ply\n\n"
       "DESCRIPTION\n";
  s += Wrap("Reads the triangle mesh INPUT (PLY, OBJ, OFF or STL; STL triangle soups are welded), "
            "runs Normal Vector Voting (Page, Sun, Koschan, Paik and Abidi, Graphical Models 64, "
            "2002) on it and writes OUTPUT.ply: the mesh with the estimated normals, a quality and a "
            "colour per vertex, and every per-vertex result (class, eigenvalues of the vote matrix, "
            "principal curvatures k1 >= k2 and their directions, crease tangent, crease curvature, "
            "cusp angle).", 2);
  s += "\n";
  s += Wrap("Pass 1 classifies each vertex as surface, crease or corner from the normals of the "
            "triangles in its geodesic neighbourhood and gives surface vertices a robust normal; pass 2 "
            "estimates the principal curvatures of surface vertices and the curvature along creases. "
            "The results equal those of the Normal Vector Voting filter in MeshLab run with the "
            "same parameters.", 2);
  s += "\n";
  s += Wrap("When INPUT has no vertex normals they are computed angle-weighted, as MeshLab does on "
            "loading; corner and unclassified vertices keep them. A summary (vertices per class, "
            "curvature ranges, neighbourhood radius, time, warnings about the input; with the crease "
            "network its edges, lines, the corners at their ends and the patches' count and sizes) is printed on "
            "standard output. Progress is shown on standard error when it is a terminal.", 2);
  s += "\nOPTIONS\n";
  s += Wrap("Algorithm and output options (each also accepts --name=value):", 2) + "\n";
  for (const auto& p : nvv::FilterParameterTable()) s += OptionEntry(p);
  s += "  --ascii\n" + Wrap("Write an ASCII PLY instead of binary_little_endian.", 6) + "\n";
  s += "  --crease_lines FILE\n" + Wrap("Also write the crease lines as polylines: FILE.obj (one 'l' record "
                                       "per line) or FILE.ply (ascii, an edge element with each edge's line). "
                                       "Finds the crease network even with --crease_edges false.", 6) + "\n";
  s += "  --threads INT\n" + Wrap("Number of threads; 0 (the default) uses every core. The results "
                                  "are the same for any number of threads.", 6) + "\n";
  s += "  --quiet\n" + Wrap("Print nothing but errors: no summary, no progress.", 6) + "\n";
  s += "  --help\n" + Wrap("Print this text and exit.", 6) + "\n";
  s += "  --version\n" + Wrap("Print the version and exit.", 6) + "\n";
  s += "OUTPUT\n";
  s += Wrap("OUTPUT.ply (binary_little_endian, or ascii with --ascii) has the mesh's faces as "
            "'property list uchar int vertex_indices' and, per vertex, these properties (MeshLab reads "
            "x..quality; the others are extra properties it ignores):", 2);
  s += "    x y z            float  position\n"
       "    nx ny nz         float  normal (updated unless --update_normals false)\n"
       "    red green blue alpha\n"
       "                     uchar  colour chosen by --color\n"
       "    quality          float  value chosen by --quality\n"
       "    nvv_class        uchar  0 surface, 1 crease, 2 corner, 3 unclassified\n"
       "    nvv_lambda1..3   float  eigenvalues of the vote matrix (sum 1)\n"
       "    k1 k2            float  principal curvatures k1 >= k2, 1/units\n"
       "    pd1x pd1y pd1z   float  direction of k1\n"
       "    pd2x pd2y pd2z   float  direction of k2\n"
       "    nvv_crease_tangent_x/_y/_z\n"
       "                     float  crease direction (crease vertices)\n"
       "    nvv_crease_curvature\n"
       "                     float  curvature along the crease, 1/units\n"
       "    nvv_cusp_angle   float  angle between the two sheets' normals, degrees\n"
       "    nvv_flags        uchar  1 normal valid, 2 curvature valid, 4 crease values\n"
       "                            valid, 8 neighbourhood truncated at the cap\n"
       "    nvv_selected     uchar  1 if selected by --selection, else 0\n";
  s += Wrap("With the crease network (--crease_edges true, the default) each face also has 'property "
            "int patch', its smooth patch (-1: a face the filter skipped), and an element 'edge' "
            "follows the faces, one record per crease edge:", 2);
  s += "    vertex1 vertex2  int    the edge's vertices, vertex1 < vertex2\n"
       "    cusp_angle       float  angle between the two sheets' normals, radians\n"
       "    line             int    the crease line the edge belongs to\n";
  s += Wrap("Curvature values are 0 where the flags say they are not valid. Vertices keep the "
            "input's order (STL: the order after welding).", 2);
  s += "\nEXIT STATUS\n"
       "  0  success\n"
       "  2  bad arguments: unknown option, invalid value, missing file names\n"
       "  3  INPUT missing, unreadable, corrupt, or not PLY/OBJ/OFF/STL\n"
       "  4  mesh refused by the filter: empty, a point cloud, or every triangle\n"
       "     degenerate\n"
       "  5  OUTPUT cannot be written\n";
  s += Wrap("Every error is reported as one line on standard error starting with \"nvv: \".", 2);
  s += "\nEXAMPLES\n"
       "  nvv fandisk.off fandisk_nvv.ply\n"
       "      Defaults: k = 3 mean edge lengths, crease angle 40 and corner angle 60\n"
       "      degrees, class colours, mean curvature as quality.\n\n"
       "  nvv --neighbourhood_k 5 --crease_angle 30 scan.ply scan_nvv.ply\n"
       "      A larger neighbourhood for a noisy scan; shallower edges become creases.\n\n"
       "  nvv --neighbourhood_k auto scan.ply scan_nvv.ply\n"
       "      k chosen from the noise the tool estimates: 3 on a clean mesh, up to 5\n"
       "      from 10 % noise; the summary line gives both.\n\n"
       "  nvv --quality gaussian --color ramp --selection creases part.stl out.ply\n"
       "      Gaussian curvature as a colour ramp; crease and corner vertices selected.\n\n"
       "  nvv --curvature_fit taubin --ascii --threads 1 model.obj model_nvv.ply\n"
       "      The paper's Taubin estimator, ASCII output, one thread.\n";
  return s;
}

}  // namespace nvv_cli

#endif
