"""Every setting of ewa-mcp in one typed object: defaults < ``EWA_*`` environment variables < CLI flags.

``load_settings(flags)`` is called once, by the CLI (or ``build_server`` for in-process servers), and the
result is handed down: server -> ``Services`` -> environments (``services.settings``). No other module
reads these variables. docs/architecture.md ("Settings") lists every setting with its variable and flag.

A value that does not fit its setting raises ``SettingsError`` naming the variable or flag it came
from and how to fix it, e.g. ``EWA_PORT='http' is not valid: ... set EWA_PORT to a port number 1-65535``.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, SecretStr, ValidationError, field_validator
from pydantic_settings import BaseSettings, NoDecode, SettingsConfigDict
from pydantic_settings import SettingsError as _SourceError


# The browser's options (ewa_mcp/envs/browser/README.md, "Configuration"): the ``browser`` setting, ``EWA_BROWSER__HEADLESS=false``.
class BrowserConfig(BaseModel):
    model_config = ConfigDict(extra="forbid")

    executable_path: str | None = None
    headless: bool = True
    allow_origins: list[str] = Field(default_factory=list, description="extra http(s) origins the browser may reach")
    viewport_width: int = Field(1280, ge=320, le=3840)
    viewport_height: int = Field(720, ge=240, le=2160)
    max_chars: int = Field(24_000, ge=500, le=500_000, description="accessibility tree budget per observation")
    viewport_only: bool = False
    action_timeout_s: float = Field(5.0, gt=0, le=120)
    navigation_timeout_s: float = Field(15.0, gt=0, le=300)
    settle_timeout_s: float = Field(5.0, gt=0, le=120)
    # Memory (ewa_mcp/envs/browser/README.md, "Memory"): the warm pool falls back to pool_keep_idle contexts once they have been
    # idle pool_idle_s; a page quiet for idle_gc_s gets one full garbage collection (0 turns that off).
    pool_keep_idle: int = Field(2, ge=0, le=8)
    pool_idle_s: float = Field(30.0, gt=0, le=86_400)
    idle_gc_s: float = Field(10.0, ge=0, le=3_600)


ENV_PREFIX = "EWA_"

# The CLI flag of each setting that has one (``ewa-mcp serve``); the others are set by their variable only.
FLAGS: dict[str, str] = {
    "tasks_dir": "--tasks-dir",
    "run_dir": "--run-dir",
    "transport": "--transport",
    "host": "--host",
    "port": "--port",
    "allow_remote": "--allow-remote",
    "mcp_token": "--token",
    "verbose": "--verbose",
}

# How to fix a bad value of each setting (the generic pydantic message says what was wrong).
FIXES: dict[str, str] = {
    "port": "a port number 1-65535",
    "transport": "stdio or http",
    "kitchen_backend": "sim or ai2thor",
    "allow_remote": "true or false",
    "verbose": "true or false",
    "browser": 'a JSON object of browser options, e.g. {"headless": false}, or set one option with '
               "EWA_BROWSER__<OPTION> (EWA_BROWSER__HEADLESS=false)",
    "site_ports": 'a JSON object of site name -> port, e.g. {"shop": 9001}',
    "allowed_hosts": "host names or addresses separated by commas, e.g. ewa.example.org,10.0.0.5",
    "max_episodes": "a whole number of episodes, 0 for no cap",
    "max_episodes_per_client": "a whole number of episodes, 0 for no cap",
    "episode_idle_s": "a number of seconds, 0 to never end idle episodes",
}

PathList = Annotated[list[Path], NoDecode]  # "dir1:dir2" (os.pathsep), not JSON
HostList = Annotated[list[str], NoDecode]  # "name1,name2" (IPv6 addresses hold colons), not JSON


class SettingsError(ValueError):
    """A setting with a bad value; the message names the variable or flag and the fix."""


class Settings(BaseSettings):
    """The process's settings. Field ``x`` is read from ``EWA_X``; see docs/architecture.md, "Settings"."""

    model_config = SettingsConfigDict(env_prefix=ENV_PREFIX, env_nested_delimiter="__", extra="forbid",
                                      validate_default=True)

    # -- data and records
    tasks_dir: PathList = Field(default_factory=list, description="task suite directories to serve (default: the "
                                "installed package's suites, else the checkout's tasks/)")
    runs_dir: Path | None = Field(None, description="where new runs are recorded (default: ./runs)")
    run_dir: Path | None = Field(None, description="the one run directory `serve` records into (default: "
                                 "<runs_dir>/<new run id>)")
    import_dir: Path | None = Field(None, description="`tasks import-ewa` output (default: "
                                    "$XDG_DATA_HOME/ewa-mcp/imported)")
    street_data: PathList = Field(default_factory=list, description="extra directories of street graph files")
    geo_font_dirs: PathList = Field(default_factory=list, description="extra font directories for geo signs")

    # -- serving (`ewa-mcp serve`)
    transport: Literal["stdio", "http"] = "stdio"
    host: str = Field("127.0.0.1", min_length=1)
    port: int = Field(8765, ge=1, le=65535)
    allow_remote: bool = False
    mcp_token: SecretStr | None = Field(None, description="bearer token HTTP requests must carry")
    allowed_hosts: HostList = Field(default_factory=list, description="more Host names the HTTP server answers "
                                    "to (comma-separated), e.g. a DNS name or proxy in front of it")
    verbose: bool = False

    # -- admission: what the server holds open at once (ewa_mcp/core/episodes.py)
    max_episodes: int = Field(256, ge=0, description="open episodes the server admits at once (0: no cap)")
    max_episodes_per_client: int = Field(0, ge=0, description="open episodes one MCP session may hold at once "
                                         "(0: no cap)")
    episode_idle_s: float = Field(1800.0, ge=0, description="an episode with no call for this long is ended as "
                                  "aborted and its environments released (0: never)")

    # -- environments
    chromium: str | None = Field(None, description="the Chromium/Chrome executable (default: discovered)")
    browser: BrowserConfig = Field(default_factory=BrowserConfig)
    site_ports: dict[str, int] | None = Field(None, description="ports of the embedded web sites (default: 8701..)")
    site_data_dir: Path | None = Field(None, description="where the web sites keep their databases "
                                       "(default: a temporary directory)")
    kitchen_backend: Literal["sim", "ai2thor"] = "sim"
    ai2thor_executable: str | None = Field(None, description="an AI2-THOR Unity build, or 'standin'")

    @field_validator("tasks_dir", "street_data", "geo_font_dirs", mode="before")
    @classmethod
    def _split_paths(cls, value: Any) -> Any:
        if isinstance(value, str):
            return [Path(p) for p in value.split(os.pathsep) if p.strip()]
        if isinstance(value, os.PathLike):
            return [Path(value)]
        return value

    @field_validator("allowed_hosts", mode="before")
    @classmethod
    def _split_hosts(cls, value: Any) -> Any:
        if isinstance(value, str):
            return [h.strip() for h in value.split(",") if h.strip()]
        return value

    @field_validator("allowed_hosts")
    @classmethod
    def _plain_hosts(cls, value: list[str]) -> list[str]:
        for host in value:
            if any(c.isspace() or c in "/@?#" for c in host) or not host.isascii():
                raise ValueError(f"{host[:100]!r} is not a host name or address")
        return value

    @field_validator("kitchen_backend", "transport", mode="before")
    @classmethod
    def _lower(cls, value: Any) -> Any:
        return value.strip().lower() if isinstance(value, str) else value

    @field_validator("chromium", "ai2thor_executable", "mcp_token", mode="before")
    @classmethod
    def _empty_is_unset(cls, value: Any) -> Any:
        return None if isinstance(value, str) and not value.strip() else value

    def chromium_path(self) -> str | None:
        """The browser to launch: the browser options' executable_path, else EWA_CHROMIUM."""
        return self.browser.executable_path or self.chromium

    def token(self) -> str | None:
        return self.mcp_token.get_secret_value() if self.mcp_token is not None else None


