"""The heuristic agents. None uses a model; each exploits one prior an agent can see (docs/verified.md)."""

from __future__ import annotations

import math
import re
from collections import Counter
from functools import lru_cache
from typing import Any

from ...envs.geo.names import resolve_continent
from ...core.paths import tasks_dir
from ...core.taskmodel import TaskStore, TextAnswer
from ...envs.geo.goals import GeoAnswer
from ...websites.shop import catalog
from ...websites.wiki import store as wiki
from ..agents import Session

# The question an intent asks, from its own words (what every agent reads).
QUESTIONS = (("In what year was it built", "year_built", "Year built"), ("Who was its architect", "architect", "Architect"),
             ("What is its architectural style", "architectural_style", "Architectural style"),
             ("How tall is it", "height_m", "Height"), ("When is it open", "opening_hours", "Opening hours"),
             ("How many calories", "calories", None), ("What size of", "size", None))
STOPWORDS = frozenset("""a an the and or of in on at to for from with by is are was were be it its this that these
those as you your there here what which who when where how many much one two some any all each every no not
near about within m on foot stands landmark will know only look address name given find see street views walk
ends call street_stop finish_episode destination when wiki answer reply characters naming another candidate
even rule hedging counts wrong corner up into out over under you're has have had do does did can could would
should may might""".split())
_WORD = re.compile(r"[a-z][a-z'-]+")


def visible(s: Session) -> dict[str, Any]:
    """What the server showed the agent when the episode started (the intent, the step limit, ...)."""
    return dict(s.start.structured_content or {})


def question_of(intent: str) -> tuple[str, str | None]:
    for words, key, row in QUESTIONS:
        if words in intent:
            return key, row
    return "", None


def words_of(text: str) -> list[str]:
    return [w for w in _WORD.findall(text.casefold()) if w not in STOPWORDS and len(w) > 2]


def text_of(result: Any) -> str:
    return " ".join(getattr(c, "text", "") for c in (result.content or []))


# ------------------------------------------------------------------ priors from the public task files
@lru_cache(maxsize=1)
def _public_tasks() -> tuple[Any, ...]:
    return tuple(sorted(TaskStore([tasks_dir()]).all(), key=lambda t: t.id))


def prior_answer(task_id: str, intent: str) -> str | None:
    """The most frequent expected answer among the *other* tasks asking the same question."""
    key, _ = question_of(intent)
    if not key:
        return None
    counts = Counter(t.answer.must_include[0] for t in _public_tasks()
                     if t.id != task_id and isinstance(t.answer, TextAnswer) and t.answer.must_include
                     and question_of(t.intent)[0] == key)
    return counts.most_common(1)[0][0] if counts else None


def prior_location(task_id: str) -> dict[str, Any]:
    """The most frequent continent, country, city and street among the *other* geolocation tasks, at the
    mean position of that city's tasks: the best constant guess."""
    answers = [t.answer for t in _public_tasks() if t.id != task_id and isinstance(t.answer, GeoAnswer)]
    pick = {level: Counter(getattr(a, level) for a in answers).most_common(1)[0][0]
            for level in ("continent", "country", "city", "street")}
    at = [a for a in answers if a.city == pick["city"]] or answers
    return {"lat": sum(a.lat for a in at) / len(at), "lng": sum(a.lng for a in at) / len(at), **pick}


# ------------------------------------------------------------------ the wiki as a bag of words
@lru_cache(maxsize=1)
def _city_index() -> tuple[list[dict[str, Any]], dict[str, float]]:
    """Every city article with coordinates, as words of the city's article and its country's article."""
    articles = wiki.load_articles()
    by_title = {a.title: a for a in articles}
    cities: list[dict[str, Any]] = []
    for a in articles:
        if a.coordinates is None or "Country" not in a.infobox or a.category != "Cities":
            continue
        country = by_title.get(a.infobox["Country"])
        text = " ".join([a.title, wiki.plain_text(a.body), *(a.infobox.values()),
                         wiki.plain_text(country.body) if country else ""])
        cities.append({"title": a.title, "country": a.infobox["Country"], "continent": a.infobox.get("Continent"),
                       "lat": a.coordinates["lat"], "lng": a.coordinates["lng"], "words": set(words_of(text))})
    df: Counter[str] = Counter(w for c in cities for w in c["words"])
    idf = {w: math.log(len(cities) / n) for w, n in df.items()}
    return cities, idf


def best_city(observation: str) -> dict[str, Any] | None:
    """The city whose articles share the most (idf-weighted) words with the observation."""
    cities, idf = _city_index()
    seen = set(words_of(observation))
    scored = [(sum(idf.get(w, 0.0) for w in seen & c["words"]) / math.sqrt(len(c["words"]) or 1), c["title"], c)
              for c in cities]
    return max(scored, key=lambda x: (x[0], x[1]))[2] if scored else None


