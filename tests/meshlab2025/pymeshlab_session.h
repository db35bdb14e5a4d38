// What PyMeshLab 2025.7 does when a script runs
//     ms = pymeshlab.MeshSet(); pymeshlab.load_plugin(path); ms.load_new_mesh(f)
//     d = ms.compute_normal_vector_voting(neighbourhood_k=4); ms.save_current_mesh(g)
// written with the same MeshLab 2025.07 calls, in C++ (PyMeshLab cannot be installed here).
// A Session is a MeshSet: a MeshDocument with its log; filters are found by python name in
// pymeshlab::functionSetInstance() and applied the way PyMeshLab's MeshSet::applyFilter does.
#ifndef NVV_TESTS_MESHLAB2025_PYMESHLAB_SESSION_H
#define NVV_TESTS_MESHLAB2025_PYMESHLAB_SESSION_H

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QString>

#include <map>
#include <stdexcept>
#include <string>

#include <common/globals.h>
#include <common/mlexception.h>
#include <common/ml_document/mesh_document.h>
#include <common/plugins/plugin_manager.h>
#include <common/python/function_set.h>
#include <common/python/python_utils.h>
#include <common/utilities/load_save.h>

namespace nvv2025 {

// Python keyword arguments: booleans 0/1, enums by index, meshes by id; everything as a number.
typedef std::map<std::string, double> Kwargs;
typedef std::map<std::string, QVariant> Dict;

// MeshLab's plugins the tests use (the five of the double core build) and our plugin, loaded
// into the process-wide plugin manager once, as `import pymeshlab` + `pymeshlab.load_plugin`.
// meshlabPluginDir holds MeshLab's plugins; only filter and IO plugins are loaded from it (no
// QApplication is needed for them), through a folder of links as PyMeshLab's own plugin folder.
inline void LoadPluginsOnce(const std::string& meshlabPluginDir, const std::string& ourPlugin, const std::string& tmp) {
  static bool done = false;
  if (done) return;
  done = true;
  const QString links = QString::fromStdString(tmp) + "/meshlab-plugins";
  QDir().mkpath(links);
  for (const char* name : {"libio_base.so", "libfilter_meshing.so", "libfilter_unsharp.so", "libfilter_sampling.so",
                           "libfilter_select.so"}) {
    const QString target = QString::fromStdString(meshlabPluginDir) + "/" + name;
    if (!QFileInfo::exists(target)) throw std::runtime_error("missing MeshLab plugin " + target.toStdString());
    QFile::remove(links + "/" + name);
    QFile::link(target, links + "/" + name);
  }
  PluginManager& pm = meshlab::pluginManagerInstance();
  pm.loadPlugins(QDir(links));                             // PyMeshLab: its package's plugin folder
  pm.loadPlugin(QString::fromStdString(ourPlugin));        // pymeshlab.load_plugin(path)
  MeshLabPlugin* ours = nullptr;
  for (MeshLabPlugin* p : pm.pluginIterator())
    if (p->pluginFileInfo().absoluteFilePath() == QFileInfo(QString::fromStdString(ourPlugin)).absoluteFilePath()) ours = p;
  // The function set was built from the plugins present then; a plugin loaded later is added.
  FilterPlugin* fp = dynamic_cast<FilterPlugin*>(ours);
  if (!fp) throw std::runtime_error("our plugin did not load as a filter plugin");
  pymeshlab::FunctionSet& fs = pymeshlab::functionSetInstance();
  if (!fs.containsFilterFunction(fp->pythonFilterName(fp->actions().front()))) fs.loadFilterPlugin(fp);
}

// PyMeshLab always passes a progress callback, and some of MeshLab's filters (Quadric Edge
// Collapse) call it without checking for null.
inline bool QuietProgress(const int, const char*) { return true; }

class Session {
 public:
  MeshDocument md;

