"""The Inspect AI tasks end to end, offline: Inspect's mockllm model, scripted to make each task's oracle
calls as model tool calls, plays one task of every domain through the real MCP server and Inspect's MCP
tools; the project's grader scores 1.0. The unscripted mockllm (its default output only talks) scores 0.

No output here carries its token usage, so mockllm counts tokens itself: the harness must give it an
offline estimate, because Inspect's default counter loads tiktoken's o200k_base encoding, which tiktoken
downloads on first use (the tests fail if anything asks tiktoken for an encoding)."""

from __future__ import annotations

import json
import re

import pytest

pytest.importorskip("inspect_ai")

from inspect_ai import eval as inspect_eval  # noqa: E402
from inspect_ai.model import ModelOutput, get_model  # noqa: E402

from ewa_mcp import inspect_tasks  # noqa: E402
from ewa_mcp.core.paths import tasks_dir  # noqa: E402
from ewa_mcp.core.taskmodel import TaskStore  # noqa: E402

# End to end (minutes of the suite's time): `make test-slow`, which CI runs after `make test`.
pytestmark = pytest.mark.slow



@pytest.fixture(autouse=True)
def no_tokenizer_download(monkeypatch):
    """tiktoken's encodings are downloaded on first use: asking for one is a failure here, network or not."""
    tiktoken = pytest.importorskip("tiktoken")

    def refuse(name, *args, **kwargs):
        raise AssertionError(f"tiktoken.get_encoding({name!r}) was called: it downloads {name} at run time")

    monkeypatch.setattr(tiktoken, "get_encoding", refuse)
    monkeypatch.setattr(tiktoken, "encoding_for_model", refuse)


def oracle_model():
    """A mockllm whose every turn is the next oracle call of the task named in the first user message."""
    store = TaskStore([tasks_dir()])

    def outputs(messages, tools, tool_choice, config):
        first = next(m for m in messages if m.role == "user")
        task_id = re.search(r"Task id: (\S+)", first.text).group(1)
        oracle = store.get(task_id).oracle
        turn = sum(m.role == "assistant" for m in messages)
        call = oracle[turn] if turn < len(oracle) else None
        tool, args = (call.tool, call.args) if call else ("finish_episode", {})
        return ModelOutput.for_tool_call("mockllm/model", tool, dict(args))

    return get_model("mockllm/model", custom_outputs=outputs, memoize=False)


def talking_model():
    """``--model mockllm/model`` as a user gives it: no script, its default output is prose."""
    return get_model("mockllm/model", memoize=False)


def _run(task, model, tmp_path):
    [log] = inspect_eval(task, model=model, log_dir=str(tmp_path / "logs"), display="none", max_samples=2)
    assert log.status == "success", log.error
    return log


@pytest.mark.browser
def test_scripted_oracle_scores_one_on_every_domain(tmp_path):
    log = _run(inspect_tasks.suite(sample=1, run_dir=str(tmp_path / "run")), oracle_model(), tmp_path)
    domains = {s.metadata["domain"] for s in log.samples}
    assert domains == set(inspect_tasks.DOMAINS)
    for sample in log.samples:
        value = sample.scores["ewa_grader"].value
        assert value["overall"] == 1.0, (sample.id, sample.scores["ewa_grader"].explanation)
        assert value["completion"] == 1.0
        # The model played through the MCP tools without ever seeing episode_id.
        calls = [c for m in sample.messages if m.role == "assistant" for c in (m.tool_calls or [])]
        assert calls and all("episode_id" not in c.arguments for c in calls)
    metrics = log.results.scores[0].metrics
    assert metrics["overall"].value == 1.0 and metrics["completion"].value == 1.0
    assert metrics["web_only"].value == 1.0 and metrics["embodied_only"].value == 1.0
    assert metrics["geo_country"].value == 1.0
    # Every sample's episode was recorded where the grader reads it.
    assert len(list((tmp_path / "run").glob("*/final_state.json"))) == len(inspect_tasks.DOMAINS)
    # The harness's own status checks are not the model's steps: every trajectory line is a model's call
    # (or the harness's start and, for a model that stopped early, its finish).
    for trajectory in (tmp_path / "run").glob("*/trajectory.jsonl"):
        tools = [json.loads(line)["tool"] for line in trajectory.read_text().splitlines()]
        assert "episode_status" not in tools, trajectory


