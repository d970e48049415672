"""The indoor world: 30 AI2-THOR-style kitchens, a pure-Python simulator and an AI2-THOR adapter.

Modules: ``vocabulary`` (object types and rules), ``scenes`` (the generated kitchens; parts in
``scene_model``, ``scene_layout``, ``scene_stock``), ``sim`` (``KitchenSim``, answering AI2-THOR
actions with AI2-THOR metadata; parts in ``sim_objects``, ``sim_world``, ``sim_moves``,
``sim_hands``, ``sim_heat``, ``sim_metadata``), ``session`` (references, teleporting, final state
over any controller; ``deliveries`` for shop orders), ``observe`` and ``kitchen_map`` (what the
agent sees), ``actions`` (the kitchen action table) and ``commands`` (action strings), ``env``
(the episode environment), ``backends``/``ai2thor_backend``/``standin`` (the real ai2thor client,
and a headless stand-in for its Unity build), ``planner`` (recipe ops to tool calls).
See docs/indoor.md.
"""
