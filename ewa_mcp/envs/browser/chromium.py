"""Finding and running the one Chromium of a server process.

``find_chromium()`` is the discovery others may reuse: an explicit path (argument or
``EWA_CHROMIUM``), else Playwright's bundled build when installed, else a system Chromium.
``BrowserService`` is the shared service (``await services.get("chromium", chromium_service)``):
it launches the browser on first use and relaunches it when it crashed or was closed.
"""

from __future__ import annotations

import json
import os
import platform
import shutil
import socket
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

import anyio

from .idlegc import IdleCollector
from .pool import ContextPool

# Without the background-networking flags Chromium keeps trying to reach Google services,
# which floods a closed network with failing requests and slows start-up.
PLATFORM_FLAGS: tuple[str, ...] = (
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
)

# WebRTC may send UDP only through the proxy, which refuses everything (BrowserService): no WebRTC traffic at
# all. The full browser and the headless shell each read one of these two spellings.
WEBRTC_GUARD_FLAGS: tuple[str, ...] = (
    "--webrtc-ip-handling-policy=disable_non_proxied_udp",
    "--force-webrtc-ip-handling-policy=disable_non_proxied_udp",
)

# Debian's package "chromium-headless-shell": the headless-only build (what Playwright itself runs
# headless). It loads and snapshots the sites' pages ~35 % faster than the full browser in
# headless mode (benchmarks/bench_browser.py), so headless runs prefer it where it is installed.
HEADLESS_SHELL_CANDIDATES: tuple[str, ...] = (
    "/usr/bin/chromium-headless-shell",
)

SYSTEM_CANDIDATES: tuple[str, ...] = (
    "/usr/bin/chromium",
    "/usr/bin/chromium-browser",
    "/usr/bin/google-chrome",
    "/usr/bin/google-chrome-stable",
    "/snap/bin/chromium",
)

INSTALL_HINT = (
    "install one with `apt-get install chromium` (Debian/Ubuntu; CI does this), or "
    "`playwright install chromium` where the Playwright CDN is reachable, or point "
    "EWA_CHROMIUM at a Chromium/Chrome executable"
)


class ChromiumNotFoundError(RuntimeError):
    """No usable Chromium; the message says how to install one."""


@dataclass(frozen=True)
class ChromiumInfo:
    path: str
    source: Literal["explicit", "playwright", "system"]

    def launch_args(self) -> list[str]:
        args = list(PLATFORM_FLAGS)
        if hasattr(os, "geteuid") and os.geteuid() == 0:
            args.append("--no-sandbox")  # Chromium refuses to start sandboxed as root
        return args


def _playwright_browsers_dir() -> Path:
    override = os.environ.get("PLAYWRIGHT_BROWSERS_PATH")
    if override and override != "0":
        return Path(override)
    if platform.system() == "Darwin":
        return Path.home() / "Library" / "Caches" / "ms-playwright"
    if platform.system() == "Windows":
        return Path(os.environ.get("LOCALAPPDATA", Path.home())) / "ms-playwright"
    return Path(os.environ.get("XDG_CACHE_HOME", Path.home() / ".cache")) / "ms-playwright"


def _expected_revision() -> str | None:
    """The Chromium revision this Playwright package was built against (from its browsers.json)."""
    try:
        import playwright

        manifest = Path(playwright.__file__).parent / "driver" / "package" / "browsers.json"
        for entry in json.loads(manifest.read_text(encoding="utf-8"))["browsers"]:
            if entry["name"] == "chromium":
                return str(entry["revision"])
    except (OSError, KeyError, ValueError, ImportError):
        return None
    return None


def playwright_bundled_chromium() -> Path | None:
    """Playwright's own build of the revision it expects, if `playwright install` has run."""
    revision = _expected_revision()
    if revision is None:
        return None
    root = _playwright_browsers_dir()
    arm = platform.machine().lower() in ("arm64", "aarch64")
    candidates = [
        root / f"chromium_headless_shell-{revision}"
        / ("chrome-headless-shell-linux-arm64" if arm else "chrome-headless-shell-linux64") / "chrome-headless-shell",
        root / f"chromium-{revision}" / ("chrome-linux-arm64" if arm else "chrome-linux64") / "chrome",
        root / f"chromium-{revision}" / "chrome-linux" / "chrome",  # older layout
    ]
    for path in candidates:
        if path.is_file() and os.access(path, os.X_OK):
            return path
    return None


