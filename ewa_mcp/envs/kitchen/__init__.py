"""The indoor world: 30 AI2-THOR-style kitchens, a pure-Python simulator and an AI2-THOR adapter.

Modules: ``vocabulary`` (object types and rules), ``scenes`` (the generated kitchens; parts in
``scene_model``, ``scene_layout``, ``scene_stock``), ``sim`` (``KitchenSim``, answering AI2-THOR
actions with AI2-THOR metadata; parts in ``sim_objects``, ``sim_world``, ``sim_moves``,
``sim_hands``, ``sim_heat``, ``sim_metadata``), ``session`` (references, teleporting, final state
over any controller; ``deliveries`` for shop orders), ``observe`` and ``kitchen_map`` (what the
agent sees), ``actions`` (the kitchen action table) and ``commands`` (action strings), ``env``
(the episode environment), ``backends``/``ai2thor_backend``/``standin`` (the real ai2thor client,
and a headless stand-in for its Unity build), ``planner`` (recipe ops to tool calls).
See ewa_mcp/envs/kitchen/README.md.
"""

from __future__ import annotations

from ewa_mcp.core.registry import Domain, EnvironmentSpec

from ..browser import BROWSER, WEB_CHECKS, WEB_GOALS

KITCHEN = EnvironmentSpec("kitchen", "embodied", f"{__name__}.env:KitchenEnvironment", f"{__name__}.tools",
                          "kitchen_* tools", tool_order=30, start=f"{__name__}.goals:KitchenStart",
                          goals=(f"{__name__}.goals:ObjectState", f"{__name__}.goals:ObjectIn"),
                          options=f"{__name__}.options:KitchenOptions")

DOMAINS = [
    Domain("cooking", (BROWSER, KITCHEN), generator=f"{__name__}.taskgen.pantry:generate",
           goal_kinds=(*WEB_GOALS, "object_state", "object_in", "cooked_with", "holds_only"),
           checks={**WEB_CHECKS, "object_state": f"{__name__}.checks:object_state",
                   "object_in": f"{__name__}.checks:object_in",
                   "cooked_with": f"{__name__}.checks:cooked_with",
                   "holds_only": f"{__name__}.checks:holds_only"}),
]