  // ms.load_new_mesh(path): MeshLab's importer, the mesh becomes the current one.
  MeshModel& LoadNewMesh(const std::string& path) {
    const std::list<MeshModel*> loaded = meshlab::loadMeshWithStandardParameters(QString::fromStdString(path), md);
    if (loaded.empty()) throw MLException("nothing loaded from " + QString::fromStdString(path));
    md.setCurrentMesh(loaded.front()->id());
    return *loaded.front();
  }

  // ms.<pythonName>(**kwargs): returns the filter's dict; MLException propagates, as to Python.
  // Text arguments (file names) go in `strings`.
  Dict Apply(const std::string& pythonName, const Kwargs& kwargs = {}, vcg::CallBackPos* cb = nullptr,
             const std::map<std::string, std::string>& strings = {}) {
    pymeshlab::FunctionSet& fs = pymeshlab::functionSetInstance();
    const QString py = QString::fromStdString(pythonName);
    if (!fs.containsFilterFunction(py)) throw MLException("no filter named " + py);
    const pymeshlab::Function& f = fs.filterFunction(py);
    PluginManager& pm = meshlab::pluginManagerInstance();
    QAction* action = pm.filterAction(f.meshlabFunctionName());
    FilterPlugin* fp = pm.getFilterPluginFromAction(action);
    if (!action || !fp) throw MLException("no action for " + f.meshlabFunctionName());
    RichParameterList rpl = fp->initParameterList(action, md);
    for (const auto& kw : kwargs) {
      const QString key = QString::fromStdString(kw.first);
      if (!f.contains(key)) throw MLException("filter " + py + " has no parameter " + key);
      const QString name = f.getFilterFunctionParameter(key).meshlabName();
      const Value& current = rpl.getParameterByName(name).value();
      if (current.isBool()) rpl.setValue(name, BoolValue(kw.second != 0));
      else if (current.isInt()) rpl.setValue(name, IntValue(int(kw.second)));
      else if (current.isFloat()) rpl.setValue(name, FloatValue(float(kw.second)));
      else throw MLException("unsupported parameter type of " + key);
    }
    for (const auto& kw : strings) {
      const QString key = QString::fromStdString(kw.first);
      if (!f.contains(key)) throw MLException("filter " + py + " has no parameter " + key);
      rpl.setValue(f.getFilterFunctionParameter(key).meshlabName(), StringValue(QString::fromStdString(kw.second)));
    }
    fp->setLog(&md.Log);
    if (md.mm() != nullptr) md.mm()->updateDataMask(fp->getRequirements(action));
    unsigned int postConditionMask = MeshModel::MM_UNKNOWN;
    Dict out = fp->applyFilter(action, rpl, md, postConditionMask, cb ? cb : &QuietProgress);
    if (postConditionMask == MeshModel::MM_UNKNOWN) postConditionMask = fp->postCondition(action);
    for (MeshModel& m : md.meshIterator()) vcg::tri::UpdateBounding<CMeshO>::Box(m.cm);
    return out;
  }

  // Python name -> (MeshLab name, default) of every parameter of a filter, as PyMeshLab lists them.
  static const pymeshlab::Function& FunctionOf(const std::string& pythonName) {
    return pymeshlab::functionSetInstance().filterFunction(QString::fromStdString(pythonName));
  }

  // ms.save_current_mesh(path): MeshLab's exporter with PyMeshLab's default mask (every
  // component the format can hold and the mesh has).
  void SaveCurrentMesh(const std::string& path) {
    const QString file = QString::fromStdString(path);
    const QString ext = QFileInfo(file).suffix().toLower();
    IOPlugin* io = meshlab::pluginManagerInstance().outputMeshPlugin(ext);
    if (!io) throw MLException("no exporter for " + ext);
    int capability = 0, defaultBits = 0;
    io->exportMaskCapability(ext, capability, defaultBits);
    int mask = 0;
    for (int bit : pymeshlab::capabilitiesBits)
      if ((capability & bit) && md.mm()->hasDataMask(MeshModel::io2mm(bit))) mask |= bit;
    io->setLog(&md.Log);
    io->save(ext, file, *md.mm(), mask, io->initSaveParameter(ext, *md.mm()));
  }
};

}  // namespace nvv2025

#endif
