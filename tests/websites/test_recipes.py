"""Route tests for the recipes site (Starlette TestClient, no browser)."""

from __future__ import annotations

import html
import json
import re
from pathlib import Path
from urllib.parse import urlencode

import pytest
from starlette.testclient import TestClient

from ewa_mcp.websites.common import EPISODE_HEADER
from ewa_mcp.websites.recipes.app import create_app

DATA = json.loads((Path(__file__).resolve().parents[2] / "websites" / "recipes" / "data" / "recipes.json")
                  .read_text(encoding="utf-8"))
BY_ID = {r["id"]: r for r in DATA}


@pytest.fixture
def client(site_context):
    return TestClient(create_app(site_context))


def result_ids(page_html: str) -> list[str]:
    return re.findall(r'<h2><a href="/recipe/(r\d+)">', page_html)


def all_result_ids(client: TestClient, query: str) -> list[str]:
    """Follow the pagination links so the whole result set is checked, not only page 1."""
    ids, url = [], "/" + query
    while url:
        response = client.get(url)
        assert response.status_code == 200, response.text
        ids += result_ids(response.text)
        match = re.search(r'<a href="([^"]+)" rel="next">Next page</a>', response.text)
        url = html.unescape(match.group(1)) if match else ""
    return ids


def names(recipe: dict) -> set[str]:
    return {i["name"] for i in recipe["ingredients"]}


def test_front_page_lists_every_recipe_across_pages(client):
    first = client.get("/")
    assert first.status_code == 200
    assert f"of {len(DATA)} recipes" in first.text
    ids = all_result_ids(client, "")
    assert sorted(ids) == sorted(BY_ID)  # each recipe exactly once over all pages


def test_url_state_filters_results_and_is_restored_in_the_form(client):
    query = "?q=toast&diet=vegetarian&include=Bread&exclude=Egg&equipment=Toaster&difficulty=novice"
    page = client.get("/" + query).text
    ids = all_result_ids(client, query)
    assert ids, "the example query should match something"
    for rid in ids:
        r = BY_ID[rid]
        assert "toast" in (r["name"] + " " + " ".join(names(r))).lower()
        assert r["diet"] == "vegetarian" and r["difficulty"] == "novice"
        assert "Bread" in names(r) and "Egg" not in names(r) and "Toaster" in r["equipment"]
    # Everything that satisfies the filters is found (checked against the data, not the site's code).
    expected = {r["id"] for r in DATA if r["diet"] == "vegetarian" and r["difficulty"] == "novice"
                and "Bread" in names(r) and "Egg" not in names(r) and "Toaster" in r["equipment"]
                and "toast" in (r["name"] + " " + r["cuisine"] + " " + " ".join(names(r))).lower()}
    assert set(ids) == expected
    # A reload shows the same state: the search box and every select keep their values.
    assert 'name="q" value="toast"' in page
    for select, value in (("diet", "vegetarian"), ("difficulty", "novice"), ("include", "Bread"),
                          ("exclude", "Egg"), ("equipment", "Toaster")):
        block = re.search(rf'<select id="{select}" name="{select}">(.*?)</select>', page, re.S).group(1)
        assert re.findall(r'<option value="([^"]*)" selected>', block) == [value], select


def test_filters_are_case_insensitive_and_canonicalised(client):
    loose = all_result_ids(client, "?diet=VEGAN&include=tomato&equipment=stove%20burner")
    strict = all_result_ids(client, "?diet=vegan&include=Tomato&equipment=StoveBurner")
    assert loose == strict and loose
    assert all("StoveBurner" in BY_ID[i]["equipment"] for i in loose)


def test_form_submissions_redirect_to_one_canonical_url(client, event_log):
    response = client.get("/?q=+salad+&diet=&difficulty=&cuisine=&include=tomato&exclude=&equipment=bowl",
                          headers={EPISODE_HEADER: "ep-canon"}, follow_redirects=False)
    assert response.status_code == 302
    assert response.headers["location"] == "/?q=salad&include=Tomato&equipment=Bowl"
    assert event_log.for_episode("ep-canon") == []  # only the canonical page counts as the visit
    assert client.get("/?q=salad&include=Tomato&equipment=Bowl", follow_redirects=False).status_code == 200


