"""Set-of-Marks: a screenshot with a labelled box around each interactive element.

The marks are drawn by the browser: an overlay (in a closed shadow root, ignoring pointer events)
is added for the one screenshot and removed right after, the way Playwright's own screenshot
masks work. Drawing them into the PNG afterwards would mean decoding and re-encoding every
screenshot, which costs about as much as taking it.
"""

from __future__ import annotations

from typing import Any

from .tree_text import Mark

# Distinct, readable colours; an element keeps its colour between screenshots (id-based).
PALETTE = ("#e6194b", "#3c8c3c", "#005ac8", "#f58230", "#911eb4", "#008c8c", "#c81ea0", "#786400", "#000080",
           "#800000")

# The marks must never hide what they mark (play-testers read "hop" for Shop and could not see which radio
# button was checked): each element gets an outline drawn just outside its box, and its number a small
# badge placed outside the box too. Where the badge goes is chosen in the page, in one pass over the marks:
# from a few spots around the box (above its left corner first; beside small controls such as radio
# buttons and checkboxes first), the first that stays on screen and covers no other marked element, no
# earlier badge and no text of the page, else the one covering least of them. Only an element with no room
# around it on screen (one filling the viewport) gets its badge inside, in its visible top-left corner.
# Returns the badges as [id, x, y, width, height] (tests read them; the overlay is a closed shadow root).
DRAW_MARKS_JS = """(marks) => {
  const host = document.createElement('ewa-marks');
  host.style.cssText = 'all:initial;position:fixed;inset:0;pointer-events:none;z-index:2147483647;' +
    'display:block;margin:0;padding:0;border:0;transform:none;';
  const root = host.attachShadow({mode: 'closed'});
  const vw = document.documentElement.clientWidth || window.innerWidth;
  const vh = document.documentElement.clientHeight || window.innerHeight;
  // The outline: a LINE px line RING px outside the box, so a 1 px gap keeps it off the element even where the
  // box's whole pixels round a fractional position.
  const FONT = 'bold 10px/12px sans-serif', H = 12, LINE = 2, RING = 3;
  const measure = document.createElement('canvas').getContext('2d');
  measure.font = 'bold 10px sans-serif';
  const area = (a, b) =>
    Math.max(0, Math.min(a[0] + a[2], b[0] + b[2]) - Math.max(a[0], b[0])) *
    Math.max(0, Math.min(a[1] + a[3], b[1] + b[3]) - Math.max(a[1], b[1]));
  const within = (outer, inner) => outer[0] <= inner[0] && outer[1] <= inner[1] &&
    outer[0] + outer[2] >= inner[0] + inner[2] && outer[1] + outer[3] >= inner[1] + inner[3];
  const boxes = marks.map((m) => [m[1], m[2], m[3], m[4]]);
  const small = boxes.map((b) => b[2] <= 24 && b[3] <= 24);
  const badges = [];
  // The page's text on screen, line by line, in bands of BAND px rows: a badge should hide no word either
  // (the label above a drop-down, the line above a link), which the marks' boxes alone do not say.
  const BAND = 32, bands = new Map();
  const addTo = (rect) => {
    for (let b = Math.floor(rect[1] / BAND); b <= Math.floor((rect[1] + rect[3]) / BAND); b++) {
      if (!bands.has(b)) bands.set(b, []);
      bands.get(b).push(rect);
    }
  };
  const walker = document.createTreeWalker(document.body || document.documentElement, NodeFilter.SHOW_TEXT);
  const range = document.createRange();
  for (let node = walker.nextNode(); node; node = walker.nextNode()) {
    if (!node.data.trim()) continue;
    range.selectNodeContents(node);
    for (const r of range.getClientRects()) {
      if (r.width > 0 && r.bottom > 0 && r.top < vh && r.right > 0 && r.left < vw) addTo([r.x, r.y, r.width, r.height]);
    }
  }
  const textCost = (badge) => {
    let cost = 0;
    const first = Math.floor(badge[1] / BAND), last = Math.floor((badge[1] + badge[3]) / BAND);
    for (let b = first; b <= last; b++) for (const r of bands.get(b) || []) cost += area(badge, r);
    return cost;
  };
  for (let i = 0; i < marks.length; i++) {
    const [, x, y, w, h, colour] = marks[i];
    const ring = document.createElement('div');
    ring.style.cssText = `position:absolute;left:${x - RING}px;top:${y - RING}px;width:${w + 2 * RING}px;` +
      `height:${h + 2 * RING}px;border:${LINE}px solid ${colour};box-sizing:border-box;`;
    root.append(ring);
  }
  for (let i = 0; i < marks.length; i++) {
    const [id, x, y, w, h] = marks[i];
    const own = boxes[i];
    const bw = Math.ceil(measure.measureText(String(id)).width) + 4;
    const above = y - RING - H - 1, below = y + h + RING + 1, middle = Math.round(y + (h - H) / 2);
    const left = x - RING - bw - 1, right = x + w + RING + 1;
    const spots = small[i]
      ? [[left, middle], [x - RING, above], [x - RING, below], [right, middle], [left, above], [left, below]]
      : [[x - RING, above], [x + w + RING - bw, above], [left, y], [x - RING, below], [left, middle],
         [x + w + RING - bw, below], [right, y]];
    let best = null, bestCost = Infinity;
    for (const [bx, by] of spots) {
      const badge = [bx - 1, by - 1, bw + 2, H + 2];  // with its white outline
      if (bx - 1 < 0 || by - 1 < 0 || bx + bw + 1 > vw || by + H + 1 > vh || area(badge, own) > 0) continue;
      let cost = 0;
      for (let j = 0; j < boxes.length && cost < bestCost; j++) {
        if (j !== i && !within(boxes[j], own)) cost += area(badge, boxes[j]) * (small[j] ? 50 : 1);
      }
      for (let j = 0; j < badges.length && cost < bestCost; j++) cost += area(badge, badges[j]) * 10;
      if (cost < bestCost) cost += textCost(badge) * 3;
      if (cost < bestCost) { best = [bx, by]; bestCost = cost; }
      if (cost === 0) break;
    }
    if (best === null) {  // no room around it on screen: its own visible top-left corner
      best = [Math.min(Math.max(x, 1), Math.max(1, vw - bw - 1)), Math.min(Math.max(y, 1), Math.max(1, vh - H - 1))];
    }
    badges.push([best[0] - 1, best[1] - 1, bw + 2, H + 2]);
    const label = document.createElement('div');
    label.textContent = String(id);
    label.style.cssText = `position:absolute;left:${best[0]}px;top:${best[1]}px;width:${bw}px;height:${H}px;` +
      `background:${marks[i][5]};color:#fff;font:${FONT};text-align:center;white-space:nowrap;` +
      'box-shadow:0 0 0 1px #fff;border-radius:2px;letter-spacing:0;';
    root.append(label);
  }
  document.documentElement.appendChild(host);
  return badges.map((b, i) => [marks[i][0], b[0] + 1, b[1] + 1, b[2] - 2, b[3] - 2]);
}"""
REMOVE_MARKS_JS = "() => document.querySelectorAll('ewa-marks').forEach((e) => e.remove())"


def colour_of(mark_id: int) -> str:
    return PALETTE[mark_id % len(PALETTE)]


def marks_payload(marks: list[Mark]) -> list[list[Any]]:
    return [[m.id, *m.box, colour_of(m.id)] for m in marks]
