"""The floor under the whole-suite time: what the suite's browser steps cost with Playwright alone.

Two measurements, printed in one JSON object:

* per step, with the Playwright library alone in this process (no MCP, no server, no environment):
  a page load (``goto`` to ``load``, then the AI-mode ARIA snapshot every step of ewa-mcp returns)
  and an in-place step (typing into a field, then the snapshot), on the recipes site's pages and
  the same Chromium build. Wall ms (median) and CPU ms per step of every process involved
  (Chromium's, Playwright's node driver, this Python), read from /proc;
* from a run directory (``bench_oracle_suite.py --run-dir DIR``, or any ``ewa-mcp eval`` run):
  how many browser steps of each kind its episodes made. Multiplied by the per-step CPU, that is
  the CPU the browser work of the run needs however little a server adds, and divided by the cores,
  the shortest time it could take here.

    .venv/bin/python benchmarks/bench_floor.py [--steps 60] [--run-dir DIR]

Linux only (/proc). The machine should be otherwise idle: CPU time under contention runs high.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import re
import statistics
import threading
import time
from pathlib import Path
from typing import Any

from bench_memory import descendants  # the process tree under this one, read from /proc

HZ = os.sysconf("SC_CLK_TCK")
# Tools whose step loads a new document (the start of a web episode loads the start page).
PAGE_LOADS = {"start_episode", "browser_goto", "browser_click", "browser_go_back", "browser_go_forward",
              "browser_new_tab"}
IN_PLACE = {"browser_type", "browser_press", "browser_scroll", "browser_hover", "browser_snapshot",
            "browser_select", "browser_tab_focus", "browser_close_tab", "get_observation"}


def _cpu_ticks(pid: int) -> int | None:
    try:
        text = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return None
    fields = text[text.rfind(")") + 2:].split()
    return int(fields[11]) + int(fields[12])  # utime + stime


class CpuMeter:
    """CPU seconds of this process and all its descendants between start() and stop(), sampled
    every 100 ms so that processes that come and go are counted."""

    def __init__(self) -> None:
        self.base: dict[int, int] = {}
        self.last: dict[int, int] = {}
        self._running = False
        self._thread: threading.Thread | None = None

    def _sample(self, first: bool = False) -> None:
        for pid in descendants(os.getpid()):
            ticks = _cpu_ticks(pid)
            if ticks is None:
                continue
            self.base.setdefault(pid, ticks if first else 0)
            self.last[pid] = ticks

    def _loop(self) -> None:
        while self._running:
            self._sample()
            time.sleep(0.1)

    def start(self) -> None:
        self._sample(first=True)
        self._running = True
        self._thread = threading.Thread(target=self._loop, daemon=True)
        self._thread.start()

    def stop(self) -> float:
        self._running = False
        if self._thread is not None:
            self._thread.join()
        self._sample()
        return sum(self.last[pid] - self.base.get(pid, 0) for pid in self.last) / HZ


async def measure_steps(steps: int) -> dict[str, Any]:
    from playwright.async_api import async_playwright

    from ewa_mcp.core.services import Services
    from ewa_mcp.envs.browser.chromium import find_chromium
    from ewa_mcp.websites.serve import site_service

    services = Services()
    sites = await services.get("websites", site_service)
    base = sites.urls["recipes"]
    urls = [f"{base}/", f"{base}/?q=Egg+Bhurji+Toast&difficulty=simple", f"{base}/recipe/r115",
            f"{base}/recipe/r115?step=5"]
    info = find_chromium()
    out: dict[str, Any] = {"chromium": info.path}
    async with async_playwright() as playwright:
        browser = await playwright.chromium.launch(executable_path=info.path, args=info.launch_args())
        page = await (await browser.new_context(viewport={"width": 1280, "height": 720})).new_page()

        async def load(i: int) -> None:
            await page.goto(urls[i % len(urls)], wait_until="load")
            await page.aria_snapshot(mode="ai")

        async def in_place(i: int) -> None:
            await page.get_by_role("searchbox").first.fill(f"soup {i}")
            await page.aria_snapshot(mode="ai")

        for name, step in (("page_load", load), ("in_place", in_place)):
            if name == "in_place":
                await page.goto(urls[0], wait_until="load")
            for i in range(5):
                await step(i)  # warm-up
            meter, walls = CpuMeter(), []
            meter.start()
            for i in range(steps):
                started = time.perf_counter()
                await step(i)
                walls.append((time.perf_counter() - started) * 1000)
            cpu = meter.stop()
            out[name] = {"steps": steps, "wall_median_ms": round(statistics.median(walls), 1),
                         "cpu_ms_per_step": round(cpu * 1000 / steps, 1)}
        await browser.close()
    await services.aclose()
    return out


def count_run(run_dir: Path) -> dict[str, Any]:
    """Browser steps of a run directory, by kind (page loads, in-place steps), and episodes.

    Counted low rather than high: a click is a page load only when the tab's URL changed (a form
    that reloads the same URL counts as in place)."""
    loads = in_place = episodes = 0
    for trajectory in run_dir.glob("*/trajectory.jsonl"):
        episodes += 1
        last_url = None
        for line in trajectory.read_text().splitlines():
            record = json.loads(line)
            tool, env = str(record.get("tool")), record.get("environment")
            if env != "web" or not record.get("ok", True):
                continue
            found = re.search(r" URL: (\S+)", record.get("observation") or "")
            url = found.group(1) if found else last_url
            if tool in PAGE_LOADS and (tool != "browser_click" or url != last_url):
                loads += 1
            elif tool in IN_PLACE or tool.startswith("browser_") or tool == "browser_click":
                in_place += 1
            last_url = url
    return {"episodes": episodes, "page_loads": loads, "in_place_steps": in_place}


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--steps", type=int, default=60)
    parser.add_argument("--run-dir", type=Path, default=None)
    args = parser.parse_args()
    report: dict[str, Any] = {"benchmark": "Playwright-alone floor of the browser steps",
                              "cpu_count": os.cpu_count(), "load_average_1m_before": round(os.getloadavg()[0], 2)}
    report.update(asyncio.run(measure_steps(args.steps)))
    if args.run_dir is not None:
        counts = count_run(args.run_dir)
        cpu_s = (counts["page_loads"] * report["page_load"]["cpu_ms_per_step"]
                 + counts["in_place_steps"] * report["in_place"]["cpu_ms_per_step"]) / 1000
        cores = os.cpu_count() or 1
        report["run"] = {"run_dir": str(args.run_dir), **counts,
                         "floor_cpu_seconds": round(cpu_s, 1),
                         "floor_minutes_on_all_cores": round(cpu_s / cores / 60, 2)}
    report["load_average_1m_after"] = round(os.getloadavg()[0], 2)
    print(json.dumps(report, indent=2))


if __name__ == "__main__":
    main()
