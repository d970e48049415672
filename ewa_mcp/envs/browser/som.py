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

DRAW_MARKS_JS = """(marks) => {
  const host = document.createElement('ewa-marks');
  host.style.cssText = 'position:fixed;inset:0;pointer-events:none;z-index:2147483647;display:block;' +
    'margin:0;padding:0;border:0;transform:none;';
  const root = host.attachShadow({mode: 'closed'});
  for (const [id, x, y, w, h, colour] of marks) {
    const box = document.createElement('div');
    box.style.cssText = `position:absolute;left:${x}px;top:${y}px;width:${w}px;height:${h}px;` +
      `border:2px solid ${colour};box-sizing:border-box;`;
    const label = document.createElement('div');
    label.textContent = String(id);
    label.style.cssText = `position:absolute;left:${Math.max(0, x)}px;top:${y >= 14 ? y - 14 : y}px;` +
      `background:${colour};color:#fff;font:bold 11px/14px sans-serif;padding:0 3px;white-space:nowrap;`;
    root.append(box, label);
  }
  document.documentElement.appendChild(host);
}"""
REMOVE_MARKS_JS = "() => document.querySelectorAll('ewa-marks').forEach((e) => e.remove())"


def colour_of(mark_id: int) -> str:
    return PALETTE[mark_id % len(PALETTE)]


def marks_payload(marks: list[Mark]) -> list[list[Any]]:
    return [[m.id, *m.box, colour_of(m.id)] for m in marks]
