import pytest


@pytest.fixture
def anyio_backend():
    return "asyncio"


@pytest.fixture(scope="session")
def world():
    from ewa_mcp.envs.street.world import get_world

    return get_world()
