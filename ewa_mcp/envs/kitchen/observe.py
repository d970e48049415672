"""The kitchen observation: a compact text scene graph for the model and the same as data.

Unlike the paper's reference, the observation shows what an agent needs to act: its pose and
what it holds, which objects are in reach now, where every object is (inside what), and the
states that matter (open/closed, on/off, cooked, broken, filled). It shows what is seen: a closed
cabinet, drawer or fridge the agent has not seen open this episode shows no contents and is not
called empty (``Fridge_1 (closed) {not looked inside: open it to see}``; closed cabinets and
drawers on one "Not looked inside" line), and what it holds is left out of the data, of "In reach"
and of what a bare type names. Once seen open (opened by the agent, or open in any observation)
its contents are shown, open or closed again: the agent remembers what it saw.
"""

from __future__ import annotations

from typing import Any

from .session import HEADINGS, KitchenSession, _compress, _handle_order

_APPLIANCES = {"Fridge", "Microwave", "Toaster", "CoffeeMachine", "StoveBurner", "SinkBasin", "GarbageCan"}


def state_tags(session: KitchenSession, obj: dict[str, Any]) -> list[str]:
    tags = []
    kind = obj["objectType"]
    if obj.get("openable"):
        tags.append("open" if obj.get("isOpen") else "closed")
    if obj.get("toggleable") or kind == "StoveBurner":
        tags.append("on" if obj.get("isToggled") else "off")
    if kind == "StoveBurner":
        knobs = [k for k, o in session.objects.items() if obj["objectId"] in (o.get("controlledObjects") or [])]
        if knobs:
            tags.append("knob " + ", ".join(session.handle(k) for k in knobs))
    if obj.get("isCooked"):
        tags.append("cooked")
    if obj.get("isBroken"):
        tags.append("broken")
    if obj.get("isFilledWithLiquid"):
        tags.append(f"filled with {obj.get('fillLiquid') or 'liquid'}")
    return tags


def _children(session: KitchenSession) -> dict[str | None, list[str]]:
    children: dict[str | None, list[str]] = {}
    for object_id, obj in session.objects.items():
        if obj.get("isPickedUp") or session.hidden_by(obj) is not None:
            continue
        children.setdefault(session.parent_of(obj), []).append(object_id)
    for ids in children.values():
        ids.sort(key=lambda i: (session.objects[i]["objectType"], session._number(i)))
    return children


def _describe(session: KitchenSession, object_id: str, children: dict[str | None, list[str]]) -> str:
    """``Pan_1 {PotatoSliced_1–4 (cooked)}`` — an object, its states and what it holds."""
    obj = session.objects[object_id]
    text = session.handle(object_id)
    tags = state_tags(session, obj)
    if tags:
        text += f" ({', '.join(tags)})"
    inside = children.get(object_id, [])
    if session.unlooked(object_id):
        text += " {not looked inside: open it to see}"
    elif inside:
        text += " {" + _list(session, inside, children) + "}"
    elif obj.get("receptacle") and obj.get("pickupable"):
        text += " {}"
    return text


def _list(session: KitchenSession, ids: list[str], children: dict[str | None, list[str]]) -> str:
    # Runs of identical pieces (same type, same states, holding nothing) collapse to "TomatoSliced_1–5".
    parts: list[str] = []
    run: list[str] = []
    run_key: tuple[Any, ...] | None = None

    def flush() -> None:
        if run:
            tags = state_tags(session, session.objects[run[0]])
            label = _compress([session.handle(i) for i in run])
            parts.append(label + (f" ({', '.join(tags)})" if tags else ""))
            run.clear()

    for object_id in ids:
        obj = session.objects[object_id]
        simple = (not children.get(object_id) and not (obj.get("receptacle") and obj.get("pickupable"))
                  and not session.unlooked(object_id))
        key = (obj["objectType"], tuple(state_tags(session, obj))) if simple else None
        if key is not None and key == run_key:
            run.append(object_id)
            continue
        flush()
        run_key = key
        if key is not None:
            run.append(object_id)
        else:
            parts.append(_describe(session, object_id, children))
    flush()
    return ", ".join(parts)


def pose_line(session: KitchenSession) -> str:
    agent = session.agent
    position = agent["position"]
    rotation = int(round(agent["rotation"]["y"])) % 360
    heading = HEADINGS.get(rotation, f"{rotation}°")
    held = session.held_id
    if held is not None:
        holding = _describe(session, held, _children(session))
    else:
        holding = "nothing"
    return (f"Kitchen {session.scene} ({session.backend}). You stand at x={position['x']:.2f} z={position['z']:.2f} "
            f"facing {heading}, rotation {rotation}°; holding {holding}.")


