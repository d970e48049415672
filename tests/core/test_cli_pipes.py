"""Output into a pipe whose reader has gone (`ewa-mcp tasks list | head`): the commands stop quietly, with the
status a shell reports for a tool ended by SIGPIPE, and print no traceback. The pipe here is a real one whose
read end is closed before the command starts, so its very first write meets the closed pipe."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from ewa_mcp.pipes import CLOSED_PIPE_STATUS
from ewa_mcp.core.records import EpisodeRecorder
from ewa_mcp.core.taskmodel import Task


def run_into_closed_pipe(*argv: str) -> subprocess.CompletedProcess[str]:
    read_end, write_end = os.pipe()
    os.close(read_end)
    try:
        return subprocess.run([sys.executable, *argv], stdout=write_end, stderr=subprocess.PIPE, text=True,
                              timeout=120, check=False)
    finally:
        os.close(write_end)


# argparse's --help drops a failed write itself and exits 0; the interpreter's last flush must stay quiet too.
@pytest.mark.parametrize(("argv", "status"), [(["tasks", "list"], CLOSED_PIPE_STATUS),
                                              (["tasks", "schema"], CLOSED_PIPE_STATUS), (["--help"], 0)])
def test_ewa_mcp_output_into_a_closed_pipe(argv: list[str], status: int) -> None:
    done = run_into_closed_pipe("-m", "ewa_mcp", *argv)
    assert "Traceback" not in done.stderr and "BrokenPipeError" not in done.stderr, done.stderr
    assert done.returncode == status


def test_the_same_commands_into_an_open_pipe_are_unchanged() -> None:
    done = subprocess.run([sys.executable, "-m", "ewa_mcp", "tasks", "list", "--domain", "navigation"],
                          capture_output=True, text=True, timeout=120, check=False)
    assert done.returncode == 0 and done.stdout.count("\tnavigation\t") > 100


def test_ewa_grade_output_into_a_closed_pipe(tmp_path: Path) -> None:
    task = Task.model_validate({"id": "t-1", "domain": "cooking", "intent": "answer",
                                "answer": {"kind": "text", "must_include": ["yes"]}})
    recorder = EpisodeRecorder(tmp_path / "run" / "ep-1")
    recorder.write_task(task.model_dump(mode="json"))
    recorder.write_final_state({"schema_version": 1, "episode_id": recorder.directory.name, "task_id": "t-1",
                                "domain": "cooking", "status": "finished", "end_reason": "finished", "answer": "yes"})
    recorder.close()
    done = run_into_closed_pipe("-m", "ewa_mcp.graders.cli", str(tmp_path / "run"), "--format", "json")
    assert "Traceback" not in done.stderr and "BrokenPipeError" not in done.stderr, done.stderr
    assert done.returncode == CLOSED_PIPE_STATUS


def test_an_async_main_whose_task_group_meets_the_closed_pipe_ends_quietly(monkeypatch) -> None:
    """examples/mcp_call.py runs its main under anyio: the BrokenPipeError arrives wrapped in an exception group
    (a play-tester's `mcp_call.py ... | head` printed the traceback). Anything else in the group still raises."""
    import anyio

    from ewa_mcp import pipes

    monkeypatch.setattr(pipes, "_detach_stdout", lambda: None)  # pytest's captured stdout is no real pipe

    async def main() -> int:
        async def write() -> None:
            raise BrokenPipeError

        async with anyio.create_task_group() as group:
            group.start_soon(write)
        return 0

    assert pipes.quiet_on_closed_pipe(lambda: anyio.run(main))() == CLOSED_PIPE_STATUS

    def mixed() -> int:
        raise BaseExceptionGroup("two failures", [BrokenPipeError(), ValueError("a real failure")])

    with pytest.raises(BaseExceptionGroup):
        pipes.quiet_on_closed_pipe(mixed)()
