"""The one settings object: defaults < EWA_* variables < CLI flags, handed down to the environments,
and bad values refused with the variable or flag named and the fix."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from ewa_mcp import cli
from ewa_mcp.core.paths import REPO_ROOT, runs_dir, task_dirs
from ewa_mcp.server import ServerConfig, build_server
from ewa_mcp.settings import Settings, SettingsError, child_server_env, load_settings


@pytest.fixture(autouse=True)
def clean_env(monkeypatch):
    for name in [n for n in __import__("os").environ if n.startswith("EWA_")]:
        monkeypatch.delenv(name)


def serve_settings(*argv: str) -> Settings:
    """The settings `ewa-mcp serve ARGV` would run with (the real parser, the real flag mapping)."""
    return load_settings(cli.serve_flags(cli.build_parser().parse_args(["serve", *argv])))


def test_defaults_when_nothing_is_set():
    s = serve_settings()
    assert (s.transport, s.host, s.port, s.allow_remote, s.token(), s.kitchen_backend) == \
        ("stdio", "127.0.0.1", 8765, False, None, "sim")
    assert s.browser.headless is True and s.tasks_dir == [] and s.chromium_path() is None


def test_a_variable_beats_the_default_and_a_flag_beats_the_variable(monkeypatch, tmp_path):
    monkeypatch.setenv("EWA_PORT", "9100")
    monkeypatch.setenv("EWA_HOST", "localhost")
    monkeypatch.setenv("EWA_MCP_TOKEN", "from-the-environment-0123")
    monkeypatch.setenv("EWA_TASKS_DIR", f"{tmp_path / 'a'}:{tmp_path / 'b'}")
    s = serve_settings()
    assert (s.port, s.host, s.token()) == (9100, "localhost", "from-the-environment-0123")
    assert s.tasks_dir == [tmp_path / "a", tmp_path / "b"]
    s = serve_settings("--port", "9200", "--token", "from-the-flag-0123456789", "--tasks-dir", str(tmp_path / "c"))
    assert (s.port, s.host, s.token()) == (9200, "localhost", "from-the-flag-0123456789")  # host: no flag given
    assert s.tasks_dir == [tmp_path / "c"]
    assert task_dirs(s) == [tmp_path / "c"]


def test_a_flag_overrides_a_bad_variable(monkeypatch):
    monkeypatch.setenv("EWA_PORT", "not-a-port")
    assert serve_settings("--port", "9300").port == 9300
    with pytest.raises(SettingsError, match="EWA_PORT"):
        serve_settings()


def test_switch_flags_only_count_when_given(monkeypatch):
    monkeypatch.setenv("EWA_ALLOW_REMOTE", "true")
    assert serve_settings().allow_remote is True  # no --allow-remote: the variable stands
    monkeypatch.setenv("EWA_ALLOW_REMOTE", "false")
    assert serve_settings("--allow-remote").allow_remote is True


def test_nested_browser_options_and_chromium(monkeypatch):
    monkeypatch.setenv("EWA_BROWSER__HEADLESS", "false")
    monkeypatch.setenv("EWA_BROWSER__MAX_CHARS", "8000")
    monkeypatch.setenv("EWA_CHROMIUM", "/opt/chrome/chrome")
    s = load_settings()
    assert s.browser.headless is False and s.browser.max_chars == 8000
    assert s.chromium_path() == "/opt/chrome/chrome"
    s = load_settings({"browser": {"executable_path": "/usr/bin/chromium"}})  # the option wins over EWA_CHROMIUM
    assert s.chromium_path() == "/usr/bin/chromium"
    assert s.browser.headless is False and s.browser.max_chars == 8000  # merged with the variables' options


def test_runs_dir_setting(monkeypatch, tmp_path):
    assert runs_dir(load_settings()) == Path.cwd() / "runs"
    monkeypatch.setenv("EWA_RUNS_DIR", str(tmp_path / "runs"))
    assert runs_dir() == tmp_path / "runs"


@pytest.mark.parametrize("env, flags, expected", [
    ({"EWA_PORT": "http"}, {}, r"EWA_PORT='http' is not valid: .*integer.*; set EWA_PORT to a port number 1-65535"),
    ({}, {"port": "70000"}, r"--port='70000' is not valid: .*less than or equal to 65535.*set --port to a port"),
    ({"EWA_TRANSPORT": "carrier-pigeon"}, {}, r"EWA_TRANSPORT='carrier-pigeon' .*set EWA_TRANSPORT to stdio or http"),
    ({}, {"transport": "sse"}, r"--transport='sse' is not valid.*stdio or http"),
    ({"EWA_KITCHEN_BACKEND": "unity"}, {}, r"EWA_KITCHEN_BACKEND='unity' .*set EWA_KITCHEN_BACKEND to sim or ai2thor"),
    ({"EWA_ALLOW_REMOTE": "perhaps"}, {}, r"EWA_ALLOW_REMOTE='perhaps' .*true or false"),
    ({"EWA_BROWSER__VIEWPORT_WIDTH": "10"}, {}, r"EWA_BROWSER__VIEWPORT_WIDTH='10' .*greater than or equal to 320"),
    ({"EWA_BROWSER": "{not json"}, {}, r"EWA_BROWSER is not valid: .*set EWA_BROWSER to a JSON object"),
])
def test_bad_values_name_the_variable_or_flag_and_the_fix(monkeypatch, env, flags, expected):
    for name, value in env.items():
        monkeypatch.setenv(name, value)
    with pytest.raises(SettingsError) as info:
        load_settings(flags)
    assert re.search(expected, str(info.value)), str(info.value)


def test_every_problem_is_reported_at_once_and_long_values_are_cut(monkeypatch):
    monkeypatch.setenv("EWA_PORT", "x" * 5000)
    monkeypatch.setenv("EWA_KITCHEN_BACKEND", "unity")
    message = str(pytest.raises(SettingsError, load_settings).value)
    assert "EWA_PORT" in message and "EWA_KITCHEN_BACKEND" in message and len(message) < 1000


def test_a_token_is_never_echoed(monkeypatch):
    with pytest.raises(SettingsError) as info:
        load_settings({"mcp_token": ["secret-secret-secret"]})
    assert "secret-secret" not in str(info.value) and "--token" in str(info.value)


def test_cli_refuses_a_bad_flag_or_variable_with_exit_2(monkeypatch, capsys):
    assert cli.main(["serve", "--transport", "http", "--port", "eighty"]) == 2
    err = capsys.readouterr().err
    assert "--port='eighty' is not valid" in err and "port number 1-65535" in err
    monkeypatch.setenv("EWA_TRANSPORT", "tcp")
    assert cli.main(["serve"]) == 2
    assert "EWA_TRANSPORT='tcp'" in capsys.readouterr().err
    # Commands other than serve read the settings too (tasks_dir, runs_dir): same clear error, no traceback.
    monkeypatch.setenv("EWA_KITCHEN_BACKEND", "unity")
    assert cli.main(["tasks", "list"]) == 2
    assert "ewa-mcp tasks: error: " in (err := capsys.readouterr().err) and "EWA_KITCHEN_BACKEND='unity'" in err


def test_the_server_hands_its_settings_down_to_the_environments(tmp_path):
    settings = load_settings({"kitchen_backend": "ai2thor", "ai2thor_executable": "standin",
                              "site_ports": {"shop": 9999}, "tasks_dir": [str(tmp_path)]})
    mcp, episodes = build_server(ServerConfig(settings=settings, run_dir=tmp_path / "run"))
    assert episodes.services.settings.kitchen_backend == "ai2thor"
    assert episodes.services.settings.site_ports == {"shop": 9999}
    assert episodes.services.settings.run_dir == tmp_path / "run" and episodes.run_dir == tmp_path / "run"
    assert episodes.services.emit_event == episodes.emit_event
    assert episodes.tasks.roots == [tmp_path]


def test_build_server_reads_the_variables_once(monkeypatch, tmp_path):
    monkeypatch.setenv("EWA_KITCHEN_BACKEND", "ai2thor")
    _, episodes = build_server(ServerConfig(task_dirs=[tmp_path], run_dir=tmp_path / "run"))
    monkeypatch.setenv("EWA_KITCHEN_BACKEND", "sim")
    assert episodes.services.settings.kitchen_backend == "ai2thor"


def test_no_module_reads_an_ewa_variable_but_the_settings():
    """The variable names live in ewa_mcp/settings.py only; every other module gets the settings."""
    readers = []
    for path in sorted((REPO_ROOT / "ewa_mcp").rglob("*.py")) + sorted((REPO_ROOT / "websites").rglob("*.py")):
        text = path.read_text(encoding="utf-8")
        if re.search(r"""(environ(\.get)?\(|getenv\(|environ\[)\s*["']EWA_""", text):
            readers.append(str(path.relative_to(REPO_ROOT)))
    assert readers == [], f"read EWA_* through ewa_mcp.settings.load_settings, not os.environ: {readers}"


def test_a_child_server_does_not_inherit_how_the_callers_server_is_reached():
    environ = {"EWA_TRANSPORT": "http", "EWA_HOST": "0.0.0.0", "EWA_PORT": "80", "EWA_ALLOW_REMOTE": "1",
               "EWA_MCP_TOKEN": "t" * 20, "EWA_RUN_DIR": "/elsewhere", "EWA_KITCHEN_BACKEND": "ai2thor",
               "EWA_BROWSER__HEADLESS": "false", "PATH": "/usr/bin"}
    child = child_server_env(environ)
    assert child == {"EWA_KITCHEN_BACKEND": "ai2thor", "EWA_BROWSER__HEADLESS": "false", "PATH": "/usr/bin"}
