# One Python process calling the filter many times, as a batch script does; and the README's
# Python example, run exactly as printed, with the installed package.
import os
import re
import shutil
import subprocess
import sys

import pymeshlab
from conftest import CAD, REPO, rss_bytes

CALLS = 50
MAX_RSS_GROWTH = 32 << 20  # bytes, between call 10 and call 50


def test_fifty_calls_in_one_process_give_the_same_result_in_bounded_memory():
    ms = pymeshlab.MeshSet()
    first, rss = None, []
    for i in range(CALLS):
        ms.load_new_mesh(str(CAD))
        out = ms.compute_normal_vector_voting(selection="Creases and corners")
        summary = {k: v for k, v in out.items() if not k.startswith("seconds")}
        if first is None:
            first = summary
        assert summary == first, "call %d" % (i + 1)
        assert ms.current_mesh().selected_vertex_number() == out["crease_vertices"] + out["corner_vertices"]
        ms.delete_current_mesh()
        rss.append(rss_bytes())
    assert ms.mesh_number() == 0
    growth = rss[-1] - rss[9]
    print("[repeated] %d calls; RSS after call 10: %.1f MB, after call %d: %.1f MB (growth %.2f MB)"
          % (CALLS, rss[9] / 2**20, CALLS, rss[-1] / 2**20, growth / 2**20))
    assert growth < MAX_RSS_GROWTH


def readme_example():
    text = (REPO / "README.md").read_text()
    block = re.search(r"<!-- pymeshlab-example -->\s*```python\n(.*?)```\s*<!-- end pymeshlab-example -->", text, re.S)
    assert block, "README.md has no Python example between <!-- pymeshlab-example --> markers"
    return block.group(1)


def test_readme_example_runs_as_printed(tmp_path):
    code = readme_example()
    (tmp_path / "example.py").write_text(code)
    shutil.copy(CAD, tmp_path / CAD.name)  # the example loads the sample by its file name
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    proc = subprocess.run([sys.executable, "example.py"], cwd=tmp_path, capture_output=True, text=True, env=env,
                          timeout=300)
    print(proc.stdout, proc.stderr)
    assert proc.returncode == 0
    assert "crease_vertices" in proc.stdout