def find_chromium(explicit: str | None = None, headless: bool = True) -> ChromiumInfo:
    """The Chromium to launch; raises ChromiumNotFoundError naming the fix when there is none.

    Order: an explicit path, Playwright's bundled build, (headless only) Debian's headless
    shell, then a system Chromium or Chrome."""
    if explicit:
        path = Path(explicit)
        if path.is_file() and os.access(path, os.X_OK):
            return ChromiumInfo(str(path), "explicit")
        raise ChromiumNotFoundError(
            f"the Chromium executable {explicit!r} (from the browser options or EWA_CHROMIUM) does not exist or "
            f"is not executable; fix the path, or unset it to use a discovered browser, or {INSTALL_HINT}"
        )
    bundled = playwright_bundled_chromium()
    if bundled is not None:
        return ChromiumInfo(str(bundled), "playwright")
    for candidate in (HEADLESS_SHELL_CANDIDATES if headless else ()) + SYSTEM_CANDIDATES:
        if os.path.isfile(candidate) and os.access(candidate, os.X_OK):
            return ChromiumInfo(candidate, "system")
    for name in ("chromium", "chromium-browser", "google-chrome"):
        found = shutil.which(name)
        if found:
            return ChromiumInfo(found, "system")
    looked = ", ".join(SYSTEM_CANDIDATES)
    raise ChromiumNotFoundError(f"no Chromium found (looked for Playwright's bundled build and {looked}); {INSTALL_HINT}")


