"""The indoor world: 30 AI2-THOR-style kitchens, a pure-Python simulator and an AI2-THOR adapter.

Modules: ``vocabulary`` (object types and rules), ``scenes`` (the generated kitchens), ``sim``
(``KitchenSim``, answering AI2-THOR actions with AI2-THOR metadata), ``session`` (references,
teleporting, deliveries, final state over any controller), ``observe`` and ``render`` (what the
agent sees), ``env`` (the episode environment), ``backends``/``ai2thor_backend``/``standin``
(the real ai2thor client, and a headless stand-in for its Unity build), ``planner`` (recipe ops
to tool calls). See docs/indoor.md.
"""
