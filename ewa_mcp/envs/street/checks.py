"""Street goals: did the walk end near the goal (and pass its waypoints), and how efficiently.

The walk ends at the first street_stop, or else when the episode finishes; success is "the walk
ended within the radius" (default 25 m), not the reference's exact node: street graphs have nodes
every 10–25 m, so ending one panorama short of the door is an arrival. Exact-node arrival, distance
to goal, whether the agent stopped explicitly and SPL are reported beside it.
"""

from __future__ import annotations

import math
from typing import Any

from ewa_mcp.geometry import haversine_m
from ewa_mcp.envs.street.goals import PassedPlace, ReachedPlace

from ewa_mcp.graders.models import CheckContext, ConditionResult, NavigationResult


def _number(value: Any) -> float | None:
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
        return None
    return float(value)


def shortest_path(goal: ReachedPlace, metadata: dict[str, Any]) -> tuple[float | None, str]:
    """The task's shortest walk (metadata.shortest_path_m, from the generator's Dijkstra), else the
    straight line from metadata.start_lat/start_lng to the goal (a lower bound, so SPL is optimistic)."""
    value = _number(metadata.get("shortest_path_m"))
    if value is not None and value >= 0:
        return value, "metadata"
    lat, lng = _number(metadata.get("start_lat")), _number(metadata.get("start_lng"))
    if lat is not None and lng is not None:
        return haversine_m(lat, lng, goal.lat, goal.lng), "straight_line"
    return None, "unknown"


def order_store_check(goal: ReachedPlace, metadata: dict[str, Any], orders: list[dict[str, Any]]) -> tuple[bool, str]:
    """Shopping: the goal must be the pickup store of the order (metadata.store_nodes maps store ids to nodes)."""
    store_nodes = metadata.get("store_nodes")
    if not isinstance(store_nodes, dict):
        return False, "task metadata has no store_nodes, so the pickup store cannot be checked"
    if not orders:
        return False, "no matching order was placed, so there is no pickup store to walk to"
    for order in orders:
        if store_nodes.get(order.get("store_id")) == goal.node:
            return True, f"walked to the pickup store of order {order.get('order_id')}"
    stores = ", ".join(sorted({str(o.get("store_id")) for o in orders}))
    return False, f"the goal is not the pickup store of the order (ordered at {stores})"


def walk_end(state: dict[str, Any]) -> tuple[float | None, float | None, Any]:
    """Where the walk ended: the final state's walk_end (the stop position if stopped), else its position."""
    end = state.get("walk_end")
    source = end if isinstance(end, dict) else state
    return _number(source.get("lat")), _number(source.get("lng")), source.get("node")


def check_passed_place(goal: PassedPlace, state: dict[str, Any], radius_override: float | None) -> ConditionResult:
    """A waypoint: some node of the walk (path_points, up to where the walk ended) within the radius."""
    radius = radius_override if radius_override is not None else goal.radius_m
    description = f"pass within {radius:g} m of {goal.place_id or goal.node} ({goal.city})"
    points = state.get("path_points")
    if state.get("city") not in (None, goal.city):
        return ConditionResult(side="embodied", kind=goal.kind, description=description, met=False,
                               note=f"the agent is in {state.get('city')}, the waypoint in {goal.city}")
    if not isinstance(points, list):
        return ConditionResult(side="embodied", kind=goal.kind, description=description, met=None,
                               note="the final state has no path_points, so the walk's course is unknown")
    track = [(lat, lng) for lat, lng in
             ((_number(p[0]), _number(p[1])) for p in points if isinstance(p, list | tuple) and len(p) == 2)
             if lat is not None and lng is not None]
    distances = [haversine_m(lat, lng, goal.lat, goal.lng) for lat, lng in track]
    closest = min(distances) if distances else None
    met = closest is not None and closest <= radius
    note = None if met else ("the walk has no positions" if closest is None else
                             f"the walk came no closer than {closest:.0f} m to the waypoint (radius {radius:g} m)")
    detail: dict[str, Any] = {"closest_m": round(closest, 2) if closest is not None else None}
    if goal.after is not None:
        before = goal.after.place_id or goal.after.node
        description += f" after passing {before}"
        first = next((i for i, (lat, lng) in enumerate(track)
                      if haversine_m(lat, lng, goal.after.lat, goal.after.lng) <= radius), None)
        last = max((i for i, d in enumerate(distances) if d <= radius), default=None)
        in_order = first is not None and last is not None and last >= first
        detail["in_order"] = in_order
        if met and not in_order:
            met = False
            note = (f"the walk never passed {before}" if first is None else
                    f"the walk passed here only before it passed {before}: the task gives the other order")
    return ConditionResult(side="embodied", kind=goal.kind, description=description, met=met,
                           detail=detail, note=note)


