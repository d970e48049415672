"""The wheel ships every package: the explicit package list in pyproject.toml must name each
directory with an __init__.py (websites/ and graders/ install as ewa_mcp.websites / ewa_mcp.graders)."""

from __future__ import annotations

import tomllib

from ewa_mcp.core.paths import REPO_ROOT


def test_every_package_is_listed():
    config = tomllib.loads((REPO_ROOT / "pyproject.toml").read_text())
    listed = set(config["tool"]["setuptools"]["packages"])
    mapping = config["tool"]["setuptools"]["package-dir"]
    found = set()
    for name, folder in mapping.items():
        root = REPO_ROOT / folder
        for init in root.rglob("__init__.py"):
            rel = init.parent.relative_to(root)
            if any(part.startswith(".") or part == "__pycache__" for part in rel.parts):
                continue
            dotted = ".".join([name, *rel.parts]) if rel.parts else name
            # A sub-folder of ewa_mcp that is itself mapped elsewhere is not a package of ewa_mcp.
            found.add(dotted)
    missing = sorted(found - listed)
    assert not missing, f"add to [tool.setuptools] packages in pyproject.toml: {missing}"
    assert not any(p.split(".")[0] != "ewa_mcp" for p in listed), "only ewa_mcp may be a top-level import name"
