// The filter as a MeshLab 2020.09 plugin (MeshFilterInterface). A thin layer: everything it
// does is in meshlab_filter_common.h.
#ifndef NVV_MESHLAB_PLUGIN_MESHLAB2020_H
#define NVV_MESHLAB_PLUGIN_MESHLAB2020_H

#include <common/interfaces.h>

class NormalVectorVotingPlugin : public QObject, public MeshFilterInterface {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

 public:
  enum { FP_NORMAL_VECTOR_VOTING };

  NormalVectorVotingPlugin();
  QString pluginName() const override;
  QString filterName(FilterIDType filter) const override;
  QString filterInfo(FilterIDType filter) const override;
  FilterClass getClass(QAction*) override;
  FILTER_ARITY filterArity(QAction*) const override;
  int postCondition(QAction*) const override;
  void initParameterSet(QAction*, MeshModel& m, RichParameterList& par) override;
  bool applyFilter(QAction* filter, MeshDocument& md, const RichParameterList& par, vcg::CallBackPos* cb) override;
};

#endif