def test_repeated_include_requires_all_and_repeated_exclude_rejects_any(client):
    ids = all_result_ids(client, "?include=Egg&include=Potato&exclude=Bacon&exclude=Onion")
    expected = {r["id"] for r in DATA if {"Egg", "Potato"} <= names(r) and not {"Bacon", "Onion"} & names(r)}
    assert set(ids) == expected and expected
    page = client.get("/?include=Egg&include=Potato").text
    # The second value rides along as a hidden input so submitting the form again keeps it.
    assert '<input type="hidden" name="include" value="Potato">' in page


def test_exact_name_search_ranks_the_lookalike_pair_first(client):
    pair = [r for r in DATA if r["name"] == "Garlic Tomato Toast"]
    assert len(pair) == 2
    ids = result_ids(client.get("/?" + urlencode({"q": "garlic tomato toast"})).text)
    assert set(ids[:2]) == {r["id"] for r in pair}


def test_active_filter_remove_links_drop_only_that_filter(client):
    page = client.get("/?q=salad&diet=vegan&include=Tomato").text
    links = dict((label, html.unescape(href)) for href, label in
                 re.findall(r'<a href="([^"]+)" aria-label="([^"]+)">Remove</a>', page))
    assert links["Remove diet filter"] == "/?q=salad&include=Tomato"
    assert links["Remove include Tomato"] == "/?q=salad&diet=vegan"


def test_search_and_page_view_events_carry_the_episode(client, event_log):
    client.get("/?q=soup&difficulty=simple", headers={EPISODE_HEADER: "ep-7"})
    searches = event_log.for_episode("ep-7", type="search")
    assert len(searches) == 1
    event = searches[0]
    assert event["site"] == "recipes" and event["query"] == "soup"
    assert event["filters"]["difficulty"] == "simple" and event["filters"]["include"] == []
    expected = sum(1 for r in DATA if r["difficulty"] == "simple"
                   and "soup" in (r["name"] + " " + r["cuisine"] + " " + " ".join(names(r))).lower())
    assert event["results"] == expected
    assert event_log.for_episode("ep-7", type="page_view")[0]["path"] == "/"
    assert event_log.for_episode("anonymous") == []  # nothing leaked to another episode


def test_plain_front_page_is_not_a_search(client, event_log):
    client.get("/", headers={EPISODE_HEADER: "ep-8"})
    assert event_log.for_episode("ep-8", type="search") == []
    assert len(event_log.for_episode("ep-8", type="page_view")) == 1


def test_step_viewer_walks_a_recipe_and_emits_every_step(client, event_log):
    recipe = BY_ID["r001"]
    n = len(recipe["steps"])
    headers = {EPISODE_HEADER: "ep-steps"}
    first = client.get("/recipe/r001", headers=headers).text
    assert f"Step 1 of {n}" in first
    assert '<button type="button" disabled>Previous step</button>' in first
    # Step links land on the step box (#step), not on the top of the recipe page.
    assert 'href="/recipe/r001?step=2#step" rel="next">Next step</a>' in first
    assert '<section class="steps" id="step"' in first
    assert html.escape(recipe["steps"][0]["text"], quote=False) in first
    for k in range(2, n + 1):
        page = client.get(f"/recipe/r001?step={k}", headers=headers).text
        assert f"Step {k} of {n}" in page
        assert html.escape(recipe["steps"][k - 1]["text"], quote=False) in page
    last = page
    assert '<button type="button" disabled>Next step</button>' in last
    assert "This is the last step" in last
    steps = event_log.for_episode("ep-steps", type="recipe_step")
    assert [(e["recipe_id"], e["step"], e["of"]) for e in steps] == [("r001", k, n) for k in range(1, n + 1)]


def test_recipe_page_shows_facts_ingredients_equipment_and_image(client):
    recipe = next(r for r in DATA if any(not i["kitchen_type"] for i in r["ingredients"]))
    page = client.get(f"/recipe/{recipe['id']}").text
    assert f"<h1>{html.escape(recipe['name'])}</h1>" in page
    for item in recipe["ingredients"]:
        assert f"{html.escape(item['amount'])} {html.escape(item['name'])}" in page
    # Kitchen foods link to their shop product for delivery (whichever one a kitchen lacks); shop-only
    # ingredients are marked as outside the kitchen goal, with no buy link to mislead an agent.
    for item in recipe["ingredients"]:
        if item["kitchen_type"]:
            assert re.search(rf'/product/{item["product_id"]}">order {item["name"]} for delivery</a>', page)
        else:
            assert f"{html.escape(item['name'])} (not in the kitchen: not part of the kitchen goal)" in page
            assert f"/product/{item['product_id']}\"" not in page and "find " not in page
    alt = re.search(rf'<img src="/image/{recipe["id"]}.svg" alt="([^"]+)"', page).group(1)
    assert recipe["name"] in html.unescape(alt)


