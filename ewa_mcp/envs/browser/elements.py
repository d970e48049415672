"""Element references: the numeric ids an agent sees, and role+name references oracles use.

An id names (tab, page generation, Playwright aria ref). Ids are handed out from one
per-episode counter and never reused, so an id from a page that has since navigated away
cannot silently point at an element of the new page: it is recognised as stale instead.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from .aria import AriaNode

_ID = re.compile(r"^\s*\[?\s*(\d{1,9})\s*\]?(?:\s+.*)?$", re.S)
_ROLE_NAME = re.compile(r"""^\s*([A-Za-z][\w-]*)(?:\s+(['"])(.*)\2)?(?:\s+#(\d{1,4}))?\s*$""", re.S)

ELEMENT_HELP = (
    "pass an id from the latest observation (12 or [12]) or a role and name such as "
    "link 'Tomato Bruschetta' or button 'Next' (add #2 to pick the second of several)"
)


@dataclass(frozen=True)
class IdRef:
    id: int


@dataclass(frozen=True)
class RoleNameRef:
    role: str
    name: str | None
    nth: int | None = None  # 1-based, among exact matches in document order

    def __str__(self) -> str:
        text = self.role + (f" '{self.name}'" if self.name is not None else "")
        return text + (f" #{self.nth}" if self.nth else "")


class ElementRefError(ValueError):
    """A reference that names no element (or several); the message lists what would work."""


def parse_element(text: str) -> IdRef | RoleNameRef:
    if not isinstance(text, str) or not text.strip():
        raise ElementRefError(f"empty element reference; {ELEMENT_HELP}")
    m = _ID.match(text)
    if m:
        return IdRef(int(m.group(1)))
    m = _ROLE_NAME.match(text)
    if m:
        return RoleNameRef(m.group(1), m.group(3), int(m.group(4)) if m.group(4) else None)
    raise ElementRefError(f"cannot read the element reference {text!r}; {ELEMENT_HELP}")


@dataclass
class ElementEntry:
    id: int
    tab_uid: int
    generation: int
    ref: str
    role: str
    name: str

    def describe(self) -> str:
        return f"[{self.id}] {self.role}" + (f" '{self.name}'" if self.name else "")


class ElementRegistry:
    """Per-episode map between numeric ids and (tab, generation, ref)."""

    def __init__(self) -> None:
        self._next = 1
        self._by_id: dict[int, ElementEntry] = {}
        self._by_key: dict[tuple[int, int, str], int] = {}

    def id_for(self, tab_uid: int, generation: int, node: AriaNode) -> int:
        assert node.ref is not None
        key = (tab_uid, generation, node.ref)
        existing = self._by_key.get(key)
        if existing is not None:
            entry = self._by_id[existing]
            entry.role, entry.name = node.role, node.name
            return existing
        element_id = self._next
        self._next += 1
        self._by_key[key] = element_id
        self._by_id[element_id] = ElementEntry(element_id, tab_uid, generation, node.ref, node.role, node.name)
        return element_id

    def get(self, element_id: int) -> ElementEntry | None:
        return self._by_id.get(element_id)

    def id_of(self, tab_uid: int, generation: int, ref: str) -> int | None:
        return self._by_key.get((tab_uid, generation, ref))


def _norm(text: str) -> str:
    return " ".join(text.split()).casefold()


def resolve_role_name(ref: RoleNameRef, nodes: list[AriaNode], id_of: dict[str, int]) -> AriaNode:
    """The one node (with an aria ref) matching a role+name reference, or a clear error."""
    role = ref.role.casefold()
    actionable = [n for n in nodes if n.ref is not None]
    same_role = [n for n in actionable if n.role.casefold() == role]
    if ref.name is None:
        matches = same_role
    else:
        matches = [n for n in same_role if n.name == ref.name]
        if not matches:  # tolerate case and spacing differences, never partial names
            matches = [n for n in same_role if _norm(n.name) == _norm(ref.name)]
    if ref.nth is not None:
        if ref.nth < 1 or ref.nth > len(matches):
            raise ElementRefError(
                f"{ref} asks for match #{ref.nth}, but {len(matches)} element(s) match "
                f"{ref.role}" + (f" '{ref.name}'" if ref.name is not None else "") + _listing(matches, id_of)
            )
        return matches[ref.nth - 1]
    if len(matches) == 1:
        return matches[0]
    if len(matches) > 1:
        raise ElementRefError(
            f"{ref} is ambiguous: {len(matches)} elements match{_listing(matches, id_of)}; "
            "use one of these ids, or add #N to pick the N-th"
        )
    if same_role:
        raise ElementRefError(f"no {ref.role} named '{ref.name}' on this page; the {ref.role} elements are"
                              f"{_listing(same_role, id_of)}")
    roles = sorted({n.role for n in actionable})
    raise ElementRefError(f"no {ref.role} on this page; roles present: {', '.join(roles) or 'none'}")


def _listing(nodes: list[AriaNode], id_of: dict[str, int], limit: int = 15) -> str:
    items = [f"[{id_of.get(n.ref or '', '?')}] {n.role} '{n.name}'" for n in nodes[:limit]]
    more = f" and {len(nodes) - limit} more" if len(nodes) > limit else ""
    return ": " + "; ".join(items) + more if items else ""
