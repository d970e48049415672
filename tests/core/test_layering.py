"""The house's rules, checked on the installed layout (websites/ and graders/ inside ewa_mcp/, as the wheel
installs them, mirrored by scripts/installed_layout.py):

- no import cycle between modules, counting every import (deferred ones inside functions and those under
  ``TYPE_CHECKING`` too);
- the kernel (``ewa_mcp.core``) runs with only a throwaway domain registered, and serving, playing and grading
  one of its episodes imports no built-in world.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import grimp
import networkx as nx
import pytest

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def installed(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("layout")
    subprocess.run([sys.executable, str(ROOT / "scripts" / "installed_layout.py"), str(out)], check=True,
                   capture_output=True)
    return out


def import_graph(layout: Path) -> nx.DiGraph:
    sys.path.insert(0, str(layout))
    saved = {k: v for k, v in sys.modules.items() if k == "ewa_mcp" or k.startswith("ewa_mcp.")}
    for name in saved:
        del sys.modules[name]
    try:
        graph = grimp.build_graph("ewa_mcp", cache_dir=None)
    finally:
        sys.path.remove(str(layout))
        for name in [k for k in sys.modules if k == "ewa_mcp" or k.startswith("ewa_mcp.")]:
            del sys.modules[name]
        sys.modules.update(saved)
    edges = nx.DiGraph()
    for module in graph.modules:
        edges.add_node(module)
        for imported in graph.find_modules_directly_imported_by(module):
            # "from package import module" is an edge to the module; a package's own __init__ is not a cycle
            if not module.startswith(imported + "."):
                edges.add_edge(module, imported)
    return edges


def test_the_installed_layout_has_every_package(installed):
    for package in ("ewa_mcp/core", "ewa_mcp/envs/kitchen", "ewa_mcp/websites/shop", "ewa_mcp/graders"):
        assert (installed / package / "__init__.py").exists(), package


def test_no_import_cycles(installed):
    graph = import_graph(installed)
    assert graph.number_of_nodes() > 150
    assert graph.has_edge("ewa_mcp.graders.episode", "ewa_mcp.core.registry")  # installed names are edges
    cycles = sorted(sorted(c) for c in nx.strongly_connected_components(graph) if len(c) > 1)
    assert not cycles, "import cycles (break each by moving the shared part down a layer):\n" + "\n".join(
        " <-> ".join(c) for c in cycles)


KERNEL_ALONE = r"""
import json, sys
import anyio
from mcp import Client

from ewa_mcp.core import registry
from tests.core.lamp_domain import DOMAIN

registry.use_only(DOMAIN)

from ewa_mcp.core.taskmodel import Task, TaskStore
from ewa_mcp.graders import grade_run
from ewa_mcp.server import ServerConfig, build_server

run_dir = sys.argv[1]
task = Task.model_validate({"id": "lamp-1", "domain": "lighting", "intent": "switch the lamp on", "step_limit": 5,
                            "start": {"environment": "embodied", "embodied": {"kind": "lamp", "lit": False}},
                            "embodied_goals": [{"kind": "lamp_lit", "lit": True}]})

async def main():
    mcp, episodes = build_server(ServerConfig(run_dir=__import__("pathlib").Path(run_dir), task_dirs=[]))
    episodes.tasks.add(task)
    async with Client(mcp) as client:
        names = [t.name for t in (await client.list_tools()).tools]
        started = await client.call_tool("start_episode", {"task_id": "lamp-1"})
        eid = started.structured_content["episode_id"]
        await client.call_tool("lamp_switch", {"episode_id": eid, "state": "on"})
        await client.call_tool("finish_episode", {"episode_id": eid})
    return names

names = anyio.run(main)
report = grade_run(run_dir)
worlds = sorted(m for m in sys.modules if m.startswith("ewa_mcp.envs"))
print(json.dumps({"tools": names, "success": report.episodes[0].overall_success, "worlds": worlds}))
"""


def test_the_kernel_runs_with_only_a_throwaway_domain(tmp_path):
    env = {**os.environ, "PYTHONPATH": str(ROOT), "EWA_RUNS_DIR": str(tmp_path / "runs")}
    out = subprocess.run([sys.executable, "-c", KERNEL_ALONE, str(tmp_path / "run")], env=env, cwd=ROOT,
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr[-3000:]
    result = json.loads(out.stdout.strip().splitlines()[-1])
    assert result["worlds"] == [], f"the kernel imported built-in worlds: {result['worlds']}"
    assert result["success"] is True
    assert "lamp_switch" in result["tools"] and not any(t.startswith(("kitchen_", "browser_", "street_", "geo_"))
                                                        for t in result["tools"])
