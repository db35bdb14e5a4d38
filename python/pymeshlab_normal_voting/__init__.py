"""Normal Vector Voting for PyMeshLab 2025.7.

Importing this package loads the filter plugin shipped inside it into PyMeshLab and adds the
filter to ``pymeshlab.MeshSet`` as ``compute_normal_vector_voting`` (PyMeshLab only adds
methods for the plugins it finds at its own import). Loading is idempotent: a plugin that
PyMeshLab already loaded (e.g. a copy in PyMeshLab's own ``lib/plugins`` folder) is kept.
"""
import os

import pymeshlab

__version__ = "0.1.0"

#: PyMeshLab's name of the filter (``MeshSet.compute_normal_vector_voting``).
FILTER_NAME = "compute_normal_vector_voting"

#: The plugin file inside this package.
PLUGIN_PATH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib", "libfilter_normal_voting.so")


def load():
    """Loads the plugin into PyMeshLab unless it is there already; returns the filter's name."""
    if FILTER_NAME not in pymeshlab.filter_list():
        pymeshlab.load_plugin(PLUGIN_PATH)
    if not hasattr(pymeshlab.MeshSet, FILTER_NAME):
        setattr(pymeshlab.MeshSet, FILTER_NAME, pymeshlab.bind_function(FILTER_NAME))
    return FILTER_NAME


load()