def test_a_model_that_only_talks_scores_zero(tmp_path):
    log = _run(inspect_tasks.navigation(sample=2, run_dir=str(tmp_path / "run")), talking_model(), tmp_path)
    assert len(log.samples) == 2
    for sample in log.samples:
        assert sample.scores["ewa_grader"].value["overall"] == 0.0
    assert log.results.scores[0].metrics["overall"].value == 0.0


def test_dataset_filters(tmp_path):
    data = inspect_tasks.ewa_dataset(["cooking"], sample=3)
    assert len(data) == 3 and all(s.metadata["domain"] == "cooking" for s in data)
    one = inspect_tasks.ewa_dataset(None, tasks="navigation-*")
    assert one and all(str(s.id).startswith("navigation-") for s in one)
    with pytest.raises(inspect_tasks.EvalError, match="difficulty"):
        inspect_tasks.ewa_dataset(["cooking"], difficulty="impossible")
    with pytest.raises(inspect_tasks.TaskStoreMissing, match="--tasks-dir DIR"):
        inspect_tasks.ewa_dataset(None, tasks_dir_=str(tmp_path))


def _metric_names(task) -> list[str]:
    from inspect_ai._util.registry import registry_info

    return [registry_info(m).name.split("/")[-1] for m in task.metrics]


def test_limit_samples_every_domain_and_tasks_carry_a_version(tmp_path):
    from ewa_mcp import __version__

    suite = inspect_tasks.suite(sample=2, run_dir=str(tmp_path / "run"))
    first = [s.metadata["domain"] for s in suite.dataset][:len(inspect_tasks.DOMAINS)]
    assert sorted(first) == sorted(inspect_tasks.DOMAINS)  # --limit 5 plays one task of each domain
    assert suite.version == __version__
    assert inspect_tasks.cooking(sample=1, run_dir=str(tmp_path / "run")).version == __version__


def test_metrics_apply_to_the_task_so_none_reads_nan(tmp_path):
    cooking = _metric_names(inspect_tasks.cooking(sample=2, run_dir=str(tmp_path / "run")))
    assert {"overall", "overall_stderr", "completion", "by_domain", "by_difficulty"} <= set(cooking)
    assert not any(name.startswith("geo_") for name in cooking)  # no geolocation sample: no geolocation metric
    geo = _metric_names(inspect_tasks.geolocation(sample=2, run_dir=str(tmp_path / "run")))
    assert {"geo_continent", "geo_street", "overall_stderr"} <= set(geo)


def test_standard_errors_and_the_per_domain_breakdown():
    from inspect_ai.scorer import SampleScore, Score

    def sample(domain, difficulty, overall):
        return SampleScore(score=Score(value={"overall": overall}), sample_id=f"{domain}-{overall}",
                           sample_metadata={"domain": domain, "difficulty": difficulty})

    scores = [sample("cooking", "easy", 1.0), sample("cooking", "hard", 0.0), sample("navigation", "easy", 1.0),
              sample("navigation", "easy", 1.0)]
    assert inspect_tasks.overall_stderr()(scores) == pytest.approx((0.25 / 4) ** 0.5)  # sd 0.5, n 4
    by_domain = inspect_tasks.overall_by_domain()(scores)
    assert by_domain == pytest.approx({"cooking": 0.5, "cooking_stderr": 0.5, "navigation": 1.0,
                                       "navigation_stderr": 0.0})
    assert inspect_tasks.overall_by_difficulty()(scores)["easy"] == 1.0
    assert inspect_tasks.overall_stderr()(scores[:1]) == 0.0  # one sample: no spread, not NaN


@pytest.mark.browser
def test_any_inspect_solver_plays_after_the_setup(tmp_path):
    """The episode is started by the task's setup, so another solver (Inspect's own generate loop) can play."""
    from inspect_ai.solver import generate

    task = inspect_tasks.navigation(tasks="navigation-boston-000", run_dir=str(tmp_path / "run"))
    [log] = inspect_eval(task, model=oracle_model(), solver=generate(tool_calls="loop"), message_limit=60,
                         log_dir=str(tmp_path / "logs"), display="none")
    assert log.status == "success", log.error
    [sample] = log.samples
    assert sample.scores["ewa_grader"].value["overall"] == 1.0, sample.scores["ewa_grader"].explanation
