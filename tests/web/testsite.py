"""A small fixture site that exercises every browser action; used by tests/web and benchmarks/bench_browser.py.

It is served by the real ``SiteServer`` next to the homepage (``start_fixture_sites``) under
the site name ``fixture``. Pages: a catalogue with a search form, a drop-down, a checkbox, a
hover menu, a fetch-driven counter, popups, a download, external and metadata links, a page
loading off-site images, a long page, and a per-episode visit counter keyed by the episode header (isolation checks).
"""

from __future__ import annotations

import asyncio
import html
from collections import Counter
from typing import Any

from starlette.applications import Starlette
from starlette.requests import Request
from starlette.responses import HTMLResponse, JSONResponse, PlainTextResponse, RedirectResponse, Response
from starlette.routing import Route

from ewa_mcp.websites import serve
from ewa_mcp.websites.common import SiteContext, episode_of

ITEMS = {
    1: ("Tomato Bruschetta", "Toasted bread topped with chopped tomato, basil and olive oil."),
    2: ("Lentil Soup", "A thick soup of red lentils, carrot and cumin."),
    3: ("Apple Crumble", "Baked apple slices under a buttery oat topping."),
    4: ("Egg Fried Rice", "Day-old rice fried with egg, spring onion and soy sauce."),
    5: ("Potato Salad", "Boiled potatoes with mustard dressing and chives."),
}


def _page(title: str, body: str) -> HTMLResponse:
    return HTMLResponse(
        "<!doctype html><html lang='en'><head><meta charset='utf-8'>"
        f"<title>{html.escape(title)}</title><style>"
        ".menu ul{display:none}.menu:hover ul{display:block}"
        ".spacer{height:2400px}</style></head>"
        f"<body><header><nav aria-label='Fixture'><a href='/'>Catalogue</a> <a href='/counter'>Counter</a> "
        f"<a href='/long'>Long page</a></nav></header><main>{body}</main></body></html>"
    )


