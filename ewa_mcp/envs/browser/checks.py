"""Web goals, checked against the events the embedded sites emitted for the episode.

The reference graded the recipe site by "some recipe reached its last step" and the shop by
the URL of a transient pop-up; here each goal names what must have happened and the check
looks for exactly that event.
"""

from __future__ import annotations

from typing import Any

from ewa_mcp.envs.browser.goals import (DirectionsShown, OrderPlaced, OrdersSplit, PageVisited, RecipeCompleted,
                                        RecipesCompleted)

from ewa_mcp.graders.models import CheckContext, ConditionResult


def _as_int(value: Any) -> int | None:
    try:
        return int(value)
    except (TypeError, ValueError):
        return None


def _same_text(a: Any, b: Any) -> bool:
    return isinstance(a, str) and isinstance(b, str) and a.strip().casefold() == b.strip().casefold()


def orders(events: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """The orders placed in the episode, in order."""
    return [
        e["order"]
        for e in events
        if e.get("site") == "shop" and e.get("type") == "order_placed" and isinstance(e.get("order"), dict)
    ]


def order_matches(order: dict[str, Any], goal: OrderPlaced) -> bool:
    """The order holds the product (and size) in exactly the quantity asked, at the store asked."""
    if goal.store_id is not None and order.get("store_id") != goal.store_id:
        return False
    quantity = 0
    for item in order.get("items") or []:
        if not isinstance(item, dict) or item.get("product_id") != goal.product_id:
            continue
        if goal.size is not None and not _same_text(item.get("size"), goal.size):
            continue
        # One product split over several lines of the same order counts once, summed.
        quantity += _as_int(item.get("quantity")) or 0
    return quantity == goal.quantity


def matching_orders(events: list[dict[str, Any]], goal: OrderPlaced) -> list[dict[str, Any]]:
    return [o for o in orders(events) if order_matches(o, goal)]


def _line_of(item: Any, order: dict[str, Any], goal: OrderPlaced) -> bool:
    """This order line is of the goal's product (and size, and store, where the goal names them)."""
    if not isinstance(item, dict) or item.get("product_id") != goal.product_id:
        return False
    if goal.store_id is not None and order.get("store_id") != goal.store_id:
        return False
    return goal.size is None or _same_text(item.get("size"), goal.size)


def extra_order_lines(events: list[dict[str, Any]], goals: list[OrderPlaced]) -> list[dict[str, Any]]:
    """What the episode ordered beyond what the task's order goals ask for: one choice means one choice
    (issue 26). A line no goal asks for (a rival product, another size, another store), and, per goal,
    what its lines hold beyond its quantity summed over every order (the same item ordered again, or at
    every store when the goal names none). Ordering every candidate, or at every store, would otherwise
    meet the goal without choosing."""
    extra: list[dict[str, Any]] = []
    ordered = {id(g): 0 for g in goals}
    for order in orders(events):
        for item in order.get("items") or []:
            wanted = [g for g in goals if _line_of(item, order, g)]
            quantity = (_as_int(item.get("quantity")) or 0) if isinstance(item, dict) else 0
            line = {"order_id": order.get("order_id"), "store_id": order.get("store_id"),
                    "product_id": item.get("product_id") if isinstance(item, dict) else None,
                    "size": item.get("size") if isinstance(item, dict) else None, "quantity": quantity}
            if not wanted:
                extra.append(line)
                continue
            goal = wanted[0]
            ordered[id(goal)] += quantity
            if ordered[id(goal)] > goal.quantity:
                extra.append(line)
    return extra


def check_recipe(goal: RecipeCompleted, events: list[dict[str, Any]]) -> ConditionResult:
    """The goal's recipe is the one the episode chose: the last recipe it followed to its last step
    (one choice means one choice, issue 26). Reading look-alikes to the end to compare them first is
    what a step-told task asks for, so it does not count against the choice; finishing another recipe
    after the goal's does (the choice changed), and opening the last step of every same-named recipe
    passes only where the goal's happens to be opened last, and then cannot meet the kitchen goals of
    the others it also "chose"."""
    steps = [e for e in events if e.get("site") == "recipes" and e.get("type") == "recipe_step"]
    best = 0
    last_step_of: int | None = None
    finished: list[str] = []  # recipe ids in the order they were shown at their last step
    for e in steps:
        step, of = _as_int(e.get("step")), _as_int(e.get("of"))
        if step is None or of is None or of < 1:
            continue
        if e.get("recipe_id") == goal.recipe_id:
            best = max(best, step)
            last_step_of = of
        if step == of:
            finished.append(str(e.get("recipe_id")))
    chosen = finished[-1] if finished else None
    detail: dict[str, Any] = {"recipe_id": goal.recipe_id, "furthest_step": best, "of": last_step_of,
                              "chosen_recipe": chosen}
    others = sorted({rid for rid in finished if rid != goal.recipe_id})
    note = None
    if others:
        detail["completed_other_recipes"] = others
    if chosen is not None and chosen != goal.recipe_id:
        # The reference counted any finished recipe; the last one finished is the one chosen here.
        note = ("another recipe was followed to its last step after this one: the last recipe followed to its "
                "end is the one chosen" if goal.recipe_id in finished
                else "a different recipe was followed to its last step")
    return ConditionResult(side="web", kind=goal.kind, description=_describe(goal),
                           met=chosen == goal.recipe_id, detail=detail, note=note)


def check_recipes(goal: RecipesCompleted, events: list[dict[str, Any]]) -> ConditionResult:
    """Two dishes, two choices: the recipes the episode chose are the goal's, the last ``len(recipe_ids)``
    distinct recipes it followed to their last step (check_recipe's rule for one). Reading look-alikes to
    the end first is comparing; finishing a look-alike after the goal's recipes changes a choice."""
    finished: list[str] = []
    for e in events:
        if e.get("site") != "recipes" or e.get("type") != "recipe_step":
            continue
        step, of = _as_int(e.get("step")), _as_int(e.get("of"))
        if step is not None and of is not None and of >= 1 and step == of:
            finished.append(str(e.get("recipe_id")))
    wanted = list(dict.fromkeys(goal.recipe_ids))
    chosen: list[str] = []
    for rid in reversed(finished):
        if len(chosen) == len(wanted):
            break
        if rid not in chosen:
            chosen.append(rid)
    chosen.reverse()
    met = bool(wanted) and sorted(chosen) == sorted(wanted)
    detail: dict[str, Any] = {"recipe_ids": wanted, "chosen_recipes": chosen,
                              "finished": sorted(set(finished))}
    note = None
    if not met:
        absent = [rid for rid in wanted if rid not in finished]
        note = (f"not followed to the last step: {', '.join(absent)}" if absent else
                f"the last {len(wanted)} recipes followed to their end are {', '.join(chosen)}: another recipe "
                "was finished after the chosen ones")
    return ConditionResult(side="web", kind=goal.kind, description=_describe(goal), met=met, detail=detail,
                           note=note)


def check_order(goal: OrderPlaced, events: list[dict[str, Any]],
                task_goals: list[Any] | None = None) -> ConditionResult:
    """Some order holds the goal's item exactly, and the episode ordered nothing the task's order goals
    (``task_goals``: all its web goals; this goal alone when not given) do not ask for."""
    found = matching_orders(events, goal)
    placed = orders(events)
    detail: dict[str, Any] = {"orders_placed": len(placed)}
    if not found:
        note = "no order was placed" if not placed else "no order has this product, size, quantity and store"
        return ConditionResult(side="web", kind=goal.kind, description=_describe(goal), met=False, detail=detail,
                               note=note)
    detail["order_id"] = found[0].get("order_id")
    detail["store_id"] = found[0].get("store_id")
    order_goals = [g for g in (task_goals or []) if isinstance(g, OrderPlaced)] or [goal]
    if goal not in order_goals:
        order_goals.append(goal)
    extra = extra_order_lines(events, order_goals)
    if extra:
        detail["extra_order_lines"] = extra
        return ConditionResult(side="web", kind=goal.kind, description=_describe(goal), met=False, detail=detail,
                               note=f"{len(extra)} order line(s) beyond what the task asks for (another product, "
                                    "size or store, or the same item again): order only what was asked")
    return ConditionResult(side="web", kind=goal.kind, description=_describe(goal), met=True, detail=detail)


def _dollars(value: Any) -> float | None:
    return float(value) if isinstance(value, int | float) and not isinstance(value, bool) else None


def check_orders_split(goal: OrdersSplit, events: list[dict[str, Any]]) -> ConditionResult:
    """The list bought in two orders at two stores (one choice means one choice, issue 26): exactly one order
    at each of the goal's stores and no other order, every item of the list exactly once over the orders
    (quantity 1, at whichever of the stores), no line the list does not ask for, and the totals added within
    ``max_total``. How the items are split between the stores is the buyer's choice."""
    placed = orders(events)
    wanted = {(i.product_id, i.size.strip().casefold()) for i in goal.items}
    got: dict[tuple[str, str], int] = {}
    extra: list[str] = []
    for order in placed:
        for item in order.get("items") or []:
            if not isinstance(item, dict):
                continue
            key = (str(item.get("product_id")), str(item.get("size") or "").strip().casefold())
            quantity = _as_int(item.get("quantity")) or 0
            if key in wanted:
                got[key] = got.get(key, 0) + quantity
            else:
                extra.append(f"{item.get('product_id')} ({item.get('size')}) at {order.get('store_id')}")
    stores = [str(o.get("store_id")) for o in placed]
    totals = [_dollars(o.get("total")) for o in placed]
    spent = round(sum(t for t in totals if t is not None), 2)
    detail: dict[str, Any] = {"orders_placed": len(placed), "order_stores": stores, "spent": spent,
                              "max_total": goal.max_total}
    problems: list[str] = []
    if sorted(stores) != sorted(goal.store_ids):
        want = " and ".join(goal.store_ids)
        problems.append(f"the orders were placed at {', '.join(stores) or 'no store'}; the task's choice is one "
                        f"order at each of {want}, and no other order")
    missing = [f"{p} ({s})" for p, s in sorted(wanted) if got.get((p, s), 0) == 0]
    again = [f"{p} ({s})" for p, s in sorted(wanted) if got.get((p, s), 0) > 1]
    if missing:
        problems.append(f"not ordered: {', '.join(missing)}")
    if again:
        problems.append(f"ordered more than once: {', '.join(again)}")
    if extra:
        problems.append(f"ordered beyond the list: {', '.join(extra)}")
    if any(t is None for t in totals) or spent > goal.max_total + 1e-9:
        problems.append(f"the orders add up to ${spent:.2f}, over the budget of ${goal.max_total:.2f}"
                        if all(t is not None for t in totals) else "an order has no total")
    return ConditionResult(side="web", kind=goal.kind, description=_describe(goal), met=not problems,
                           detail=detail, note="; ".join(problems) or None)


def check_directions(goal: DirectionsShown, events: list[dict[str, Any]]) -> ConditionResult:
    shown = [e for e in events if e.get("site") == "map" and e.get("type") == "directions"]
    met = any(e.get("origin") == goal.origin and e.get("destination") == goal.destination for e in shown)
    detail = {"directions_shown": [[e.get("origin"), e.get("destination")] for e in shown][-5:]}
    return ConditionResult(side="web", kind=goal.kind, description=_describe(goal), met=met, detail=detail)


def check_page(goal: PageVisited, events: list[dict[str, Any]]) -> ConditionResult:
    met = any(
        e.get("type") == "page_view"
        and e.get("site") == goal.site
        and isinstance(e.get("path"), str)
        and e["path"].startswith(goal.path_prefix)
        for e in events
    )
    return ConditionResult(side="web", kind=goal.kind, description=_describe(goal), met=met)


def check_web_goal(goal: Any, events: list[dict[str, Any]], task_goals: list[Any] | None = None) -> ConditionResult:
    if isinstance(goal, RecipeCompleted):
        return check_recipe(goal, events)
    if isinstance(goal, RecipesCompleted):
        return check_recipes(goal, events)
    if isinstance(goal, OrderPlaced):
        return check_order(goal, events, task_goals)
    if isinstance(goal, OrdersSplit):
        return check_orders_split(goal, events)
    if isinstance(goal, DirectionsShown):
        return check_directions(goal, events)
    if isinstance(goal, PageVisited):
        return check_page(goal, events)
    raise TypeError(f"not a web goal: {goal!r}")


def _describe(goal: Any) -> str:
    if isinstance(goal, RecipeCompleted):
        return f"recipe {goal.recipe_id} shown to its last step"
    if isinstance(goal, RecipesCompleted):
        return f"recipes {' and '.join(goal.recipe_ids)} shown to their last steps"
    if isinstance(goal, OrderPlaced):
        parts = [f"{goal.quantity} × {goal.product_id}"]
        if goal.size:
            parts.append(f"size {goal.size}")
        if goal.store_id:
            parts.append(f"at {goal.store_id}")
        return "order " + ", ".join(parts)
    if isinstance(goal, OrdersSplit):
        return (f"{len(goal.items)} items in one order at each of {' and '.join(goal.store_ids)}, "
                f"${goal.max_total:.2f} at most in all")
    if isinstance(goal, DirectionsShown):
        return f"directions {goal.origin} → {goal.destination}"
    if isinstance(goal, PageVisited):
        return f"visited {goal.site}:{goal.path_prefix}…"
    return goal.kind


def web_goal(goal: Any, ctx: CheckContext) -> ConditionResult:
    """The registry's entry point for every web goal kind (docs/grading.md, "Web goals")."""
    return check_web_goal(goal, ctx.events, ctx.web_goals)
