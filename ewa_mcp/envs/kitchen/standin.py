"""A headless stand-in for the AI2-THOR Unity build, backed by the kitchen simulator.

It speaks ai2thor's FIFO protocol, so the unmodified ai2thor client library drives it as if it
were Unity: the client starts it through ``local_executable_path``, it answers every action with
AI2-THOR metadata (and an RGB frame — a top-down drawing — when images are on). Existing
ai2thor code can run the 30 kitchens on a laptop without a GPU or a display::

    from ai2thor.controller import Controller
    from ewa_mcp.envs.kitchen.standin import standin_command

    c = Controller(local_executable_path=standin_command(), x_display=":0", scene="FloorPlan1")
    c.step(action="MoveAhead")

Protocol (ai2thor.fifo_server): two named pipes given by AI2THOR_FIFO_SERVER_PIPE_PATH (we write)
and AI2THOR_FIFO_CLIENT_PIPE_PATH (we read). A message is a sequence of fields, each a
struct "!BI" header (field type, body length) and a body, ended by an END_OF_MESSAGE header.
We send METADATA (msgpack) and optionally RGB_IMAGE (raw bottom-up RGB rows); we read ACTION
(JSON). The first message is the startup metadata with sequenceId 0.
"""

from __future__ import annotations

import json
import os
import shlex
import struct
import sys
from typing import Any, BinaryIO

from .sim import KitchenSim

METADATA, ACTION, RGB_IMAGE, END_OF_MESSAGE = 1, 2, 4, 255
HEADER = struct.Struct("!BI")


def standin_command() -> str:
    """The ``local_executable_path`` value that launches the stand-in with this Python."""
    return f"{shlex.quote(sys.executable)} -m ewa_mcp.envs.kitchen.standin"


def _screen_size(argv: list[str]) -> tuple[int, int]:
    width = height = 300
    for flag, value in zip(argv, argv[1:]):
        if flag == "-screen-width":
            width = int(value)
        elif flag == "-screen-height":
            height = int(value)
    return width, height


class StandIn:
    def __init__(self, sim: KitchenSim, out: BinaryIO, inp: BinaryIO | None = None):
        self.sim = sim
        self.out = out
        self.inp = inp
        self.render_default = True  # AI2-THOR renders a frame unless told not to

    def send(self, metadata: dict[str, Any], sequence_id: int, frame: bytes | None) -> None:
        import msgpack

        metadata["sequenceId"] = sequence_id
        body = msgpack.dumps(
            {"agents": [metadata], "sequenceId": sequence_id, "activeAgentId": 0, "thirdPartyCameras": []},
            use_bin_type=True,
        )
        parts = [HEADER.pack(METADATA, len(body)), body]
        if frame is not None:
            parts += [HEADER.pack(RGB_IMAGE, len(frame)), frame]
        parts.append(HEADER.pack(END_OF_MESSAGE, 0))
        self.out.write(b"".join(parts))
        self.out.flush()

    def read_action(self) -> dict[str, Any] | None:
        assert self.inp is not None
        action: dict[str, Any] | None = None
        while True:
            header = self.inp.read(HEADER.size)
            if len(header) < HEADER.size:
                return None  # the client closed the pipe: shut down
            field, length = HEADER.unpack(header)
            if field == END_OF_MESSAGE:
                return action
            body = self.inp.read(length)
            if field == ACTION:
                action = json.loads(body)

    def frame(self) -> bytes:
        from PIL import Image

        from .kitchen_map import render_topdown

        assert self.sim.spec is not None and self.sim.last_event is not None  # both set by the scene's reset
        spec = self.sim.spec
        reachable = [(x, z) for x, z in (spec.world(c) for c in spec.reachable)]
        def label(object_id: str) -> str:
            obj = self.sim.by_id.get(object_id)
            return obj.name if obj is not None else object_id

        image = render_topdown(self.sim.last_event.metadata, reachable, width=self.sim.width, height=self.sim.height,
                               label=label, panel=False)
        # ai2thor reads frames bottom row first (as Unity writes them)
        return image.transpose(Image.Transpose.FLIP_TOP_BOTTOM).tobytes()

    def handle(self, action: dict[str, Any]) -> None:
        sequence_id = int(action.get("sequenceId", 0))
        render = action.pop("renderImage", None)
        if action.get("action") == "Initialize" and render is not None:
            self.render_default = bool(render)
        event = self.sim.step(action)
        want_frame = self.render_default if render is None else bool(render)
        self.send(event.metadata, sequence_id, self.frame() if want_frame and self.sim.spec is not None else None)

    def serve(self) -> None:
        while True:
            action = self.read_action()
            if action is None:
                return
            self.handle(action)


def main(argv: list[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    server_path = os.environ.get("AI2THOR_FIFO_SERVER_PIPE_PATH")
    client_path = os.environ.get("AI2THOR_FIFO_CLIENT_PIPE_PATH")
    if not server_path or not client_path:
        print("ewa-mcp AI2-THOR stand-in: start me through ai2thor's Controller(local_executable_path=...); "
              "the AI2THOR_FIFO_SERVER_PIPE_PATH and AI2THOR_FIFO_CLIENT_PIPE_PATH variables are missing",
              file=sys.stderr)
        return 2
    width, height = _screen_size(argv)
    sim = KitchenSim(None, width=width, height=height)
    with open(server_path, "wb") as out:
        server = StandIn(sim, out)
        server.send(sim.step(action="Pass").metadata, 0, None)  # startup message, as Unity sends on launch
        with open(client_path, "rb") as inp:
            server.inp = inp
            server.serve()
    return 0


if __name__ == "__main__":
    sys.exit(main())
