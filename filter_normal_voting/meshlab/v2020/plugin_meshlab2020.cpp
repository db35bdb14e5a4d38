#include "plugin_meshlab2020.h"

#include "meshlab/common/meshlab_filter_common.h"

NormalVectorVotingPlugin::NormalVectorVotingPlugin() {
  typeList << FP_NORMAL_VECTOR_VOTING;
  for (FilterIDType tt : types()) actionList << new QAction(filterName(tt), this);
}

QString NormalVectorVotingPlugin::pluginName() const { return QStringLiteral("FilterNormalVectorVoting"); }

QString NormalVectorVotingPlugin::filterName(FilterIDType) const { return nvv_meshlab::FilterName(); }

QString NormalVectorVotingPlugin::filterInfo(FilterIDType) const { return nvv_meshlab::FilterInfo(); }

MeshFilterInterface::FilterClass NormalVectorVotingPlugin::getClass(QAction*) {
  return FilterClass(MeshFilterInterface::Normal | MeshFilterInterface::VertexColoring | MeshFilterInterface::Quality);
}

MeshFilterInterface::FILTER_ARITY NormalVectorVotingPlugin::filterArity(QAction*) const { return SINGLE_MESH; }

int NormalVectorVotingPlugin::postCondition(QAction*) const { return nvv_meshlab::OutputMask(); }

void NormalVectorVotingPlugin::initParameterSet(QAction*, MeshModel&, RichParameterList& par) {
  nvv_meshlab::AddParameters(par);
}

bool NormalVectorVotingPlugin::applyFilter(QAction*, MeshDocument& md, const RichParameterList& par,
                                           vcg::CallBackPos* cb) {
  // meshlabserver prints "Problem with filter" but not errorMessage: the reason also goes to the log.
  auto fail = [this](const QString& why) {
    errorMessage = why;
    Log(GLLogStream::WARNING, qUtf8Printable(why));
    return false;
  };
  if (md.mm() == nullptr) return fail(QStringLiteral("Normal Vector Voting: no mesh is loaded."));
  nvv::FilterOptions options;
  QString resultPly;
  const QString bad = nvv_meshlab::ReadOptions(par, options, resultPly);
  if (!bad.isEmpty()) return fail(QStringLiteral("Normal Vector Voting: ") + bad + QStringLiteral(" The mesh was not changed."));
  const nvv_meshlab::Outcome out = nvv_meshlab::Run(md, options, resultPly, cb);
  if (!out.ok) return fail(out.error);
  for (const QString& line : out.log) Log(qUtf8Printable(line));
  return true;
}

MESHLAB_PLUGIN_NAME_EXPORTER(NormalVectorVotingPlugin)
