"""Mirror the installed layout of the package for the linters: ``ewa_mcp/`` with ``websites/`` and ``graders/``
inside it as ``ewa_mcp/websites`` and ``ewa_mcp/graders`` (pyproject.toml's package-dir mapping), so that
import-linter and mypy see every import by its installed name (``from ewa_mcp.graders.models import ...``).

    python scripts/installed_layout.py [OUT]     # default .lint/; prints OUT

Only Python sources are copied (hard links where the file system allows), so it takes well under a second.
``make lint`` runs the contracts and the type checker on the result and maps paths back to the checkout.
"""

from __future__ import annotations

import os
import shutil
import sys
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def package_dirs() -> dict[str, Path]:
    """Installed package name -> its directory in the checkout (pyproject.toml's package-dir)."""
    config = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    mapping = config["tool"]["setuptools"]["package-dir"]
    return {name: ROOT / folder for name, folder in mapping.items() if name != "ewa_mcp.tasks"}


def build(out: Path) -> Path:
    if out.exists():
        shutil.rmtree(out)
    for name, folder in sorted(package_dirs().items()):
        target = out.joinpath(*name.split("."))
        for src in folder.rglob("*.py"):
            rel = src.relative_to(folder)
            # a mapped sub-package (ewa_mcp.websites) is copied from its own folder, never twice
            if "__pycache__" in rel.parts or any(
                    (folder / rel.parts[0]).resolve() == other.resolve() for other in package_dirs().values()
                    if other != folder):
                continue
            dst = target / rel
            dst.parent.mkdir(parents=True, exist_ok=True)
            try:
                os.link(src, dst)
            except OSError:
                shutil.copy2(src, dst)
    return out


if __name__ == "__main__":
    print(build(Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / ".lint"))