class BrowserService:
    """One Chromium per server process, relaunched on demand after a crash or close.

    ``launches`` counts launches so that an environment can tell that the browser its
    context lived in is gone and rebuild its tabs in the new one.

    The request guard: Chromium sends every request to a proxy that refuses connections (a
    loopback port we hold bound but never listen on), except requests to ``allowed_origins``
    (the embedded sites and the browser allowlist, matched on scheme, host and port), which go
    direct. ``<-loopback>`` removes Chromium's implicit bypass of loopback and link-local
    addresses, so another loopback port (this server's own HTTP port, any local service) and
    cloud metadata addresses are refused too. Being the browser's own network layer, it also
    covers redirects, sub-resources, popups and requests made by scripts, and it costs no
    interception round trip per request (``context.route`` did: ewa_mcp/envs/browser/README.md).

    WebRTC does not ask the proxy: by default a page's RTCPeerConnection sends UDP (STUN, TURN,
    connectivity checks to any candidate a script adds, mDNS) straight to any address. The WebRTC
    IP handling policy ``disable_non_proxied_udp`` makes it use the proxy or nothing, and the proxy
    refuses, so WebRTC reaches nothing. The full Chromium reads the policy from
    ``--webrtc-ip-handling-policy``, the headless shell from ``--force-webrtc-ip-handling-policy``;
    both are passed. WebTransport (QUIC) goes through the proxy resolution too and fails the same
    way (tests/web/test_browser_guard.py sends both at a local UDP listener)."""

    def __init__(self, info: ChromiumInfo, headless: bool = True, allowed_origins: list[str] | tuple[str, ...] = (),
                 pool: ContextPool | None = None, collector: IdleCollector | None = None):
        self.info = info
        self.headless = headless
        self.allowed_origins = list(allowed_origins)
        self.launches = 0
        self._guard = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        self._guard.bind(("127.0.0.1", 0))  # bound, never listening: connecting is refused at once
        self._playwright: Any = None
        self._browser: Any = None
        self._lock = anyio.Lock()
        self._closed = False
        self.pool = pool or ContextPool()  # warm contexts handed from one episode to the next (pool.py)
        self.collector = collector or IdleCollector()  # garbage collection in quiet renderers (idlegc.py)

    async def browser(self) -> Any:
        """A connected Browser, launching (or relaunching) Chromium when needed."""
        if self._browser is not None and self._browser.is_connected():
            return self._browser
        async with self._lock:
            if self._closed:
                raise RuntimeError("the browser service has been shut down")
            if self._browser is None or not self._browser.is_connected():
                await self._launch()
                self.collector.start(self.current_browser)
        return self._browser

    async def _launch(self) -> None:
        from playwright.async_api import Error as PlaywrightError
        from playwright.async_api import async_playwright

        if self._playwright is None:
            self._playwright = await async_playwright().start()
        kwargs = {"executable_path": self.info.path, "headless": self.headless, "args": self.launch_args()}
        try:
            self._browser = await self._playwright.chromium.launch(**kwargs)
        except PlaywrightError as exc:
            if "Connection closed" not in str(exc) and "has been closed" not in str(exc):
                raise RuntimeError(f"Chromium at {self.info.path} failed to start: {exc}") from exc
            # The Playwright driver itself died with the browser: start a fresh one.
            self._playwright = await async_playwright().start()
            self._browser = await self._playwright.chromium.launch(**kwargs)
        self.launches += 1

    def launch_args(self) -> list[str]:
        bypass = ["<-loopback>", *(bypass_rule(origin) for origin in self.allowed_origins)]
        return [*self.info.launch_args(), f"--proxy-server=http://127.0.0.1:{self._guard.getsockname()[1]}",
                f"--proxy-bypass-list={';'.join(bypass)}", *WEBRTC_GUARD_FLAGS]

    def current_browser(self) -> Any | None:
        """The browser if it is up, else None; never launches one (for background work)."""
        return self._browser if self.is_alive() else None

    def is_alive(self) -> bool:
        return self._browser is not None and self._browser.is_connected()

    async def browser_pid(self) -> int | None:
        """The browser process id (tests kill it to exercise crash recovery)."""
        browser = await self.browser()
        session = await browser.new_browser_cdp_session()
        try:
            info = await session.send("SystemInfo.getProcessInfo")
        finally:
            await session.detach()
        for process in info.get("processInfo", []):
            if process.get("type") == "browser":
                return int(process["id"])
        return None

    async def aclose(self) -> None:
        self._closed = True
        await self.collector.stop()
        await self.pool.aclose()
        browser, self._browser = self._browser, None
        driver, self._playwright = self._playwright, None
        if browser is not None:
            try:
                await browser.close()
            except Exception:
                pass  # already gone
        if driver is not None:
            try:
                await driver.stop()
            except Exception:
                pass
        self._guard.close()


def bypass_rule(origin: str) -> str:
    """Chromium's proxy-bypass rule for exactly one origin: scheme, host and (effective) port."""
    from urllib.parse import urlsplit

    parts = urlsplit(origin)
    port = parts.port or {"http": 80, "https": 443}[parts.scheme]
    host = parts.hostname or ""
    return f"{parts.scheme}://{f'[{host}]' if ':' in host else host}:{port}"


async def chromium_service(services: Any) -> BrowserService:
    """Services factory: ``await services.get("chromium", chromium_service)``.

    Reads ``services.settings`` (the browser options: executable, headless, the pool's and the idle
    collector's settings, config.py; EWA_CHROMIUM) and the embedded sites' URLs (the websites
    service, started here when it is not yet: the request guard needs their ports at launch), and
    launches at once so that a missing or broken browser is reported by the first web episode, not
    its first action."""
    from ewa_mcp.websites.serve import site_service
    from .safety import UrlPolicy

    settings = services.settings
    browser = settings.browser
    sites = await services.get("websites", site_service)
    origins = UrlPolicy(sites.urls, browser.allow_origins).allowed_origins
    service = BrowserService(find_chromium(settings.chromium_path(), browser.headless), headless=browser.headless,
                             allowed_origins=origins,
                             pool=ContextPool(keep_idle=browser.pool_keep_idle, idle_s=browser.pool_idle_s),
                             collector=IdleCollector(every_s=browser.idle_gc_s))
    await service.browser()
    return service
