"""Server time per page of every embedded site that exists in this build.

For each site: its representative URLs (the app module's ``BENCH_URLS`` when it has one, else
pages found by following the site's own links from "/"), each requested in-process through
the ASGI interface (no sockets, so the figure is the site's own time plus a thin client).
Prints JSON: per site p50/p95/max in ms over all requests, per-URL p50, and whether the
site-wide p50 meets the target (<= 20 ms).

    .venv/bin/python benchmarks/bench_websites.py            # BENCH_N=30 requests per URL
"""

from __future__ import annotations

import asyncio
import importlib
import json
import logging
import os
import re
import statistics
import time
from typing import Any

import httpx

from ewa_mcp.websites.common import SiteContext
from ewa_mcp.websites.serve import SITES, available_sites

logging.getLogger("httpx").setLevel(logging.WARNING)

N = int(os.environ.get("BENCH_N", "30"))
TARGET_MS = 20.0
CRAWL_LIMIT = 12


def pct(values: list[float], q: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(round(q * (len(ordered) - 1))))]


async def crawl(client: httpx.AsyncClient, base: str) -> list[str]:
    """Site-relative pages reachable from "/" (breadth first), for sites without BENCH_URLS."""
    seen, queue = ["/"], ["/"]
    while queue and len(seen) < CRAWL_LIMIT:
        response = await client.get(queue.pop(0))
        if "html" not in response.headers.get("content-type", ""):
            continue
        for href in re.findall(r'href="([^"#]+)"', response.text):
            href = href.replace("&amp;", "&")
            if href.startswith(base):
                href = href[len(base):] or "/"
            if href.startswith("/") and not href.startswith("//") and href not in seen:
                seen.append(href)
                queue.append(href)
                if len(seen) >= CRAWL_LIMIT:
                    break
    return seen


async def bench_site(name: str, factory: Any, urls: dict[str, str]) -> dict[str, Any]:
    app = factory(SiteContext(urls=urls))
    base = urls[name]
    module = importlib.import_module(SITES[name].partition(":")[0])
    async with app.router.lifespan_context(app):
        transport = httpx.ASGITransport(app=app)
        async with httpx.AsyncClient(transport=transport, base_url=base) as client:
            pages = list(getattr(module, "BENCH_URLS", None) or await crawl(client, base))
            times: list[float] = []
            per_url: dict[str, float] = {}
            errors: dict[str, int] = {}
            for url in pages:
                first = await client.get(url)  # warm-up (template compilation, lazy data loads)
                if first.status_code >= 500:
                    errors[url] = first.status_code
                    continue
                samples = []
                for _ in range(N):
                    start = time.perf_counter()
                    await client.get(url)
                    samples.append((time.perf_counter() - start) * 1000)
                per_url[url] = round(statistics.median(samples), 3)
                times += samples
    result: dict[str, Any] = {"pages": len(per_url), "requests": len(times), "per_url_p50_ms": per_url}
    if times:
        result.update(p50_ms=round(pct(times, 0.5), 3), p95_ms=round(pct(times, 0.95), 3),
                      max_ms=round(max(times), 3), meets_target=pct(times, 0.5) <= TARGET_MS)
    if errors:
        result["server_errors"] = errors
    return result


async def main() -> dict[str, Any]:
    factories = available_sites()
    urls = {site: f"http://{site}.bench" for site in factories}
    sites = {}
    for name, factory in factories.items():
        try:
            sites[name] = await bench_site(name, factory, urls)
        except Exception as exc:  # one broken site must not hide the others' figures
            sites[name] = {"error": f"{type(exc).__name__}: {exc}"}
    return {"benchmark": "websites_server_time_per_page", "target_p50_ms": TARGET_MS, "requests_per_url": N,
            "sites": sites,
            "all_meet_target": all(s.get("meets_target", False) for s in sites.values())}


if __name__ == "__main__":
    print(json.dumps(asyncio.run(main()), indent=2))