async def submit(s: Session, where: dict[str, Any]) -> None:
    continent = where.get("continent")
    await s.call("submit_location", {"lat": where["lat"], "lng": where["lng"],
                                     "continent": continent if continent and resolve_continent(continent) else None,
                                     "country": where.get("country"), "city": where.get("city"),
                                     "street": where.get("street")})


async def finish(s: Session, answer: str | None = None) -> None:
    if not s.ended:
        await s.call("finish_episode", {"answer": answer} if answer else {})


# ------------------------------------------------------------------ the agents
class PriorAgent:
    """Frequency: the most common answer to the same question (leave-one-out over the public task files);
    for geolocation the most common continent, country, city and street. Does nothing else."""

    name = "prior"

    async def play(self, s: Session) -> None:
        seen = visible(s)
        if seen.get("domain") == "geolocation":
            await submit(s, prior_location(str(seen.get("task_id"))))
        await finish(s, prior_answer(str(seen.get("task_id")), str(seen.get("intent", ""))))


class GeoLexicalAgent:
    """Lexical matching: look around once, then submit the wiki city whose article (with its country's)
    shares the most idf-weighted words with the views; no reasoning, no second look."""

    name = "geo-lexical"

    async def play(self, s: Session) -> None:
        if visible(s).get("domain") != "geolocation":
            return await finish(s)
        look = await s.call("geo_look", {"direction": "all"})
        city = best_city(text_of(look))
        if city is not None:
            await submit(s, {"lat": city["lat"], "lng": city["lng"], "continent": city["continent"],
                             "country": city["country"], "city": city["title"]})
        await finish(s)


_RESULT = re.compile(r"link '([^']+)' url: (/wiki/[^\s]+)")
_ROW = re.compile(r"rowheader '([^']+)'\s*\n\s*\[\d+\] cell '([^']*)'")


class WikiSearchAgent:
    """Intent-word search: search the wiki with the intent's description words (traveling) or the views'
    words (geolocation), open the first result and answer from its infobox. No walk."""

    name = "wiki-search"

    async def play(self, s: Session) -> None:
        seen = visible(s)
        domain, intent = seen.get("domain"), str(seen.get("intent", ""))
        if domain == "geolocation":
            look = text_of(await s.call("geo_look", {"direction": "all"}))
            query = " ".join(list(dict.fromkeys(words_of(look)))[:25])
        elif domain == "traveling":
            described = intent.split("No address or name is given")[0].split("Your walk ends")[0]
            query = " ".join(list(dict.fromkeys(words_of(described.split(":", 1)[-1])))[:25])
        else:
            return await finish(s)
        if "web" in (seen.get("environments") or {}) and seen.get("active_environment") != "web":
            await s.call("switch_environment", {"target": "web", "message": "search the wiki"})
        page = text_of(await s.call("browser_goto", {"url": f"wiki:/search?q={query}"}))
        hits = [m.group(2) for m in _RESULT.finditer(page) if m.group(2) != "/wiki/"]
        if domain == "geolocation":  # the first listed city
            hits = [h for h in hits if (a := wiki.find(h.rsplit("/", 1)[-1])) is not None and a.category == "Cities"
                    and a.coordinates]
        if not hits:
            return await finish(s)
        article = text_of(await s.call("browser_goto", {"url": "wiki:" + hits[0]}))
        rows = {k: v for k, v in _ROW.findall(article)}
        if domain == "geolocation":
            found = wiki.find(hits[0].rsplit("/", 1)[-1])
            if found is not None and found.coordinates:
                await s.call("switch_environment", {"target": "embodied", "message": "submit"})
                await submit(s, {"lat": found.coordinates["lat"], "lng": found.coordinates["lng"],
                                 "continent": found.infobox.get("Continent"), "country": found.infobox.get("Country"),
                                 "city": found.title})
            return await finish(s)
        _, row = question_of(intent)
        await finish(s, rows.get(row or "", "") or None)


def _buy(product_id: str, size: str, store: str | None) -> list[tuple[str, dict[str, Any]]]:
    calls: list[tuple[str, dict[str, Any]]] = [("browser_goto", {"url": f"shop:/product/{product_id}"}),
                                               ("browser_type", {"element": "combobox 'Size'", "text": size})]
    if store is not None:
        calls.append(("browser_type", {"element": "combobox 'Store'", "text": store}))
    return calls + [("browser_click", {"element": "button 'Add to cart'"}), ("browser_goto", {"url": "shop:/checkout"}),
                    ("browser_click", {"element": "button 'Place order'"})]