def test_every_step_says_what_of_it_the_kitchen_does(client):
    recipe = BY_ID["r001"]  # step 4 is plain text (garlic, olive oil); step 6 names sea salt beside its op
    plain = client.get("/recipe/r001?step=4").text
    assert "Not a kitchen step" in plain and "not part of the kitchen goal" in plain
    mixed = client.get("/recipe/r001?step=6").text
    assert f"In the kitchen: {recipe['steps'][5]['kitchen']}" in mixed
    assert "Not in the kitchen (not part of the kitchen goal): Sea Salt." in mixed
    doable = client.get("/recipe/r001?step=1").text  # its text is the kitchen's own words: still noted
    assert f"In the kitchen: {recipe['steps'][0]['kitchen']}" in doable


def test_every_step_of_every_recipe_has_a_kitchen_note(client):
    """Each step says either what the kitchen does of it or that it is not a kitchen step, even when
    the step's text is already in the kitchen's words ("Turn off the stove.")."""
    for recipe in DATA:
        for number, step in enumerate(recipe["steps"], start=1):
            page = client.get(f"/recipe/{recipe['id']}?step={number}").text
            if step["kitchen"] is None:
                assert "Not a kitchen step" in page, (recipe["id"], number)
            else:
                assert f"In the kitchen: {html.escape(step['kitchen'])}" in page, (recipe["id"], number)


def test_image_is_stable_svg_describing_its_ingredients(client):
    first = client.get("/image/r003.svg")
    assert first.status_code == 200 and first.headers["content-type"].startswith("image/svg+xml")
    assert first.content == client.get("/image/r003.svg").content
    assert first.content != client.get("/image/r004.svg").content
    title = re.search(r"<title>(.*?)</title>", first.text).group(1)
    for item in BY_ID["r003"]["ingredients"]:
        if item["kitchen_type"]:
            assert item["name"].lower() in title


@pytest.mark.parametrize(
    ("url", "status", "phrase"),
    [
        ("/?diet=keto", 400, "Use one of: vegetarian, vegan, non-vegetarian"),
        ("/?difficulty=impossible", 400, "Unknown difficulty"),
        ("/?include=Caviar", 400, "Unknown include"),
        ("/?equipment=Blender", 400, "Unknown equipment"),
        ("/?include=Egg&exclude=egg", 400, "both included and excluded"),
        ("/?diet=vegan&diet=vegetarian", 400, "give it once"),
        ("/?q=" + "a" * 201, 400, "at most 200"),
        ("/?page=two", 400, "page must be a whole number"),
        ("/?page=0", 400, "page must be a whole number"),
        ("/?page=999", 404, "does not exist"),
        ("/recipe/r999", 404, "There is no recipe with id"),
        ("/recipe/r001?step=0", 404, "Use a step from 1 to"),
        ("/recipe/r001?step=99", 404, "Use a step from 1 to"),
        ("/recipe/r001?step=last", 400, "step must be a whole number"),
        ("/image/nope.svg", 404, "There is no recipe with id"),
        ("/nowhere", 404, "Error 404"),
    ],
)
def test_bad_input_gets_a_clear_4xx_page_and_no_event(client, event_log, url, status, phrase):
    response = client.get(url, headers={EPISODE_HEADER: "ep-bad"})
    assert response.status_code == status
    assert phrase in html.unescape(response.text)
    assert event_log.for_episode("ep-bad") == []


def test_hostile_query_text_is_escaped_not_executed(client):
    hostile = "<script>alert(1)</script>' OR 1=1; --"
    response = client.get("/?" + urlencode({"q": hostile}))
    assert response.status_code == 200
    assert "<script>alert(1)</script>" not in response.text
    assert "&lt;script&gt;alert(1)&lt;/script&gt;" in response.text
    assert "No recipes match" in response.text
    long_id = client.get("/recipe/" + "x" * 500)
    assert long_id.status_code == 404 and "x" * 100 not in long_id.text


def test_post_is_refused_with_405(client):
    assert client.post("/", data={"q": "x"}).status_code == 405
    assert client.post("/recipe/r001").status_code == 405