def create_app(ctx: SiteContext) -> Starlette:
    visits: Counter[str] = Counter()  # per episode: proves the header reaches the site and state is keyed on it
    clicks: Counter[str] = Counter()

    async def index(request: Request) -> Response:
        ctx.emit(episode_of(request), {"site": "fixture", "type": "page_view", "path": "/"})
        items = "".join(f"<li><a href='/item/{i}'>{html.escape(name)}</a></li>" for i, (name, _) in ITEMS.items())
        return _page("Fixture catalogue", f"""
<h1>Catalogue</h1>
<ul aria-label='Items'>{items}</ul>
<form action='/search' method='get' role='search'>
  <label>Search items <input name='q' placeholder='name'></label> <button type='submit'>Search</button>
</form>
<label>Diet <select name='diet'><option>Any</option><option>Vegetarian</option><option>Vegan</option></select></label>
<label><input type='checkbox' name='fav'> Favourites only</label>
<label>Code <input value='R-17' readonly></label>
<div class='menu'><button aria-haspopup='true'>More</button><ul><li><a href='/item/3'>Hidden dessert</a></li></ul></div>
<p><button id='ping'>Count click</button> <span id='count'>Clicked 0 times</span></p>
<script>
document.getElementById('ping').addEventListener('click', () => fetch('/api/click', {{method: 'POST'}})
  .then((r) => r.json())
  .then((d) => {{ document.getElementById('count').textContent = 'Clicked ' + d.clicks + ' times'; }}));
</script>
<p><button disabled>Unavailable</button> <button onclick="this.textContent='Done'">Mark done</button></p>
<p><a href='/item/2' target='_blank'>Soup in a new tab</a> <button onclick="window.open('/item/4')">Open rice</button>
<button onclick="alert('Saved!')">Save</button></p>
<p><a href='/download'>Get the price list</a> <a href='http://example.com/'>External site</a>
<a href='http://169.254.169.254/latest/meta-data/'>Metadata</a> <a href='/redirect-out'>Redirect out</a></p>
<form action='http://example.com/collect' method='post'><input type='hidden' name='x' value='1'>
<button type='submit'>Send off-site</button></form>
<p><button onclick="location.href='http://example.com/scripted'">Leave by script</button></p>
""")

    async def form(request: Request) -> Response:
        # labels of text fields and of controls that take no text (a type into each, tests/web/test_browser_actions.py)
        return _page("Fixture form", """
<h1>Order form</h1>
<form action='/search' method='get' aria-label='Order' style='display: grid; grid-template-columns: auto 1fr'>
<label for='f-name'>Your name</label> <input id='f-name' name='q'>
<label for='f-go'>Go ahead</label> <button id='f-go' type='submit'>Find it</button>
<input type='submit' value='Send form'>
<label><input type='radio' name='size' value='s'> Small size</label>
<label for='f-agree'>I agree</label> <input type='checkbox' id='f-agree'>
<input type='number' aria-label='Quantity' value='1'>
</form>
""")

    async def offsite(request: Request) -> Response:
        return _page("Off-site resources", "<h1>Off-site resources</h1>"
                                           "<img src='http://example.com/tracker.png' alt='tracker'>"
                                           "<img src='http://169.254.169.254/pixel.png' alt='metadata pixel'>")

    async def item(request: Request) -> Response:
        n = int(request.path_params["n"])
        if n not in ITEMS:
            return _page("Not found", "<h1>No such item</h1>")
        name, text = ITEMS[n]
        nxt = n % len(ITEMS) + 1
        return _page(name, f"<h1>{html.escape(name)}</h1><p>{html.escape(text)}</p>"
                           f"<a href='/item/{nxt}'>Next item</a> <a href='#notes'>Notes</a><h2 id='notes'>Notes</h2>")

    async def search(request: Request) -> Response:
        q = request.query_params.get("q", "")
        hits = [(i, name) for i, (name, _) in ITEMS.items() if q.lower() in name.lower()]
        rows = "".join(f"<li><a href='/item/{i}'>{html.escape(name)}</a></li>" for i, name in hits)
        return _page(f"Search: {q}", f"<h1>Results for {html.escape(q)}</h1><p>{len(hits)} found</p><ul>{rows}</ul>")

    async def counter(request: Request) -> Response:
        episode = episode_of(request)
        visits[episode] += 1
        return _page("Counter", f"<h1>Visits</h1><p>Episode {html.escape(episode)} visit {visits[episode]}</p>")

    async def api_click(request: Request) -> Response:
        episode = episode_of(request)
        clicks[episode] += 1
        await asyncio.sleep(0.05)  # a slow-ish API: the observation must still show its result
        return JSONResponse({"clicks": clicks[episode]})

    async def long_page(request: Request) -> Response:
        return _page("Long page", "<h1>Top of the long page</h1><div class='spacer'></div>"
                                  "<a href='/item/5'>Bottom link</a>")

    async def download(request: Request) -> Response:
        return PlainTextResponse("tomato,1.20\n", headers={"Content-Disposition": "attachment; filename=prices.csv"})

    async def redirect_out(request: Request) -> Response:
        return RedirectResponse("http://example.com/landing", status_code=302)

    async def busy(request: Request) -> Response:
        # A click that takes effect at once, then a page too busy to answer for ?ms= milliseconds (what a
        # loaded machine looks like from the server): after the click (?when=after) or in its handler.
        ms = int(request.query_params.get("ms", "4000"))
        when = request.query_params.get("when", "after")
        spin = f"const end = Date.now() + {ms}; while (Date.now() < end) {{}}"
        work = f"setTimeout(() => {{ {spin} }}, 0);" if when == "after" else spin
        return _page("Busy page", f"""<h1>Busy page</h1><p id='state'>Not clicked</p>
<button onclick="document.getElementById('state').textContent = 'Clicked once'; document.title = 'Busy page (clicked)';
{html.escape(work)}">Start work</button>""")

    async def webrtc(request: Request) -> Response:
        # A hostile page on an allowed origin: it tries to send UDP to a local port by WebRTC, both as
        # a STUN/TURN server (ICE gathering) and as a remote candidate (connectivity checks), and
        # by WebTransport (QUIC), and says in #done how far it got (candidates gathered, ICE state).
        port = int(request.query_params.get("port", "9"))
        return _page("WebRTC probe", f"""<h1>WebRTC probe</h1><p id='done'>running</p>
<script>
(async () => {{
  const out = [];
  try {{
    const servers = [{{urls: 'stun:127.0.0.1:{port}'}},
                     {{urls: 'turn:127.0.0.1:{port}?transport=udp', username: 'u', credential: 'p'}}];
    const a = new RTCPeerConnection({{iceServers: servers}});
    const b = new RTCPeerConnection();
    a.onicecandidate = (e) => {{ if (e.candidate) out.push(e.candidate.candidate); }};
    a.createDataChannel('probe');
    await a.setLocalDescription(await a.createOffer());
    await b.setRemoteDescription(a.localDescription);
    await b.setLocalDescription(await b.createAnswer());
    await a.setRemoteDescription(b.localDescription);
    for (const ip of ['127.0.0.1', '::1']) {{
      try {{ await a.addIceCandidate({{candidate: `candidate:1 1 udp 2122260223 ${{ip}} {port} typ host`,
                                       sdpMid: '0', sdpMLineIndex: 0}}); }} catch (e) {{ out.push('add: ' + e); }}
    }}
    if (window.WebTransport) {{  // HTTP/3 over QUIC: UDP too
      for (const host of ['127.0.0.1', '[::1]']) {{
        try {{ const wt = new WebTransport(`https://${{host}}:{port}/`); wt.ready.catch(() => {{}});
               wt.closed.catch(() => {{}}); }} catch (e) {{ out.push('webtransport: ' + e); }}
      }}
    }}
    await new Promise((r) => setTimeout(r, 1500));
    out.push('state ' + a.iceConnectionState);
  }} catch (e) {{ out.push('error: ' + e); }}
  document.getElementById('done').textContent = 'finished: ' + out.join(' | ');
}})();
</script>""")

    return Starlette(routes=[
        Route("/", index), Route("/item/{n:int}", item), Route("/search", search), Route("/counter", counter),
        Route("/api/click", api_click, methods=["POST"]), Route("/long", long_page), Route("/download", download),
        Route("/redirect-out", redirect_out), Route("/offsite", offsite), Route("/webrtc", webrtc),
        Route("/busy", busy), Route("/form", form),
    ])


def start_fixture_sites(emit: Any = None) -> serve.SiteServer:
    """The real SiteServer serving the homepage plus this site as ``fixture`` (for tests and benchmarks)."""
    original = serve.SITES
    serve.SITES = {"home": original["home"], "fixture": f"{__name__}:create_app"}
    try:
        server = serve.SiteServer(emit=emit)
    finally:
        serve.SITES = original
    return server.start()