def build_observation(session: KitchenSession, mode: str = "text", *, view: str = "map",
                      last_error: str | None = None) -> tuple[str, dict[str, Any]]:
    """(text, data) for the agent; ``mode`` is the episode's observation option, ``view`` the kitchen image
    (first_person or map), ``last_error`` the last action's error message if it failed."""
    notes = session.take_notes()
    if mode == "vision" and view == "first_person":
        return camera_observation(session, notes, last_error)
    lines = [pose_line(session)]
    report = session.last_report
    if report is not None:
        lines.append(report.line(session.handle))
    lines.extend(notes)
    agent = session.agent
    data: dict[str, Any] = {
        "scene": session.scene,
        "backend": session.backend,
        "agent": {
            "x": agent["position"]["x"], "z": agent["position"]["z"],
            "rotation": agent["rotation"]["y"], "horizon": agent.get("cameraHorizon"),
        },
        "holding": session.handle(session.held_id) if session.held_id else None,
        "last_action": None if report is None else {
            "action": report.action, "target": session.handle(report.target) if report.target else None,
            "notes": report.notes, "effects": report.effects,
        },
        "deliveries": notes,
    }
    if mode == "vision":
        lines.append("(The image shows the kitchen from above: you are the arrow; objects in reach are labelled in "
                     "blue, other visible objects in grey; the side panel lists what is in reach.)")
        return "\n".join(lines), data

    children = _children(session)
    in_reach = sorted(
        (i for i, o in session.objects.items() if o["visible"] and not o["isPickedUp"]
         and o["objectType"] not in ("Floor", "Sink") and session.hidden_by(o) is None),
        key=lambda i: (session.objects[i]["distance"], session.handle(i)),
    )
    lines.append("In reach: " + (_reach_line(session, in_reach) or "nothing — teleport to an object"))
    lines.append("Kitchen (nearest first; {…} = contents):")
    empty: list[str] = []
    unlooked: list[str] = []
    top_level = [i for i in children.get(None, []) if session.objects[i]["objectType"] not in ("StoveKnob", "Sink")]
    top_level.sort(key=lambda i: (session.objects[i]["distance"], session.handle(i)))
    for object_id in top_level:
        obj = session.objects[object_id]
        if obj["objectType"] == "Floor" and not children.get(object_id):
            continue
        if not children.get(object_id) and obj["objectType"] not in _APPLIANCES:
            # a closed cabinet never opened may hold anything: it is not empty as far as the agent knows
            (unlooked if session.unlooked(object_id) else empty).append(object_id)
            continue
        # An appliance is listed even when it holds nothing; say so, or a closed fridge with no {…} reads as
        # "not looked into" (play-testers opened empty fridges to find out).
        nothing = " {empty}" if (obj.get("receptacle") and not children.get(object_id)
                                 and not session.unlooked(object_id)) else ""
        lines.append(f"- {_describe(session, object_id, children)}{nothing} · {obj['distance']:.1f} m")
    if empty:
        closed = [i for i in empty if session.objects[i].get("openable") and not session.objects[i].get("isOpen")]
        opened = [i for i in empty if i not in closed]
        text = "Empty: "
        if closed:
            text += _compress(sorted((session.handle(i) for i in closed), key=_handle_order)) + " (closed)"
        if opened:
            text += ("; " if closed else "") + _compress(sorted((session.handle(i) for i in opened), key=_handle_order))
        lines.append(text)
    if unlooked:
        lines.append("Not looked inside (closed; open one to see what it holds): "
                     + _compress(sorted((session.handle(i) for i in unlooked), key=_handle_order)))
    data["in_reach"] = [session.handle(i) for i in in_reach]
    data["objects"] = [
        {
            "handle": session.handle(object_id),
            "objectId": object_id,
            "type": obj["objectType"],
            "parent": session.handle(session.parent_of(obj)) if session.parent_of(obj) else None,
            "distance": round(obj["distance"], 2),
            "visible": obj["visible"],
            "states": state_tags(session, obj),
            **({"looked_inside": not session.unlooked(object_id)} if obj.get("openable") and obj.get("receptacle")
               else {}),
        }
        for object_id, obj in session.objects.items() if session.hidden_by(obj) is None
    ]
    return "\n".join(lines), data


CAMERA_LEGEND = ("In the frame: each stove knob is the colour of the ring round the burner it lights; a lit burner "
                 "glows orange and an on knob shows a red mark; cooked food is brown, cooked slices carry dark "
                 "stripes; closed doors hide what is behind them; what you hold is at the bottom.")


def camera_observation(session: KitchenSession, notes: list[str],
                       last_error: str | None) -> tuple[str, dict[str, Any]]:
    """Vision only: what the camera frame cannot show, as AI2-THOR's event gives it beside the frame — what is
    held, and whether the last action succeeded (lastActionSuccess, errorMessage). No pose, no object list."""
    held = session.held_id
    holding = _describe(session, held, _children(session)) if held is not None else "nothing"
    report = session.last_report
    lines = [f"Kitchen {session.scene}: the image is your first-person camera (90° field of view). "
             f"Holding: {holding}."]
    if last_error is not None:
        lines.append(f"Last action failed: {last_error}")
    elif report is not None:
        lines.append("Last action succeeded. " + report.line(session.handle))
    else:  # the first frame: how the camera shows states that a photograph would show by detail too small here
        lines.append(CAMERA_LEGEND)
    lines.extend(notes)
    data: dict[str, Any] = {
        "scene": session.scene,
        "backend": session.backend,
        "view": "first_person",
        "holding": session.handle(held) if held else None,
        "lastActionSuccess": last_error is None,
        "errorMessage": last_error or "",
        "last_action": None if report is None or last_error is not None else {
            "action": report.action, "target": session.handle(report.target) if report.target else None,
            "notes": report.notes, "effects": report.effects,
        },
        "deliveries": notes,
    }
    return "\n".join(lines), data


def _reach_line(session: KitchenSession, in_reach: list[str]) -> str:
    """Handles nearest first, one type at a time, runs compressed: "CounterTop_5, TomatoSliced_1–5"."""
    groups: dict[str, list[str]] = {}
    for object_id in in_reach:  # already nearest first
        groups.setdefault(session.objects[object_id]["objectType"], []).append(session.handle(object_id))
    return ", ".join(_compress(sorted(handles, key=_handle_order)) for handles in groups.values())
