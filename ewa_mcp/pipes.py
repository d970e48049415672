"""Command-line output into a pipe that closes early (``ewa-mcp tasks list | head``).

When the reader goes away, the next write (or the flush at exit) raises BrokenPipeError, and Python prints
a traceback and then an "Exception ignored ... BrokenPipeError" line. A command whose reader left has
nothing more to say: it stops quietly with the status a shell gives a tool ended by SIGPIPE (128 + 13).
The default SIGPIPE action (die on the signal) is not used: the MCP server writes to sockets and to its
client's stdout, where a closed peer is an event to handle, not a reason to vanish.
"""

from __future__ import annotations

import functools
import os
import sys
from collections.abc import Callable

CLOSED_PIPE_STATUS = 128 + 13  # 141, as for `yes | head` under `set -o pipefail`


def _detach_stdout() -> None:
    """Point stdout at /dev/null so the interpreter's final flush has nowhere to fail."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except (OSError, ValueError):  # stdout is not a real file (a test's capture): nothing will flush into a pipe
        pass


def quiet_on_closed_pipe(main: Callable[..., int]) -> Callable[..., int]:
    """Wrap a command's main(argv) so that a closed stdout ends it quietly with CLOSED_PIPE_STATUS."""

    @functools.wraps(main)
    def wrapper(*args: object, **kwargs: object) -> int:
        try:
            status = main(*args, **kwargs)
            sys.stdout.flush()  # buffered output meets the closed pipe here, not at interpreter exit
            return status
        except BrokenPipeError:
            _detach_stdout()
            return CLOSED_PIPE_STATUS
        except BaseExceptionGroup as group:  # an async main (anyio task groups) wraps the error in a group
            if group.split(BrokenPipeError)[1] is not None:  # something else went wrong too: not ours to hide
                raise
            _detach_stdout()
            return CLOSED_PIPE_STATUS

    return wrapper
