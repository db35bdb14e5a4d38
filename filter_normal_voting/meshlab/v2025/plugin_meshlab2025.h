// The filter as a MeshLab 2022.02+ plugin (FilterPlugin), built for MeshLab 2025.07 and
// PyMeshLab 2025.7. A thin layer: everything it does is in meshlab/meshlab_filter_common.h.
// PyMeshLab calls it as MeshSet.compute_normal_vector_voting(**parameters) and gets the
// run's summary back as a dict; a refusal raises PyMeshLabException with the reason.
#ifndef NVV_MESHLAB2025_PLUGIN_MESHLAB2025_H
#define NVV_MESHLAB2025_PLUGIN_MESHLAB2025_H

#include <common/plugins/interfaces/filter_plugin.h>

class NormalVectorVotingPlugin : public QObject, public FilterPlugin {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID)
  Q_INTERFACES(FilterPlugin)

 public:
  enum { FP_NORMAL_VECTOR_VOTING };

  NormalVectorVotingPlugin();
  QString pluginName() const override;
  QString vendor() const override;
  QString filterName(ActionIDType filter) const override;
  QString pythonFilterName(ActionIDType filter) const override;
  QString filterInfo(ActionIDType filter) const override;
  FilterClass getClass(const QAction*) const override;
  FilterArity filterArity(const QAction*) const override;
  int postCondition(const QAction*) const override;
  using FilterPlugin::initParameterList;
  RichParameterList initParameterList(const QAction*, const MeshModel& m) override;
  // Returns the summary (nvv_meshlab::SummaryValues); throws MLException, mesh unchanged.
  std::map<std::string, QVariant> applyFilter(const QAction* filter, const RichParameterList& par, MeshDocument& md,
                                              unsigned int& postConditionMask, vcg::CallBackPos* cb) override;
};

#endif
