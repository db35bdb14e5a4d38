# The wheel holds a compiled MeshLab plugin and no Python extension module: it fits any Python 3
# that PyMeshLab 2025.7 supports, on one platform. bdist_wheel would otherwise call it pure
# ("py3-none-any"), which pip would install on any machine.
import os

from setuptools import Distribution, setup
from setuptools.command.bdist_wheel import bdist_wheel

HERE = os.path.dirname(os.path.abspath(__file__))
PLUGIN = os.path.join(HERE, "pymeshlab_normal_voting", "lib", "libfilter_normal_voting.so")


class BinaryDistribution(Distribution):
    """Holds a compiled file: installed into platlib (the wheel's root), not purelib."""

    def has_ext_modules(self):
        return True


class PluginWheel(bdist_wheel):
    def get_tag(self):
        # The plugin's platform: the build script checks the glibc and libstdc++ symbol versions
        # the plugin needs against PyMeshLab 2025.7.post1's own tag (manylinux_2_35_x86_64).
        return "py3", "none", os.environ.get("NVV_WHEEL_PLATFORM", "manylinux_2_35_x86_64")


if not os.path.isfile(PLUGIN):
    raise SystemExit("pymeshlab_normal_voting: %s is missing; build the wheel with "
                     "scripts/pymeshlab/run-tests-pymeshlab.sh" % PLUGIN)

setup(distclass=BinaryDistribution, cmdclass={"bdist_wheel": PluginWheel})
