import pytest

from ewa_mcp.indoor.session import KitchenSession
from ewa_mcp.indoor.sim import KitchenSim


@pytest.fixture
def anyio_backend():
    return "asyncio"


def new_session(scene: str = "FloorPlan3", seed: int = 0) -> KitchenSession:
    session = KitchenSession(KitchenSim(None), "sim", scene, seed)
    session.reset()
    return session