def env_name(field: str) -> str:
    return ENV_PREFIX + field.upper()


# How a `serve` is reached: a process that starts its own loopback server sets these with flags (or not at all:
# no token on loopback) and must not inherit the caller's, which may describe another server.
SERVE_ONLY = ("transport", "host", "port", "allow_remote", "mcp_token", "run_dir", "allowed_hosts")


def child_server_env(environ: Mapping[str, str] | None = None) -> dict[str, str]:
    """The environment for an `ewa-mcp serve` child started on loopback by this process (eval, Inspect):
    the caller's, less the variables of SERVE_ONLY. The other settings (browser, tasks, ...) are passed on."""
    dropped = {env_name(f) for f in SERVE_ONLY}
    return {k: v for k, v in (os.environ if environ is None else environ).items() if k.upper() not in dropped}


def _source(field: str, flags: Mapping[str, Any]) -> str:
    if field in flags and field in FLAGS:
        return FLAGS[field]
    if field in flags:
        return f"the {field} setting"
    return env_name(field)


def _shown(value: Any, field: str) -> str:
    if field == "mcp_token":
        return "(hidden)"
    text = repr(value)
    return text if len(text) <= 200 else text[:200] + "…"


def load_settings(flags: Mapping[str, Any] | None = None) -> Settings:
    """The settings from the defaults, the ``EWA_*`` variables and ``flags`` (only the flags given; they win).

    Raises SettingsError naming the variable or flag of each bad value and the fix."""
    flags = {k: v for k, v in (flags or {}).items() if v is not None}
    try:
        return Settings(**flags)
    except ValidationError as exc:
        problems = []
        for err in exc.errors():
            loc = [str(p) for p in err.get("loc", ())]
            field = loc[0] if loc else "?"
            source = _source(field, flags)
            if field not in Settings.model_fields:
                problems.append(f"{source}: unknown setting; see docs/architecture.md, \"Settings\"")
                continue
            where = source + ("__" + "__".join(p.upper() for p in loc[1:]) if len(loc) > 1 and
                              source.startswith(ENV_PREFIX) else ("." + ".".join(loc[1:]) if len(loc) > 1 else ""))
            fix = FIXES.get(field) if len(loc) == 1 else None
            how = f"; set {where} to {fix}" if fix else f"; fix or unset {where}"
            problems.append(f"{where}={_shown(err.get('input'), field)} is not valid: {err.get('msg')}{how}")
        raise SettingsError("; ".join(problems)) from None
    except _SourceError as exc:  # a variable that should hold JSON does not
        text = str(exc)
        field = next((f for f in Settings.model_fields if f'"{f}"' in text), "")
        name = env_name(field) if field else "an EWA_* variable"
        fix = FIXES.get(field, "valid JSON")
        raise SettingsError(f"{name} is not valid: {text[:200]}; set {name} to {fix}") from None
