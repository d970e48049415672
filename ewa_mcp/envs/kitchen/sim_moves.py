"""The built-in kitchen's lifecycle and navigation actions: Initialize, Reset, Pass, moves, turns, looks, Teleport.

Each ``_a_<ActionName>`` answers the AI2-THOR action of that name: it checks every precondition (raising
``ActionFailed`` with what to do instead) before it changes the agent's pose.
"""

from __future__ import annotations

import math
from typing import Any

from .scenes import GRID, SCENE_NAMES, canonical_scene, cell_to_world
from .sim_objects import AGENT_Y, ActionFailed, SimEvent
from .sim_world import SimWorld


class MoveActions(SimWorld):
    # -- lifecycle
    def _a_Initialize(self, args: dict[str, Any]) -> dict[str, float]:
        grid = float(args.get("gridSize", GRID))
        if abs(grid - GRID) > 1e-6:
            raise ActionFailed(f"gridSize {grid} is not supported: these kitchens are laid out on a {GRID} m grid",
                               "InvalidArgument")
        visibility = float(args.get("visibilityDistance", self.visibility_distance))
        if visibility <= 0:
            raise ActionFailed("visibilityDistance must be positive", "InvalidArgument")
        self.visibility_distance = visibility
        self.render_image = bool(args.get("renderImage", self.render_image))
        return {"cameraNearPlane": 0.1, "cameraFarPlane": 20.0}

    def _a_Reset(self, args: dict[str, Any]) -> SimEvent:
        scene = str(args.get("sceneName") or (self.spec.name if self.spec else "FloorPlan1"))
        try:
            canonical_scene(scene)
        except ValueError as exc:
            raise ActionFailed(str(exc), "InvalidArgument") from None
        return self.reset(scene)

    def _a_GetScenesInBuild(self, args: dict[str, Any]) -> list[str]:
        return [f"{name}_physics" for name in SCENE_NAMES] + list(SCENE_NAMES)

    def _a_ChangeResolution(self, args: dict[str, Any]) -> None:
        self.width = int(args.get("x", self.width))
        self.height = int(args.get("y", self.height))

    def _a_Pass(self, args: dict[str, Any]) -> None:
        return None

    _a_Done = _a_Pass

    def _a_GetReachablePositions(self, args: dict[str, Any]) -> list[dict[str, float]]:
        assert self.spec is not None
        return [
            {"x": x, "y": AGENT_Y, "z": z}
            for x, z in sorted(cell_to_world(c, self.spec.width, self.spec.depth) for c in self.spec.reachable)
        ]

    # -- navigation
    def _move(self, args: dict[str, Any], turn: float) -> None:
        assert self.spec is not None
        magnitude = float(args.get("moveMagnitude", GRID))
        steps = round(magnitude / GRID)
        if steps < 1 or abs(steps * GRID - magnitude) > 1e-6:
            raise ActionFailed(f"moveMagnitude must be a positive multiple of {GRID} m", "InvalidArgument")
        rad = math.radians(self.rotation + turn)
        dx, dz = round(math.sin(rad)), round(math.cos(rad))
        cell = self.cell
        for _ in range(steps):
            nxt = (cell[0] + dx, cell[1] + dz)
            if nxt not in self.spec.reachable:
                blocker = self._blocker(nxt)
                raise ActionFailed(f"Agent is blocked: moving {GRID} m would hit {blocker}")
            cell = nxt
        self.cell = cell

    def _blocker(self, cell: tuple[int, int]) -> str:
        assert self.spec is not None
        x, z = cell_to_world(cell, self.spec.width, self.spec.depth)
        for obj in self.objects:
            b = obj.box
            if b is not None and obj.object_type not in ("Floor", "StoveKnob") and obj.parent is None \
                    and b.x0 <= x <= b.x1 and b.z0 <= z <= b.z1:
                return obj.object_id
        return "a wall"

    def _a_MoveAhead(self, args: dict[str, Any]) -> None:
        self._move(args, 0.0)

    def _a_MoveBack(self, args: dict[str, Any]) -> None:
        self._move(args, 180.0)

    def _a_MoveRight(self, args: dict[str, Any]) -> None:
        self._move(args, 90.0)

    def _a_MoveLeft(self, args: dict[str, Any]) -> None:
        self._move(args, -90.0)

    def _rotate(self, args: dict[str, Any], sign: float) -> None:
        degrees = float(args.get("degrees", 90.0))
        if degrees <= 0 or abs(degrees / 90.0 - round(degrees / 90.0)) > 1e-6:
            raise ActionFailed("degrees must be a positive multiple of 90 in these grid kitchens", "InvalidArgument")
        self.rotation = (self.rotation + sign * degrees) % 360.0

    def _a_RotateRight(self, args: dict[str, Any]) -> None:
        self._rotate(args, 1.0)

    def _a_RotateLeft(self, args: dict[str, Any]) -> None:
        self._rotate(args, -1.0)

    def _look(self, args: dict[str, Any], sign: float) -> None:
        horizon = self.horizon + sign * float(args.get("degrees", 30.0))
        if not -30.0 <= horizon <= 60.0:
            raise ActionFailed("the camera horizon must stay between -30 and 60 degrees")
        self.horizon = horizon

    def _a_LookDown(self, args: dict[str, Any]) -> None:
        self._look(args, 1.0)

    def _a_LookUp(self, args: dict[str, Any]) -> None:
        self._look(args, -1.0)

    def _a_Teleport(self, args: dict[str, Any]) -> None:
        assert self.spec is not None
        position = args.get("position") or {k: args[k] for k in ("x", "y", "z") if k in args}
        if "x" not in position or "z" not in position:
            raise ActionFailed("Teleport needs a position {x, y, z}", "MissingArguments")
        x, z = float(position["x"]), float(position["z"])
        cell = self.spec.cell(x, z)
        wx, wz = cell_to_world(cell, self.spec.width, self.spec.depth)
        if abs(wx - x) > 0.01 or abs(wz - z) > 0.01 or cell not in self.spec.reachable:
            raise ActionFailed(f"Teleport failed: ({x:.2f}, {z:.2f}) is not a reachable position; "
                               "use one from GetReachablePositions")
        rotation = args.get("rotation", self.rotation)
        if isinstance(rotation, dict):
            rotation = rotation.get("y", self.rotation)
        rotation = float(rotation) % 360.0
        if abs(rotation / 90.0 - round(rotation / 90.0)) > 1e-6:
            raise ActionFailed("rotation must be a multiple of 90 degrees in these grid kitchens", "InvalidArgument")
        horizon = float(args.get("horizon", self.horizon))
        if not -30.0 <= horizon <= 60.0:
            raise ActionFailed("horizon must be between -30 and 60 degrees", "InvalidArgument")
        self.cell, self.rotation, self.horizon = cell, round(rotation / 90.0) * 90.0 % 360.0, horizon

    _a_TeleportFull = _a_Teleport
