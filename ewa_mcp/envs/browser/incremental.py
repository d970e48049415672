"""Incremental web observations (episode option ``web_incremental``): after an action, the accessibility tree is
sent as what changed since the tree the agent last read, when that is clearly shorter than the whole page.

A "Next step" on a recipe, a ticked checkbox or a new search result changes a few lines of a page the agent has
already read; resending the whole page repeats what it knows. Only the same page is sent this way (the same URL
path; session.see_tree): another page is sent whole, so lines two pages share are never left for the agent to
carry over. Each hunk names the unchanged line it follows, so
the agent can place it; removed lines are counted, not repeated. ``browser_snapshot`` and ``get_observation``
always send the whole page, so the agent can read it again at any time.
"""

from __future__ import annotations

import difflib
import re

_ID = re.compile(r"^(\s*)\[(\d+)\] ")

# Send the changes only when they cost at most this share of the whole tree's characters: a page that changed
# mostly (another site, another listing) reads better whole than as a long diff.
MAX_SHARE = 0.6


def _split(line: str) -> tuple[str, int | None]:
    """A tree line without its element id (what the line says), and the id."""
    m = _ID.match(line)
    return (line, None) if m is None else (m.group(1) + line[m.end():], int(m.group(2)))


def tree_changes(before: list[str] | None, after: list[str]) -> str | None:
    """The changes from ``before`` to ``after`` (tree lines) as text, or None when the whole tree should be sent:
    nothing read before, nothing in common, ids that moved unevenly, or changes not clearly shorter than the tree.

    Lines are compared without their element ids. On the same document ids do not change; a new document (a
    "Next step" link) numbers its elements afresh, in page order, so the unchanged elements between two changes
    moved by one amount: the text says by how much, so the agent can still address what it read by id."""
    if not before or not after:
        return None
    old = [_split(line) for line in before]
    new = [_split(line) for line in after]
    matcher = difflib.SequenceMatcher(a=[k for k, _ in old], b=[k for k, _ in new], autojunk=False)
    hunks: list[str] = []
    unchanged = 0
    first_shift: int | None = None  # how much higher the ids of the first unchanged lines are
    shift: int | None = None
    for op, i1, i2, j1, j2 in matcher.get_opcodes():
        if op == "equal":
            unchanged += i2 - i1
            moved = {n[1] - o[1] for o, n in zip(old[i1:i2], new[j1:j2]) if o[1] is not None and n[1] is not None}
            if len(moved) > 1:  # ids moved unevenly inside a block: the agent could not follow them
                return None
            if moved:
                block = moved.pop()
                if shift is None:
                    first_shift = block
                elif block != shift and hunks:
                    hunks[-1] += f"\n(ids of the unchanged elements below: {block} higher than before)"
                shift = block
            continue
        anchor = f"after: {after[j1 - 1].strip()}" if j1 > 0 else "at the top"
        lines = [f"@ {anchor}"]
        lines += [f"+ {line}" for line in after[j1:j2]]
        if i2 > i1:
            lines.append(f"- {i2 - i1} line{'s' if i2 - i1 != 1 else ''} removed")
        hunks.append("\n".join(lines))
    if unchanged == 0:
        return None
    note = (f"(a new document: the ids of the unchanged elements are {first_shift} higher than in your last "
            "observation)\n" if first_shift else "")
    if not hunks:
        return note + "(no change since your last observation of this page)"
    text = note + "\n".join(hunks)
    if len(text) > MAX_SHARE * sum(len(line) + 1 for line in after):
        return None
    return text
