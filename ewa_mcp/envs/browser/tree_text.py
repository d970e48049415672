"""Render a parsed ARIA snapshot in the WebArena text form: ``[id] role 'name' props``, one per line.

Nameless layout containers (``generic``, ``paragraph``, ``list`` ...) are folded away the way
WebArena prunes them, so the agent reads content and controls rather than div soup; a folded
container that holds a single text keeps its id as ``[id] StaticText 'text'`` (clicking it
clicks the container). Text runs become ``StaticText`` lines without ids.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from .aria import AriaNode, Box

FOLD_WHEN_NAMELESS = frozenset(
    {"generic", "paragraph", "list", "listitem", "strong", "emphasis", "none", "presentation", "group",
     "LabelText", "Section", "superscript", "subscript", "code", "time", "mark", "deletion", "insertion"}
)
INTERACTIVE_ROLES = frozenset(
    {"link", "button", "textbox", "searchbox", "combobox", "checkbox", "radio", "switch", "slider", "spinbutton",
     "tab", "menuitem", "menuitemcheckbox", "menuitemradio", "option", "treeitem", "listbox", "gridcell"}
)
EDITABLE_ROLES = frozenset({"textbox", "searchbox", "combobox", "spinbutton"})
CHECKABLE_ROLES = frozenset({"checkbox", "radio", "switch", "menuitemcheckbox", "menuitemradio"})


@dataclass
class Mark:
    """An element drawn on the Set-of-Marks screenshot."""

    id: int
    role: str
    name: str
    box: Box


@dataclass
class RenderedTree:
    text: str
    lines: int
    total_lines: int
    truncated: bool
    marks: list[Mark] = field(default_factory=list)


def _quote(text: str) -> str:
    return "'" + " ".join(text.split()) + "'"


def _props(node: AriaNode) -> str:
    parts: list[str] = []
    a = node.attrs
    if "active" in a:
        parts.append("focused: True")
    if node.role in CHECKABLE_ROLES:
        parts.append(f"checked: {'mixed' if a.get('checked') == 'mixed' else ('true' if 'checked' in a else 'false')}")
    if "disabled" in a:
        parts.append("disabled: True")
    if "expanded" in a:
        parts.append("expanded: True")
    if "selected" in a:
        parts.append("selected: True")
    if "pressed" in a:
        parts.append(f"pressed: {'mixed' if a['pressed'] == 'mixed' else 'true'}")
    if "invalid" in a:
        parts.append("invalid: True")
    value = _value(node)
    if value is not None:
        parts.append(f"value: {_quote(value)}")
    if "placeholder" in node.props:
        parts.append(f"placeholder: {_quote(node.props['placeholder'])}")
    if "url" in node.props:
        parts.append(f"url: {node.props['url']}")
    return (" " + " ".join(parts)) if parts else ""


def _value(node: AriaNode) -> str | None:
    """A text field's current value: inline, or (when it also has a placeholder) a text child."""
    if node.role not in EDITABLE_ROLES or node.role == "combobox" and any(
            isinstance(c, AriaNode) for c in node.children):
        return None
    if node.text is not None:
        return node.text
    texts = [c for c in node.children if isinstance(c, str)]
    return " ".join(texts) if texts else None


def _intersects(box: Box | None, viewport: tuple[int, int]) -> bool | None:
    """None when the node has no usable box (it then follows its parent)."""
    if box is None or (box[2] <= 0 and box[3] <= 0):
        return None
    x, y, w, h = box
    return x < viewport[0] and y < viewport[1] and x + w > 0 and y + h > 0


def render_tree(
    roots: list[AriaNode],
    id_of: Callable[[AriaNode], int],
    *,
    title: str,
    viewport: tuple[int, int],
    viewport_only: bool = False,
    max_chars: int = 24_000,
) -> RenderedTree:
    """Render the snapshot; ``id_of`` hands out the numeric id of a node that has an aria ref."""
    lines: list[str] = []
    marks: list[Mark] = []

    def visible(node: AriaNode, parent_visible: bool) -> bool:
        inside = _intersects(node.box, viewport)
        return parent_visible if inside is None else inside

    def any_visible(node: AriaNode, parent_visible: bool) -> bool:
        if visible(node, parent_visible):
            return True
        return any(isinstance(c, AriaNode) and any_visible(c, False) for c in node.children)

    def emit_text(text: str, depth: int, parent_name: str) -> None:
        flat = " ".join(text.split())
        if flat and flat != " ".join(parent_name.split()):
            lines.append("\t" * depth + f"StaticText {_quote(flat)}")

    def visit(node: AriaNode, depth: int, parent_visible: bool, parent_name: str) -> None:
        shown = visible(node, parent_visible)
        if viewport_only and not shown and not any_visible(node, parent_visible):
            return
        node_id = id_of(node) if node.ref is not None else None
        if node_id is not None and shown and node.box and (node.role in INTERACTIVE_ROLES
                                                            or node.attrs.get("cursor") == "pointer"):
            marks.append(Mark(node_id, node.role, node.name, node.box))
        clickable = node.attrs.get("cursor") == "pointer"
        fold = not node.name and node.role in FOLD_WHEN_NAMELESS and not clickable
        if node.role == "img" and not node.name and not node.children:
            return
        prefix = f"[{node_id}] " if node_id is not None else ""
        if fold:
            child_depth = depth
            if node.text is not None and (not viewport_only or shown):
                flat = " ".join(node.text.split())
                if flat:
                    lines.append("\t" * depth + f"{prefix}StaticText {_quote(flat)}")
        else:
            name = node.name or ("" if node.role in EDITABLE_ROLES else (node.text or ""))
            if not viewport_only or shown:
                lines.append("\t" * depth + f"{prefix}{node.role} {_quote(name)}{_props(node)}")
            child_depth = depth + 1
            if node.text is not None and node.name and node.role not in EDITABLE_ROLES and (not viewport_only or shown):
                emit_text(node.text, child_depth, node.name)
        for child in node.children:
            if isinstance(child, str):
                if node.role in EDITABLE_ROLES:
                    continue  # shown as the field's value
                if not viewport_only or shown:
                    emit_text(child, child_depth, node.name or parent_name)
            else:
                visit(child, child_depth, shown, node.name or parent_name)

    body = roots[0] if len(roots) == 1 and roots[0].role == "generic" and not roots[0].name else None
    if body is not None:
        root_id = f"[{id_of(body)}] " if body.ref else ""
        focused = " focused: True" if "active" in body.attrs else ""
        lines.append(f"{root_id}RootWebArea {_quote(title)}{focused}")
        if body.text:
            emit_text(body.text, 1, "")
        for child in body.children:
            if isinstance(child, str):
                emit_text(child, 1, "")
            else:
                visit(child, 1, True, "")
    else:
        lines.append(f"RootWebArea {_quote(title)}")
        for root in roots:
            visit(root, 1, True, "")

    kept: list[str] = []
    used = 0
    for line in lines:
        if used + len(line) + 1 > max_chars:
            break
        kept.append(line)
        used += len(line) + 1
    truncated = len(kept) < len(lines)
    return RenderedTree("\n".join(kept), len(kept), len(lines), truncated, marks)
