"""`ewa-mcp tasks validate`'s second half: every name a task refers to exists in the shipped data.

The task schema (taskmodel.py) checks a task's shape; it cannot know whether ``FloorPlan99``, the city
``atlantis``, the street node ``mn-0000000000``, the recipe ``r999``, the product ``prod-unicorn`` or the geo
standpoint ``g999`` exist. Such a task loads, lists and starts, then fails mid-episode or grades as
impossible. ``ReferenceChecker`` resolves each reference against the data the environments and sites
serve (the kitchens, the street graphs, including those an imported suite carries in its ``streets/``
folder, the recipe and shop catalogues, the geo standpoints, the site names) and says what is missing.

The data is loaded once per checker, only for the kinds of reference the tasks use.
"""

from __future__ import annotations

import re
from functools import cached_property
from pathlib import Path
from typing import Any

from .core.taskmodel import Task
from .envs.browser.goals import (DirectionsShown, OrderPlaced, OrdersSplit, PageVisited, RecipeCompleted,
                                 RecipesCompleted)
from .envs.geo.goals import GeoStart
from .envs.kitchen.goals import KitchenStart
from .envs.street.goals import StreetStart, _StreetTarget

_SITE_URL = re.compile(r"^([a-z][a-z0-9_-]*):(?!//)")  # "shop:/product/7"; not "http://..."


def _some(names: Any, limit: int = 5) -> str:
    names = sorted(names)
    return ", ".join(names[:limit]) + (f", … ({len(names)} in all)" if len(names) > limit else "")


class ReferenceChecker:
    """Resolves the references of tasks against the shipped data (and the street graphs of ``street_dirs``)."""

    def __init__(self, street_dirs: list[Path] | None = None):
        self.street_dirs = [Path(d) for d in street_dirs or []]

    # ------------------------------------------------------------ the data, loaded on first use
    @cached_property
    def _world(self) -> Any:
        from .envs.street.world import World, _extra_dirs

        dirs = _extra_dirs()
        dirs += [d for d in self.street_dirs if d.is_dir() and str(d) not in {str(x) for x in dirs}]
        return World(data_dirs=dirs)

    @cached_property
    def _recipes(self) -> set[str]:
        from .websites.recipes.catalog import load_recipes

        return {r["id"] for r in load_recipes()}

    @cached_property
    def _products(self) -> set[str]:
        from .websites.shop.catalog import load_products

        return {p.id for p in load_products()}

    @cached_property
    def _stores(self) -> set[str]:
        from .websites.shop.catalog import load_stores

        return {s.id for s in load_stores()}

    @cached_property
    def _sites(self) -> set[str]:
        from .websites.serve import SITES

        return set(SITES)

    # ------------------------------------------------------------ one reference each
    def _kitchen(self, scene: str) -> str | None:
        from .envs.kitchen.scene_model import SceneError, scene_number

        try:
            scene_number(scene)
        except SceneError as exc:
            return str(exc)
        return None

    def _geo(self, location_id: str) -> str | None:
        from .envs.geo.locations import LOCATIONS

        if location_id in LOCATIONS:
            return None
        return f"unknown geolocation standpoint {location_id!r}; the standpoints are {_some(LOCATIONS)}"

    def _city(self, city: str) -> str | None:
        if city in self._world.cities_by_name:
            return None
        return (f"unknown city {city!r}; the street graphs are {_some(self._world.cities_by_name)} (an imported "
                "suite's graphs must be in its streets/ folder, or in EWA_STREET_DATA)")

    def _node(self, city: str, node: str) -> str | None:
        graph = self._world.cities_by_name.get(city)
        if graph is None:
            return None  # reported as an unknown city
        if node in graph.index:
            return None
        return f"unknown street node {node!r} in {city} (node ids look like '{next(iter(graph.index), '')}')"

    def _place(self, ref: str) -> str | None:
        from .envs.street.world import WorldError

        try:
            self._world.resolve(ref)
        except WorldError:
            return f"unknown place or street node {ref!r}"
        return None

    # ------------------------------------------------------------ a task
    def missing(self, task: Task) -> list[str]:
        """One message per reference of ``task`` that the shipped data does not have: where it is in the task
        (a field path like ``start.embodied.scene``) and what is missing."""
        out: list[str] = []

        def add(where: str, problem: str | None) -> None:
            if problem:
                out.append(f"{where}: {problem}")

        web = task.start.web
        if web is not None:
            match = _SITE_URL.match(web.start_url)
            if match and match.group(1) not in self._sites:
                add("start.web.start_url", f"unknown site {match.group(1)!r}; the sites are {_some(self._sites)}")
        start = task.start.embodied
        if isinstance(start, KitchenStart):
            add("start.embodied.scene", self._kitchen(start.scene))
        elif isinstance(start, StreetStart):
            add("start.embodied.city", self._city(start.city))
            add("start.embodied.node", self._node(start.city, start.node))
        elif isinstance(start, GeoStart):
            add("start.embodied.location_id", self._geo(start.location_id))
        for i, goal in enumerate(task.web_goals):
            where = f"web_goals.{i}"
            if isinstance(goal, RecipeCompleted) and goal.recipe_id not in self._recipes:
                add(f"{where}.recipe_id", f"unknown recipe {goal.recipe_id!r}; the recipes are {_some(self._recipes)}")
            elif isinstance(goal, RecipesCompleted):
                for rid in goal.recipe_ids:
                    if rid not in self._recipes:
                        add(f"{where}.recipe_ids", f"unknown recipe {rid!r}; the recipes are {_some(self._recipes)}")
            elif isinstance(goal, OrderPlaced):
                if goal.product_id not in self._products:
                    add(f"{where}.product_id", f"unknown product {goal.product_id!r}; the shop sells "
                        f"{_some(self._products)}")
                if goal.store_id is not None and goal.store_id not in self._stores:
                    add(f"{where}.store_id", f"unknown store {goal.store_id!r}; the stores are {_some(self._stores)}")
            elif isinstance(goal, OrdersSplit):
                for j, item in enumerate(goal.items):
                    if item.product_id not in self._products:
                        add(f"{where}.items.{j}.product_id", f"unknown product {item.product_id!r}; the shop sells "
                            f"{_some(self._products)}")
                for j, store in enumerate(goal.store_ids):
                    if store not in self._stores:
                        add(f"{where}.store_ids.{j}", f"unknown store {store!r}; the stores are {_some(self._stores)}")
            elif isinstance(goal, DirectionsShown):
                add(f"{where}.origin", self._place(goal.origin))
                add(f"{where}.destination", self._place(goal.destination))
            elif isinstance(goal, PageVisited) and goal.site not in self._sites:
                add(f"{where}.site", f"unknown site {goal.site!r}; the sites are {_some(self._sites)}")
        for i, egoal in enumerate(task.embodied_goals):
            if isinstance(egoal, _StreetTarget):
                where = f"embodied_goals.{i}"
                add(f"{where}.city", self._city(egoal.city))
                add(f"{where}.node", self._node(egoal.city, egoal.node))
                if egoal.place_id is not None:
                    add(f"{where}.place_id", self._place(egoal.place_id))
        return out


def street_dirs_of(task_dirs: list[Path]) -> list[Path]:
    """The street graph folders imported task suites carry (``<dir>/streets``, as build_server reads them)."""
    return [Path(d) / "streets" for d in task_dirs if (Path(d) / "streets").is_dir()]
