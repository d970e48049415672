from pathlib import Path

import pytest

from ewa_mcp.envs.kitchen.session import KitchenSession
from ewa_mcp.envs.kitchen.sim import KitchenSim
from ewa_mcp.core.taskmodel import TaskStore


@pytest.fixture
def anyio_backend():
    return "asyncio"


def new_session(scene: str = "FloorPlan3", seed: int = 0) -> KitchenSession:
    session = KitchenSession(KitchenSim(None), "sim", scene, seed)
    session.reset()
    return session


@pytest.fixture(scope="module")
def hard() -> list:
    """The cooking hard tasks as released, in id order (the hard forms' tests share them)."""
    tasks = Path(__file__).resolve().parents[2] / "tasks"
    return sorted((t for t in TaskStore([tasks]).all() if t.domain == "cooking" and t.difficulty == "hard"),
                  key=lambda t: t.id)
