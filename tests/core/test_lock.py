"""requirements.lock pins a version inside pyproject.toml's range for every dependency `make install` installs,
so a dependency added to pyproject.toml without `make lock` fails here rather than drifting in CI."""

from __future__ import annotations

import tomllib

from packaging.requirements import Requirement
from packaging.utils import canonicalize_name

from ewa_mcp.core.paths import REPO_ROOT


def _lock() -> dict[str, str]:
    pins = {}
    for line in (REPO_ROOT / "requirements.lock").read_text(encoding="utf-8").splitlines():
        line = line.strip()
        if line and not line.startswith("#"):
            name, sep, version = line.partition("==")
            assert sep, f"requirements.lock: {line!r} is not NAME==VERSION; rewrite the file with `make lock`"
            pins[canonicalize_name(name)] = version
    return pins


def test_every_installed_requirement_is_locked_within_its_range():
    project = tomllib.loads((REPO_ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
    extras = project["optional-dependencies"]
    wanted = [Requirement(r) for r in project["dependencies"] + extras["test"] + extras["ai2thor"]]
    pins = _lock()
    problems = []
    for req in wanted:
        version = pins.get(canonicalize_name(req.name))
        if version is None:
            problems.append(f"{req.name} is not in requirements.lock")
        elif not req.specifier.contains(version, prereleases=True):
            problems.append(f"{req.name}=={version} is outside {req.specifier}")
    assert not problems, "; ".join(problems) + ". Run `make lock`, then `make test`, and commit requirements.lock"


def test_dependencies_are_ranges_not_pins():
    project = tomllib.loads((REPO_ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
    pinned = [r for r in project["dependencies"] if "==" in r]
    assert not pinned, f"pin exact versions in requirements.lock, not pyproject.toml: {pinned}"


def test_packages_installed_without_dependencies_are_locked():
    """The Makefile installs some packages with --no-deps (their declared dependencies conflict with ours); the
    lock still pins them, or `make install` would take whatever version is newest."""
    makefile = (REPO_ROOT / "Makefile").read_text(encoding="utf-8")
    line = next(line for line in makefile.splitlines() if line.startswith("NODEPS :="))
    names = line.partition(":=")[2].split()
    assert names, "NODEPS is empty in the Makefile"
    pins = _lock()
    missing = [name for name in names if canonicalize_name(name) not in pins]
    assert not missing, f"{missing} installed with --no-deps but not in requirements.lock; add NAME==VERSION there"