def named_products(intent: str) -> list[tuple[Any, str]]:
    """The products "Name (size)" the intent names, as the shop lists them (the shop's public pages)."""
    found: list[tuple[int, Any, str]] = []
    taken: set[int] = set()
    for product in sorted(catalog.load_products(), key=lambda p: -len(p.name)):
        at = intent.find(product.name + " (")
        if at < 0 or at in taken:
            continue
        taken |= set(range(at, at + len(product.name)))
        start = at + len(product.name) + 2
        found.append((at, product, intent[start:intent.index(")", start)]))
    return [(p, size) for _, p, size in sorted(found, key=lambda x: x[0])]


class OrderEverywhereAgent:
    """Doing everything: order each product the intent names at every store that sells that size, so
    whichever store the task means has an order. No walk."""

    name = "order-everywhere"

    async def play(self, s: Session) -> None:
        seen = visible(s)
        if seen.get("domain") != "shopping":
            return await finish(s)
        if seen.get("active_environment") != "web":
            await s.call("switch_environment", {"target": "web", "message": "order"})
        stores = {st.id: st.name for st in catalog.load_stores()}
        for product, size in named_products(str(seen.get("intent", ""))):
            for offer in product.offers:
                if offer.size != size:
                    continue
                for tool, args in _buy(product.id, size, stores[offer.store_id]):
                    if s.ended:
                        return
                    await s.call(tool, args)
        await finish(s)


class FirstListedAgent:
    """Position: order each named product at the store its page lists first (the menu's default), and answer
    a size question with the last size the shop lists. No walk."""

    name = "first-listed"

    async def play(self, s: Session) -> None:
        seen = visible(s)
        intent = str(seen.get("intent", ""))
        if seen.get("domain") != "shopping":
            return await finish(s)
        if seen.get("active_environment") != "web":
            await s.call("switch_environment", {"target": "web", "message": "order"})
        answer = None
        products = named_products(intent)
        m = re.search(r"What size of (.+?) should I buy", intent)
        if m:
            product = next((p for p in catalog.load_products() if p.name == m.group(1)), None)
            if product is not None:
                answer = product.sizes[-1].label
                products = [(product, answer)]
        for product, size in products:
            for tool, args in _buy(product.id, size, None):
                await s.call(tool, args)
        await finish(s, answer)


# ------------------------------------------------------------------ cooking
def dish_of(intent: str) -> str | None:
    """The dish the intent names ("Cook <name>. ..."), as the recipe site spells it."""
    from ...websites.recipes.catalog import load_catalog

    names = sorted({r["name"] for r in load_catalog().recipes}, key=len, reverse=True)
    return next((n for n in names if intent.startswith(f"Cook {n}.")), None)


def missing_foods(intent: str) -> list[str]:
    """The foods the intent says the kitchen lacks ("Your kitchen has no Egg and no Potato: ...")."""
    m = re.search(r"Your kitchen has no (.+?): order", intent)
    return [f.strip() for f in m.group(1).split(" and no ")] if m else []


def same_named(name: str) -> list[dict[str, Any]]:
    """The recipes the site lists for a search of the dish's name that carry exactly that name, in order."""
    from ...websites.recipes.catalog import Filters, load_catalog

    return [r for r in load_catalog().search(Filters(q=name)) if r["name"] == name]


def cooking_task(s: Session) -> tuple[str, list[dict[str, Any]]]:
    """The intent and the recipes the site lists for what it names ([] outside cooking)."""
    seen = visible(s)
    intent = str(seen.get("intent", ""))
    return intent, listed_recipes(intent) if seen.get("domain") == "cooking" else []


def listed_recipes(intent: str) -> list[dict[str, Any]]:
    """The recipes the intent's name matches, as the site lists them: every recipe of the dish's name, or,
    where the intent asks by a word of the name ('the dish whose name has the word "Salad"'), every recipe
    whose name has the word, or, where it asks by an ingredient ('the dish made with "Potato"'), every recipe
    the site's ingredient filter lists for it. The constraints that tell them apart are not read."""
    from ...envs.kitchen.taskgen.cooking import made_with, named_with
    from ...websites.recipes.catalog import load_catalog

    name = dish_of(intent)
    if name is not None:
        return same_named(name)
    m = re.match(r'Cook the dish whose name has the word "([^"]+)"', intent)
    if m:
        return named_with(m.group(1).lower(), load_catalog())
    m = re.match(r'Cook the dish made with "([^"]+)"', intent)
    return made_with(m.group(1), load_catalog()) if m else []


async def open_last_step(s: Session, recipe: dict[str, Any]) -> None:
    await s.call("browser_goto", {"url": f"recipes:/?q={recipe['name']}"})
    await s.call("browser_goto", {"url": f"recipes:/recipe/{recipe['id']}?step={len(recipe['steps'])}"})


