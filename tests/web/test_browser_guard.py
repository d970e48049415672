"""The browser's network guard against a hostile page on an allowed origin: no UDP leaves by WebRTC or
WebTransport, and a refused navigation (form, script, link, redirect) leaves the tab on the page it was on."""

from __future__ import annotations

import socket

import pytest

from ewa_mcp.core.environment import EnvError
from ewa_mcp.envs.browser.chromium import BrowserService, ChromiumInfo

from .helpers import open_env

pytestmark = [pytest.mark.anyio, pytest.mark.browser]


def test_the_guard_flags_are_passed_to_every_launch():
    service = BrowserService(ChromiumInfo("/bin/true", "explicit"), allowed_origins=["http://127.0.0.1:8701"])
    try:
        args = service.launch_args()
    finally:
        service._guard.close()
    # Each spelling is read by one build (the full browser, the headless shell); either alone leaks in the other.
    assert "--webrtc-ip-handling-policy=disable_non_proxied_udp" in args
    assert "--force-webrtc-ip-handling-policy=disable_non_proxied_udp" in args
    assert any(a.startswith("--proxy-server=http://127.0.0.1:") for a in args)


async def test_a_hostile_page_sends_no_udp(web_services):
    listeners = []
    for family, address in ((socket.AF_INET, "127.0.0.1"), (socket.AF_INET6, "::1")):
        try:
            sock = socket.socket(family, socket.SOCK_DGRAM)
            sock.bind((address, 0))
        except OSError:
            continue  # no IPv6 loopback here
        listeners.append(sock)
    # One port for both families where possible, so every candidate the page adds points at a listener.
    port = listeners[0].getsockname()[1]
    if len(listeners) > 1:
        listeners[1].close()
        listeners = listeners[:1]
        try:
            six = socket.socket(socket.AF_INET6, socket.SOCK_DGRAM)
            six.bind(("::1", port))
            listeners.append(six)
        except OSError:
            pass
    env = await open_env(web_services, f"fixture:/webrtc?port={port}")
    try:
        page = env.tabs[0].page
        # The page reports when its probes have had their time (it waits 1.5 s after starting them).
        await page.wait_for_function("document.getElementById('done').textContent.startsWith('finished')",
                                     timeout=30_000)
        report = await page.text_content("#done")
        assert "error:" not in report, report  # the probes ran: RTCPeerConnection exists, the offer was made
    finally:
        await env.close()
    received = []
    for sock in listeners:
        sock.setblocking(False)
        while True:
            try:
                received.append(sock.recvfrom(4096))
            except BlockingIOError:
                break
        sock.close()
    assert received == [], f"{len(received)} datagrams reached the local listener; the page said: {report}"


@pytest.mark.parametrize("control, target", [
    ("button 'Send off-site'", "http://example.com/collect"),  # a form's POST
    ("button 'Leave by script'", "http://example.com/scripted"),  # location.href = ...
    ("link 'Redirect out'", "http://example.com/landing"),  # a 302 off-site
    ("link 'External site'", "http://example.com/"),
])
async def test_a_refused_navigation_leaves_the_tab_where_it_was(web_services, control, target):
    env = await open_env(web_services)
    try:
        start = env.tabs[0].page.url
        with pytest.raises(EnvError, match="refused.*the page is unchanged") as refused:
            await env.click(control)
        assert target in str(refused.value)
        page = env.tabs[0].page
        assert page.url == start, page.url  # not chrome-error://chromewebdata/
        assert await page.title() == "Fixture catalogue"
        assert (await env.observe()).data["title"] == "Fixture catalogue"
        assert len(env.tabs) == 1
        assert (await env.final_state())["history"] == [start]
    finally:
        await env.close()
