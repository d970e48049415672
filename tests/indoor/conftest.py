import pytest

from ewa_mcp.envs.kitchen.session import KitchenSession
from ewa_mcp.envs.kitchen.sim import KitchenSim


@pytest.fixture
def anyio_backend():
    return "asyncio"


def new_session(scene: str = "FloorPlan3", seed: int = 0) -> KitchenSession:
    session = KitchenSession(KitchenSim(None), "sim", scene, seed)
    session.reset()
    return session
