#include "meshlab_filter_common.h"

#include <algorithm>

#include <QFileInfo>

#include <vcg/complex/algorithms/update/selection.h>

#include "filter/crease_lines_layer.h"
#include "filter/run_filter.h"

namespace nvv_meshlab {

QString FilterName() { return QString::fromUtf8(nvv::kFilterName); }

QString PythonName() { return QString::fromUtf8(nvv::kPythonFilterName); }

QString FilterInfo() {
  // Short, like MeshLab's own filters: each parameter's help is its tooltip in the dialog.
  return QStringLiteral(
      "Finds creases and corners and estimates normals and principal curvatures on noisy meshes by "
      "<b>Normal Vector Voting</b>: the triangles of each vertex's geodesic neighbourhood vote for its "
      "orientation, which classifies it as surface, crease or corner; surface vertices get curvature from "
      "their own side of any crease.<br>"
      "Writes vertex normals, quality and colour as chosen, PD1/PD2 with K1 &gt;= K2 (PD1 = direction of "
      "K1), an optional selection, and the attributes nvv_class, nvv_*_saliency, nvv_cusp_angle, "
      "nvv_crease_curvature, nvv_crease_tangent; with <i>crease_edges</i>, the crease edges as the faces' edge "
      "selection and each face's smooth patch in the attribute nvv_patch.<br>"
      "<i>D. L. Page, Y. Sun, A. F. Koschan, J. Paik, M. A. Abidi</i>, <b>\"Normal Vector Voting: Crease "
      "Detection and Curvature Estimation on Large, Noisy Meshes\"</b>, Graphical Models 64 (2002).");
}

void AddParameters(RichParameterList& par) {
  for (const auto& p : nvv::MeshLabParameterTable()) {
    const QString name = QString::fromUtf8(p.name), label = QString::fromUtf8(p.label), help = QString::fromUtf8(p.help);
    switch (p.type) {
      case nvv::ParamType::Float: par.addParam(RichFloat(name, MESHLAB_SCALAR(p.defaultValue), label, help)); break;
      case nvv::ParamType::Int: par.addParam(RichInt(name, int(p.defaultValue), label, help)); break;
      case nvv::ParamType::Bool: par.addParam(RichBool(name, p.defaultValue != 0, label, help)); break;
      case nvv::ParamType::Enum: {
        QStringList choices;
        for (const char* c : p.choices) choices << QString::fromUtf8(c);
        par.addParam(RichEnum(name, int(p.defaultValue), choices, label, help));
        break;
      }
    }
  }
  const nvv::SaveFileSpec& save = nvv::ResultPlyParameter();
#ifdef NVV_MESHLAB_API_2025
  par.addParam(RichFileSave(QString::fromUtf8(save.name), QString(), QStringLiteral(".ply"),  // renamed in 2022.02
                            QString::fromUtf8(save.label), QString::fromUtf8(save.help)));
#else
  par.addParam(RichSaveFile(QString::fromUtf8(save.name), QString(), QStringLiteral(".ply"),
                            QString::fromUtf8(save.label), QString::fromUtf8(save.help)));
#endif
}

QString ReadOptions(const RichParameterList& par, nvv::FilterOptions& options, QString& resultPly) {
  options = nvv::DefaultOptions();
  const QString saveName = QString::fromUtf8(nvv::ResultPlyParameter().name);
  resultPly = par.hasParameter(saveName) ? par.getSaveFileName(saveName).trimmed() : QString();
  for (const auto& p : nvv::MeshLabParameterTable()) {
    const QString name = QString::fromUtf8(p.name);
    if (!par.hasParameter(name)) continue;  // scripts written for an older version keep the defaults
    double value = 0;
    switch (p.type) {
      case nvv::ParamType::Float:
        value = par.getFloat(name);
        // MeshLab keeps a float parameter in single precision (FloatValue holds a float, in the
        // double build too), so a bound given exactly arrives rounded (1e30 as 1.0000000150e30)
        // and would be refused as outside the range: a value that rounds to a bound is the bound.
        if (float(value) == float(p.maxValue)) value = std::min(value, p.maxValue);
        if (float(value) == float(p.minValue)) value = std::max(value, p.minValue);
        break;
      case nvv::ParamType::Int: value = par.getInt(name); break;
      case nvv::ParamType::Bool: value = par.getBool(name) ? 1 : 0; break;
      case nvv::ParamType::Enum: value = par.getEnum(name); break;
    }
    const std::string err = nvv::SetOption(options, p.name, value);
    if (!err.empty()) return QString::fromStdString(err);
  }
  return QString::fromStdString(nvv::ValidateOptions(options));
}

int OutputMask(const nvv::FilterOptions* options) {
  int mask = MeshModel::MM_VERTNORMAL | MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR |
             MeshModel::MM_VERTFLAGSELECT | MeshModel::MM_VERTCURVDIR;
  if (options && options->creaseEdges) mask |= MeshModel::MM_FACEFLAG;  // the faces' edge selection
  // Patch colours are on the faces alone: declaring only them makes MeshLab show face colours.
  if (options && options->color == nvv::ColorMode::Patches) mask = (mask & ~MeshModel::MM_VERTCOLOR) | MeshModel::MM_FACECOLOR;
  return mask;
}

// The crease lines as a new layer after mm (which stays the current one); its log line.
QString AddCreaseLinesLayer(MeshDocument& md, MeshModel& mm, const nvv::CreaseOutputs& crease) {
  if (crease.net.lines.empty()) return QStringLiteral("Normal vector voting: no crease lines, so no lines layer");
  const QString label = QFileInfo(mm.label()).completeBaseName() + QStringLiteral(" crease lines");
  MeshModel* layer = md.addNewMesh(QString(), label, false);
  layer->updateDataMask(MeshModel::MM_VERTCOLOR);
  nvv::BuildCreaseLinesLayer(mm.cm, crease, layer->cm);
  return QStringLiteral("Normal vector voting: layer '%1' holds the %2 crease lines (%3 edges)")
      .arg(label)
      .arg(crease.net.lines.size())
      .arg(layer->cm.en);
}

Outcome Run(MeshDocument& md, const nvv::FilterOptions& options, const QString& resultPly, vcg::CallBackPos* cb) {
  Outcome out;
  MeshModel& mm = *md.mm();
  nvv::Progress progress;
#ifdef NVV_MESHLAB_API_2025
  // 2022.02+ ignores the callback's result (no cancelling); PyMeshLab's may return false.
  if (cb) progress = [cb](int pos, const char* text) { cb(pos, text); return true; };
#else
  if (cb) progress = [cb](int pos, const char* text) { return cb(pos, text); };
#endif
  nvv::RunRequest request;
  request.options = options;
  request.resultPly = resultPly.toStdString();
  // Only once the results exist is the mesh touched: enable the components they are written to.
  auto enable = [&mm](const nvv::ApplyResults<CMeshO>::Needs& needs) {
    int mask = MeshModel::MM_VERTCURVDIR;
    if (needs.quality) mask |= MeshModel::MM_VERTQUALITY;
    if (needs.color) mask |= MeshModel::MM_VERTCOLOR;
    if (needs.faceColor) mask |= MeshModel::MM_FACECOLOR;
    mm.updateDataMask(mask);
  };
  const nvv::RunOutcome run = nvv::RunFilter(mm.cm, request, progress, enable);
  out.summary = run.summary;
  if (run.creaseNetwork) {
    const nvv::CreaseNetwork& net = run.crease.net;
    out.creaseEdges = int(net.edges.size());
    out.creaseLines = int(net.lines.size());
    out.closedLines = run.crease.closedLines;
    out.lineCorners = run.crease.lineCorners;
    out.patches = net.patchCount;
    out.smallestPatch = net.smallestPatch;
    out.largestPatch = net.largestPatch;
  }
  if (!run.meshChanged) {
    out.error = QStringLiteral("Normal Vector Voting: ") + QString::fromStdString(run.error) +
                (run.failure == nvv::RunOutcome::kCancelled ? QString() : QStringLiteral(" The mesh was not changed."));
    return out;
  }
  // MeshLab's selection filters (Delete Selected Vertices, Laplacian "selected only", ...) trust
  // the mesh's count of selected vertices, so keep it true.
  CMeshO& m = mm.cm;
  if (options.selection != nvv::SelectionMode::None) m.svn = int(vcg::tri::UpdateSelection<CMeshO>::VertexCount(m));
  if (cb) cb(100, "Normal vector voting: done");
  out.ok = true;
  if (!resultPly.isEmpty()) {
    if (run.Ok())
      out.log << QStringLiteral("Normal vector voting: all results written to %1").arg(resultPly);
    else
      out.log << QStringLiteral("Normal vector voting: warning: ") + QString::fromStdString(run.error);
  }
  for (const auto& line : run.log) out.log << QString::fromStdString(line);
  if (options.creaseLinesLayer) out.log << AddCreaseLinesLayer(md, mm, run.crease);
  for (const auto& w : run.warnings) out.log << QStringLiteral("Normal vector voting: warning: ") + QString::fromStdString(w);
  return out;
}

std::map<std::string, QVariant> SummaryValues(const Outcome& outcome) {
  const nvv::Summary& s = outcome.summary;
  // Plain int / double / bool values: every MeshLab front end converts them.
  std::map<std::string, QVariant> v;
  v["surface_vertices"] = int(s.perClass[int(nvv::VertexClass::Surface)]);
  v["crease_vertices"] = int(s.perClass[int(nvv::VertexClass::Crease)]);
  v["corner_vertices"] = int(s.perClass[int(nvv::VertexClass::Corner)]);
  v["unclassified_vertices"] = int(s.perClass[int(nvv::VertexClass::Invalid)]);
  v["capped_vertices"] = int(s.capped);
  v["thinned_vertices"] = int(s.thinned);
  v["k1_min"] = s.k1Min;
  v["k1_max"] = s.k1Max;
  v["k2_min"] = s.k2Min;
  v["k2_max"] = s.k2Max;
  v["absolute_radius"] = s.radius;
  v["k_used"] = s.k;
  v["noise_estimate"] = s.noiseOverEdge;
  v["mean_edge_length"] = s.meanEdge;
  v["epsilon"] = s.epsilon;
  v["eta"] = s.eta;
  v["sign_aware_rule"] = s.signAwareUsed;
  v["seconds"] = s.secondsTotal;
  v["seconds_pass1"] = s.secondsPass1;
  v["seconds_pass2"] = s.secondsPass2;
  v["crease_edge_count"] = outcome.creaseEdges;
  v["crease_lines"] = outcome.creaseLines;
  v["closed_crease_lines"] = outcome.closedLines;
  v["line_end_corners"] = outcome.lineCorners;
  v["patches"] = outcome.patches;
  v["smallest_patch_faces"] = outcome.smallestPatch;
  v["largest_patch_faces"] = outcome.largestPatch;
  return v;
}

}  // namespace nvv_meshlab