async def order_missing(s: Session, foods: list[str]) -> None:
    """Order the foods the intent names as missing, for delivery (the shop's public pages)."""
    from ...envs.kitchen.taskgen.cooking import buy_oracle, delivery_store
    from ...websites.recipes.vocabulary import KITCHEN_PRODUCTS

    products = [KITCHEN_PRODUCTS[f] for f in foods if f in KITCHEN_PRODUCTS]
    if products and delivery_store(products) is not None:
        for c in buy_oracle(products):
            if s.ended:
                return
            await s.call(c.tool, c.args)


async def enter_kitchen(s: Session) -> str | None:
    """Switch to the kitchen; the scene its first observation names."""
    seen = text_of(await s.call("switch_environment", {"target": "embodied", "message": "cook"}))
    m = re.search(r"Kitchen (FloorPlan\d+)", seen)
    return m.group(1) if m else None


async def run_calls(s: Session, calls: list[dict[str, Any]]) -> None:
    for c in calls:
        if s.ended:
            return
        await s.call(c["tool"], c["args"])


class CookingHeuristic:
    """What every cooking heuristic does, told apart by what it opens and what it cooks: open the last step
    of each recipe ``opened`` picks from those the intent's name lists, order the foods the intent names as
    missing, enter the kitchen, make the calls that carry out ``ops`` there, then finish."""

    name = ""

    def opened(self, recipes: list[dict[str, Any]]) -> list[dict[str, Any]]:
        return recipes

    def ops(self, recipes: list[dict[str, Any]], scene: str, missing: list[str]) -> list[dict[str, Any]]:
        raise NotImplementedError

    async def play(self, s: Session) -> None:
        from ...envs.kitchen.taskgen.outcomes import kitchen_calls

        intent, recipes = cooking_task(s)
        if not recipes:
            return await finish(s)
        for recipe in self.opened(recipes):
            await open_last_step(s, recipe)
        missing = missing_foods(intent)
        await order_missing(s, missing)
        scene = await enter_kitchen(s)
        if scene is not None:
            await run_calls(s, kitchen_calls(scene, self.ops(recipes, scene, missing), missing))
        await finish(s)


class CookEverythingAgent(CookingHeuristic):
    """Doing everything: open the last step of every recipe with the dish's name, order the missing foods,
    then cut (crack) every food, cook every piece (bread in the toaster, the rest in the pan on a lit burner),
    put a piece of each on one plate and turn the stove off. Never reads a constraint."""

    name = "cook-everything"

    def ops(self, recipes: list[dict[str, Any]], scene: str, missing: list[str]) -> list[dict[str, Any]]:
        from ...envs.kitchen.taskgen.outcomes import everything_ops, kitchen_foods

        return everything_ops(kitchen_foods(scene, missing))


class LookAlikeAgent(CookingHeuristic):
    """Choosing by name: open the last step of every recipe the site lists with the dish's name (so the
    recipe goal cannot tell), ignore the intent's constraints (diet, equipment, ingredients), and cook
    exactly the first listed one's kitchen steps (the planner's calls) after ordering the missing foods.
    Where the first listed recipe is the task's it does the task; where it is the look-alike, the kitchen
    goals must fail."""

    name = "look-alike"

    def ops(self, recipes: list[dict[str, Any]], scene: str, missing: list[str]) -> list[dict[str, Any]]:
        from ...envs.kitchen.taskgen.recipe_goals import recipe_ops

        return recipe_ops(recipes[0])


class FirstRecipeAgent(LookAlikeAgent):
    """Choosing by position: open only the first recipe the site lists for the dish's name (or the word the
    intent asks by) and cook it exactly (the planner's calls), the constraints ignored. It passes where the
    target is listed first: a guess, which a choice among two recipes leaves right half the time."""

    name = "first-recipe"

    def opened(self, recipes: list[dict[str, Any]]) -> list[dict[str, Any]]:
        return recipes[:1]


class CookUnionAgent(CookingHeuristic):
    """Over-acting among look-alikes: open the last step of every recipe the intent's name matches, order the
    missing foods, then do every cut and cooking any of them does and plate only what all of them serve
    (outcomes.union_ops). Passes only where the goals ask for nothing that tells the recipes apart."""

    name = "cook-union"

    def ops(self, recipes: list[dict[str, Any]], scene: str, missing: list[str]) -> list[dict[str, Any]]:
        from ...envs.kitchen.taskgen.outcomes import union_ops
        from ...envs.kitchen.taskgen.recipe_goals import recipe_ops

        return union_ops([recipe_ops(r) for r in recipes])


# The agents of this module; table.py lists them with the walking agents (walking.py builds on the helpers
# here, so the table lives above both).
AGENTS = (PriorAgent, GeoLexicalAgent, WikiSearchAgent, OrderEverywhereAgent, FirstListedAgent,
          CookEverythingAgent, LookAlikeAgent, FirstRecipeAgent, CookUnionAgent)
