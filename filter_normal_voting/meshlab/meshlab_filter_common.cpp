#include "meshlab_filter_common.h"

#include <vcg/complex/algorithms/update/selection.h>

#include <QFileInfo>
#include <new>

#include "apply/apply_results.h"
#include "core/normal_vector_voting.h"
#include "io/result_ply.h"

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
      "nvv_crease_curvature, nvv_crease_tangent.<br>"
      "<i>D. L. Page, Y. Sun, A. F. Koschan, J. Paik, M. A. Abidi</i>, <b>\"Normal Vector Voting: Crease "
      "Detection and Curvature Estimation on Large, Noisy Meshes\"</b>, Graphical Models 64 (2002).");
}

void AddParameters(RichParameterList& par) {
  for (const auto& p : nvv::FilterParameterTable()) {
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
  for (const auto& p : nvv::FilterParameterTable()) {
    const QString name = QString::fromUtf8(p.name);
    if (!par.hasParameter(name)) continue;  // scripts written for an older version keep the defaults
    double value = 0;
    switch (p.type) {
      case nvv::ParamType::Float: value = par.getFloat(name); break;
      case nvv::ParamType::Int: value = par.getInt(name); break;
      case nvv::ParamType::Bool: value = par.getBool(name) ? 1 : 0; break;
      case nvv::ParamType::Enum: value = par.getEnum(name); break;
    }
    const std::string err = nvv::SetOption(options, p.name, value);
    if (!err.empty()) return QString::fromStdString(err);
  }
  return QString::fromStdString(nvv::ValidateOptions(options));
}

int OutputMask() {
  return MeshModel::MM_VERTNORMAL | MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR |
         MeshModel::MM_VERTFLAGSELECT | MeshModel::MM_VERTCURVDIR;
}

Outcome Run(MeshModel& mm, const nvv::FilterOptions& options, const QString& resultPly, vcg::CallBackPos* cb) {
  Outcome out;
  CMeshO& m = mm.cm;
  if (!resultPly.isEmpty()) {  // refuse an unwritable destination before any work
    const QFileInfo dir(QFileInfo(resultPly).absolutePath());
    if (!dir.isDir() || !dir.isWritable() || QFileInfo(resultPly).isDir()) {
      out.error = QStringLiteral("Normal Vector Voting: cannot write the results PLY '%1' (its folder is missing or not "
                                 "writable). The mesh was not changed.").arg(resultPly);
      return out;
    }
  }
  if (m.vn == 0) {
    out.error = QStringLiteral("Normal Vector Voting: the mesh is empty.");
    return out;
  }
  if (m.fn == 0) {
    out.error = QStringLiteral("Normal Vector Voting: the mesh has no faces (a point cloud?). "
                               "It needs a triangle mesh: reconstruct a surface first.");
    return out;
  }
  nvv::Progress progress;
#ifdef NVV_MESHLAB_API_2025
  // 2022.02+ ignores the callback's result (no cancelling); PyMeshLab's may return false.
  if (cb) progress = [cb](int pos, const char* text) { cb(pos, text); return true; };
#else
  if (cb) progress = [cb](int pos, const char* text) { return cb(pos, text); };
#endif
  std::vector<nvv::VertexResult> res;
  nvv::Status st;
  try {  // the compact graph and the results of a huge mesh may not fit: refuse, never throw into MeshLab
    st = vcg::tri::NormalVectorVoting<CMeshO>::Compute(m, options.core, res, out.summary, progress);
  } catch (const std::bad_alloc&) {
    st = nvv::Status();
    st.message = "Out of memory: the mesh's working copy and results did not fit.";
    res.clear();
  }
  if (!st.ok) {
    out.error = QStringLiteral("Normal Vector Voting: ") + QString::fromStdString(st.message) +
                (st.cancelled ? QString() : QStringLiteral(" The mesh was not changed."));
    return out;
  }
  // Only now is the mesh touched: enable the components and write every output.
  const auto needs = nvv::ApplyResults<CMeshO>::NeedsFor(options);
  int mask = MeshModel::MM_VERTCURVDIR;
  if (needs.quality) mask |= MeshModel::MM_VERTQUALITY;
  if (needs.color) mask |= MeshModel::MM_VERTCOLOR;
  mm.updateDataMask(mask);
  nvv::ApplyResults<CMeshO>::Apply(m, res, options);
  // MeshLab's selection filters (Delete Selected Vertices, Laplacian "selected only", ...) trust
  // the mesh's count of selected vertices, so keep it true.
  if (options.selection != nvv::SelectionMode::None) m.svn = int(vcg::tri::UpdateSelection<CMeshO>::VertexCount(m));
  if (cb) cb(100, "Normal vector voting: done");

  out.ok = true;
  if (!resultPly.isEmpty()) {
    std::string err;
    if (nvv::WriteResultPly(resultPly.toStdString(), m, res, true, err))
      out.log << QStringLiteral("Normal vector voting: all results written to %1").arg(resultPly);
    else
      out.log << QStringLiteral("Normal vector voting: warning: could not write %1: %2").arg(resultPly, QString::fromStdString(err));
  }
  out.log << QString::fromStdString(nvv::SummaryLine(out.summary));
  out.log << QStringLiteral("Normal vector voting: neighbourhood k = %1 mean edge lengths -> absolute radius %2; "
                            "crease angle %3 deg (epsilon %4), corner angle %5 deg (eta %6)%7")
                 .arg(options.core.k).arg(out.summary.radius)
                 .arg(options.core.creaseAngleDeg).arg(out.summary.epsilon, 0, 'g', 4)
                 .arg(options.core.cornerAngleDeg).arg(out.summary.eta, 0, 'g', 4)
                 .arg(out.summary.signAwareUsed ? QStringLiteral(", sign-aware rule") : QStringLiteral(", paper's rule"));
  for (const auto& w : out.summary.warnings) out.log << QStringLiteral("Normal vector voting: warning: ") + QString::fromStdString(w);
  return out;
}

std::map<std::string, QVariant> SummaryValues(const nvv::Summary& s) {
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
  v["mean_edge_length"] = s.meanEdge;
  v["epsilon"] = s.epsilon;
  v["eta"] = s.eta;
  v["sign_aware_rule"] = s.signAwareUsed;
  v["seconds"] = s.secondsTotal;
  v["seconds_pass1"] = s.secondsPass1;
  v["seconds_pass2"] = s.secondsPass2;
  return v;
}

}  // namespace nvv_meshlab