def check_reached_place(
    goal: ReachedPlace,
    state: dict[str, Any],
    metadata: dict[str, Any],
    orders: list[dict[str, Any]],
    radius_override: float | None,
) -> tuple[ConditionResult, NavigationResult]:
    radius = radius_override if radius_override is not None else goal.radius_m
    lat, lng, end_node = walk_end(state)
    same_city = state.get("city") in (None, goal.city)
    distance = haversine_m(lat, lng, goal.lat, goal.lng) if lat is not None and lng is not None and same_city else None
    stopped = state.get("walk_stopped", state.get("stopped")) is True
    within = distance is not None and distance <= radius
    success = within  # the walk ends at the first street_stop, or else when the episode finishes
    notes: list[str] = []
    if not same_city:
        notes.append(f"the agent is in {state.get('city')}, the goal in {goal.city}")
    elif distance is None:
        notes.append("the final state has no position")
    if not within and distance is not None:
        how = "stopped" if stopped else "never stopped (street_stop); the walk ended when the episode finished,"
        notes.append(f"{how} {distance:.0f} m from the goal (radius {radius:g} m)")
    if goal.must_match_order_store:
        store_ok, why = order_store_check(goal, metadata, orders)
        if not store_ok:
            success = False
            notes.append(why)
    shortest, source = shortest_path(goal, metadata)
    walked = _number(state.get("distance_walked_m"))
    spl = None
    if shortest is not None and walked is not None:
        # Habitat's SPL: success weighted by shortest / max(walked, shortest).
        spl = (shortest / max(walked, shortest) if max(walked, shortest) > 0 else 1.0) if success else 0.0
    nav = NavigationResult(
        goal_node=goal.node,
        final_node=end_node if isinstance(end_node, str) else None,
        stopped=stopped,
        radius_m=radius,
        distance_to_goal_m=round(distance, 2) if distance is not None else None,
        within_radius=within,
        exact_node=end_node == goal.node and same_city,
        success=success,
        shortest_path_m=round(shortest, 2) if shortest is not None else None,
        shortest_path_source=source,
        path_length_m=walked,
        spl=round(spl, 4) if spl is not None else None,
    )
    description = f"end the walk within {radius:g} m of {goal.place_id or goal.node} ({goal.city})"
    condition = ConditionResult(
        side="embodied", kind=goal.kind, description=description, met=success,
        detail={"distance_to_goal_m": nav.distance_to_goal_m, "stopped": stopped, "exact_node": nav.exact_node},
        note="; ".join(notes) or None,
    )
    return condition, nav


def _position(goal: Any, ctx: CheckContext) -> dict[str, Any] | ConditionResult:
    state = ctx.state
    if state is None:
        return ctx.unknown("embodied", goal, ctx.why_no_state)
    if "lat" not in state and "node" not in state:
        return ctx.unknown("embodied", goal,
                           f"the embodied final state ({state.get('name', '?')}) has no street position")
    return state


def reached_place(goal: ReachedPlace, ctx: CheckContext) -> ConditionResult:
    state = _position(goal, ctx)
    if isinstance(state, ConditionResult):
        return state
    condition, nav = check_reached_place(goal, state, ctx.metadata, ctx.orders, ctx.radius_m)
    ctx.navigation.append(nav)
    return condition


def passed_place(goal: PassedPlace, ctx: CheckContext) -> ConditionResult:
    state = _position(goal, ctx)
    return state if isinstance(state, ConditionResult) else check_passed_place(goal, state, ctx.radius_m)
