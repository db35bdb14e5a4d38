#include "plugin_meshlab2025.h"

#include "meshlab/common/meshlab_filter_common.h"

NormalVectorVotingPlugin::NormalVectorVotingPlugin() {
  typeList = {FP_NORMAL_VECTOR_VOTING};
  for (ActionIDType tt : types()) actionList.push_back(new QAction(filterName(tt), this));
}

QString NormalVectorVotingPlugin::pluginName() const { return QStringLiteral("FilterNormalVectorVoting"); }

QString NormalVectorVotingPlugin::vendor() const { return QStringLiteral("filter_normal_voting"); }

QString NormalVectorVotingPlugin::filterName(ActionIDType) const { return nvv_meshlab::FilterName(); }

QString NormalVectorVotingPlugin::pythonFilterName(ActionIDType) const { return nvv_meshlab::PythonName(); }

QString NormalVectorVotingPlugin::filterInfo(ActionIDType) const { return nvv_meshlab::FilterInfo(); }

FilterPlugin::FilterClass NormalVectorVotingPlugin::getClass(const QAction*) const {
  // Not VertexColoring: MeshLab would then show vertex colours after every run, also when the
  // patch colours are on the faces; the run's postConditionMask says which colours it wrote.
  return FilterClass(FilterPlugin::Normal | FilterPlugin::Quality);
}

FilterPlugin::FilterArity NormalVectorVotingPlugin::filterArity(const QAction*) const { return SINGLE_MESH; }

int NormalVectorVotingPlugin::postCondition(const QAction*) const { return nvv_meshlab::OutputMask(); }

RichParameterList NormalVectorVotingPlugin::initParameterList(const QAction*, const MeshModel&) {
  RichParameterList par;
  nvv_meshlab::AddParameters(par);
  return par;
}

std::map<std::string, QVariant> NormalVectorVotingPlugin::applyFilter(const QAction*, const RichParameterList& par,
                                                                      MeshDocument& md, unsigned int& postConditionMask,
                                                                      vcg::CallBackPos* cb) {
  // The GUI shows the exception's text in "Filter Failure"; PyMeshLab raises it. Both also log it.
  auto fail = [this](const QString& why) {
    log(GLLogStream::WARNING, why.toStdString());
    throw MLException(why);
  };
  if (md.mm() == nullptr) fail(QStringLiteral("Normal Vector Voting: no mesh is loaded."));
  nvv::FilterOptions options;
  QString resultPly;
  const QString bad = nvv_meshlab::ReadOptions(par, options, resultPly);
  if (!bad.isEmpty()) fail(QStringLiteral("Normal Vector Voting: ") + bad + QStringLiteral(" The mesh was not changed."));
  const nvv_meshlab::Outcome out = nvv_meshlab::Run(md, options, resultPly, cb);
  if (!out.ok) fail(out.error);
  for (const QString& line : out.log) log(line.toStdString());
  postConditionMask = nvv_meshlab::OutputMask(&options);
  return nvv_meshlab::SummaryValues(out);
}

MESHLAB_PLUGIN_NAME_EXPORTER(NormalVectorVotingPlugin)
