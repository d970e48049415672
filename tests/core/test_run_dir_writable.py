"""Where a server records when it may not write where it was started (an MCP client often starts it in `/`):
no run directory set -> the per-user data directory; a run directory set and not writable -> `serve` refuses to
start with an error naming the setting; one that breaks later -> start_episode says which setting to change."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import textwrap
from collections.abc import Iterator
from pathlib import Path

import anyio
import pytest
from mcp import Client

from ewa_mcp.server import ServerConfig, build_server

# The child: a stdio MCP client that starts `ewa-mcp serve` in its own working directory (as a desktop client
# does) and starts one episode; it prints what came back.
CLIENT = textwrap.dedent("""
    import json, sys
    import anyio
    from mcp import Client, StdioServerParameters

    async def main():
        params = StdioServerParameters(command=sys.executable, args=["-m", "ewa_mcp", "serve"], env=dict(__import__("os").environ))
        async with Client(params) as client:
            r = await client.call_tool("start_episode", {"task_id": "demo-hello"})
            text = " ".join(getattr(c, "text", "") for c in r.content)
            episode = (r.structured_content or {}).get("episode_id")
            if episode:
                await client.call_tool("finish_episode", {"episode_id": episode, "answer": "hello"})
            print(json.dumps({"error": r.is_error, "text": text, "episode_id": episode}))

    anyio.run(main)
""")


def clean_env(**extra: str) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith("EWA_") and k not in ("XDG_DATA_HOME", "HOME")}
    return {**env, **extra}


@pytest.fixture
def read_only(tmp_path: Path) -> Iterator[Path]:
    """A directory this process cannot create anything in: mode 555, and immutable when running as root
    (root passes permission bits; the immutable flag binds it too)."""
    ro = tmp_path / "read-only"
    ro.mkdir()
    ro.chmod(0o555)
    immutable = os.geteuid() == 0
    if immutable:
        if shutil.which("chattr") is None:
            pytest.skip("running as root without chattr (e2fsprogs): no directory root cannot write")
        done = subprocess.run(["chattr", "+i", str(ro)], capture_output=True, text=True, check=False)
        if done.returncode != 0:
            pytest.skip(f"running as root and `chattr +i` is refused here ({done.stderr.strip()}): "
                        "no directory root cannot write")
    try:
        yield ro
    finally:
        if immutable:
            subprocess.run(["chattr", "-i", str(ro)], check=False)
        ro.chmod(0o755)


def test_read_only_working_directory_records_in_the_user_data_directory(read_only: Path, tmp_path: Path) -> None:
    ro, data = read_only, tmp_path / "data"
    done = subprocess.run([sys.executable, "-c", CLIENT], cwd=ro, capture_output=True, text=True, timeout=180,
                          env=clean_env(XDG_DATA_HOME=str(data), HOME=str(data)), check=False)
    assert done.returncode == 0, done.stderr[-2000:]
    result = json.loads(done.stdout.strip().splitlines()[-1])
    assert result["error"] is False, result["text"]
    episodes = list((data / "ewa-mcp" / "runs").glob(f"*/{result['episode_id']}/final_state.json"))
    assert len(episodes) == 1
    assert json.loads(episodes[0].read_text())["answer"] == "hello"
    assert list(ro.iterdir()) == []  # nothing written (or left behind by the write probe) where it was started


def test_nothing_writable_refuses_to_start_naming_the_setting(read_only: Path) -> None:
    ro = read_only
    done = subprocess.run([sys.executable, "-m", "ewa_mcp", "serve"], cwd=ro, capture_output=True, text=True,
                          timeout=120, stdin=subprocess.DEVNULL, check=False,
                          env=clean_env(XDG_DATA_HOME=str(ro / "data"), HOME=str(ro)))
    assert done.returncode == 2
    assert "episodes cannot be recorded" in done.stderr and "EWA_RUNS_DIR=DIR" in done.stderr, done.stderr
    assert "Traceback" not in done.stderr


@pytest.mark.parametrize("how", ["flag", "EWA_RUN_DIR", "EWA_RUNS_DIR"])
def test_an_unwritable_run_directory_setting_is_refused_at_start(tmp_path: Path, how: str) -> None:
    blocker = tmp_path / "a-file"
    blocker.write_text("not a directory")
    argv, env = [sys.executable, "-m", "ewa_mcp", "serve"], clean_env()
    if how == "flag":
        argv += ["--run-dir", str(blocker / "run")]
    else:
        env[how] = str(blocker / "run")
    done = subprocess.run(argv, capture_output=True, text=True, timeout=120, stdin=subprocess.DEVNULL, env=env,
                          check=False)
    assert done.returncode == 2 and "Traceback" not in done.stderr
    assert f"{blocker} is not a directory" in done.stderr
    named = "--run-dir / EWA_RUN_DIR" if how != "EWA_RUNS_DIR" else f"EWA_RUNS_DIR={blocker / 'run'}"
    assert named in done.stderr, done.stderr
    assert not blocker.is_dir()


def test_a_run_directory_that_breaks_after_start_is_named_by_start_episode(tmp_path: Path) -> None:
    run = tmp_path / "parent" / "run"

    async def start() -> tuple[bool, str]:
        mcp, _ = build_server(ServerConfig(run_dir=run))
        shutil.rmtree(tmp_path / "parent", ignore_errors=True)
        (tmp_path / "parent").write_text("the run directory's parent became a file")
        async with Client(mcp) as client:
            r = await client.call_tool("start_episode", {"task_id": "demo-hello"})
            return r.is_error, " ".join(getattr(c, "text", "") for c in r.content)

    is_error, text = anyio.run(start)
    assert is_error
    assert str(run) in text and "--run-dir DIR, EWA_RUN_DIR=DIR" in text and "nothing was started" in text
