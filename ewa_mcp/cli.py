"""The ``ewa-mcp`` command: serve, sites, tasks, demo (and the commands later domains add)."""

from __future__ import annotations

import argparse
import json
import logging
import sys
from pathlib import Path
from typing import Any

from . import __version__
from .evaluation.heuristics import NAMES as HEURISTIC_NAMES
from .evaluation.scale import add_scale_arguments
from .pipes import quiet_on_closed_pipe


def _task_dirs_or_error(given: list[str] | None) -> list[Path] | None:
    """The task directories to use, or None after printing why there are none (the caller exits 2)."""
    from .core.paths import TaskStoreMissing, check_task_dirs, task_dirs

    dirs = [Path(p) for p in given] if given else task_dirs()  # every directory of EWA_TASKS_DIR=a:b
    try:
        check_task_dirs(dirs)
    except TaskStoreMissing as exc:
        print(f"error: {exc}", file=sys.stderr)
        return None
    return dirs


def _report_skipped(errors: list[str], limit: int = 20) -> None:
    """Name the task files a store skipped (path, reason, fix) on stderr; the good tasks are still used."""
    for err in errors[:limit]:
        print(f"warning: skipped {err}", file=sys.stderr)
    if len(errors) > limit:
        print(f"warning: {len(errors) - limit} more bad task files; `ewa-mcp tasks validate` lists them all",
              file=sys.stderr)


def serve_flags(args: argparse.Namespace) -> dict[str, object]:
    """The settings given as `serve` flags (only those given: the others keep their EWA_* variable or default)."""
    return {"transport": args.transport, "host": args.host, "port": args.port, "allow_remote": args.allow_remote,
            "mcp_token": args.token, "tasks_dir": args.tasks, "run_dir": args.run_dir, "verbose": args.verbose}


def cmd_serve(args: argparse.Namespace) -> int:
    from .core.paths import TaskStoreMissing, check_task_dirs, task_dirs
    from .settings import SettingsError, load_settings

    try:
        settings = load_settings(serve_flags(args))  # defaults < EWA_* variables < these flags
    except SettingsError as exc:
        print(f"ewa-mcp serve: error: {exc}", file=sys.stderr)
        return 2
    # stdout carries the stdio protocol: every log line goes to stderr.
    logging.basicConfig(level=logging.INFO if settings.verbose else logging.WARNING, stream=sys.stderr)
    dirs = task_dirs(settings)
    try:
        check_task_dirs(dirs)
    except TaskStoreMissing as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    from .server import ServerConfig, build_server

    # The task files are parsed on first use, not here: a client's `initialize` is answered at once.
    mcp, episodes = build_server(ServerConfig(settings=settings))
    print(f"ewa-mcp {__version__}: tasks from {', '.join(map(str, dirs))}; "
          f"episodes recorded under {episodes.run_dir}", file=sys.stderr)
    if args.bind_task:
        from .bound import BindError, BoundServer, parse_options

        if episodes.tasks.get(args.bind_task) is None:
            print(f"error: unknown task id {args.bind_task!r} for --bind-task; `ewa-mcp tasks list` shows the ids",
                  file=sys.stderr)
            return 2
        try:
            options = parse_options(args.episode_options)
        except BindError as exc:
            print(f"error: {exc}", file=sys.stderr)
            return 2
        # The agent plane of one episode of the task, started when the server starts (docs/training.md).
        mcp = BoundServer(mcp, task_id=args.bind_task, options=options, own_services=True)
        print(f"bound to one episode of {args.bind_task}: no list_tasks, start_episode or episode_id", file=sys.stderr)
    elif args.episode_options:
        print("error: --episode-options goes with --bind-task", file=sys.stderr)
        return 2
    if settings.transport == "stdio":
        mcp.run("stdio")
    else:
        from .http_serve import serve_http

        return serve_http(mcp, settings)
    return 0


def cmd_sites(args: argparse.Namespace) -> int:
    import time

    from .websites.serve import DEFAULT_PORTS, SiteServer

    ports = {name: args.base_port + i for i, name in enumerate(DEFAULT_PORTS)} if args.base_port else DEFAULT_PORTS
    server = SiteServer(host=args.host, ports=ports).start()
    for name, url in server.urls.items():
        print(f"{name:8s} {url}/")
    print("Serving; press Ctrl-C to stop.", flush=True)
    try:
        while True:
            time.sleep(3600)
    except KeyboardInterrupt:
        server.stop()
    return 0


def _add_split_arguments(p: argparse.ArgumentParser, prefix: str) -> None:
    p.add_argument("--split", choices=["test", "train", "hidden"], default="test",
                   help=prefix + "test is the public suite; train and hidden are drawn fresh with --seed and share "
                   "no instance with it (navigation and cooking; docs/training.md)")
    p.add_argument("--seed", type=int, default=0, metavar="N", help=prefix + "the seed of a train or hidden split")


def cmd_tasks(args: argparse.Namespace) -> int:
    from .core.paths import generated_tasks_dir
    from .core.taskmodel import TaskStore, export_json_schema

    if args.action == "schema":
        out = Path(args.output) if args.output else None
        text = json.dumps(export_json_schema(), indent=2) + "\n"
        if out:
            out.write_text(text, encoding="utf-8")
            print(f"wrote {out}")
        else:
            sys.stdout.write(text)
        return 0
    if args.action == "import-ewa":
        from .envs.street.taskgen.release import run_cli

        return run_cli(args.paths, args.output, args.annotations)
    if args.paths:
        print(f"error: tasks {args.action} takes no PATH arguments", file=sys.stderr)
        return 2
    if args.action == "generate":
        from .taskgen.splits import write_split

        out = Path(args.output) if args.output else generated_tasks_dir()
        if args.split != "test" and not args.output:
            print(f"error: --split {args.split} needs -o DIR: the default directory holds the public test split",
                  file=sys.stderr)
            return 2
        try:
            generated = write_split(out, args.split, args.seed, domains=args.domain)
        except ValueError as exc:
            print(f"error: {exc}", file=sys.stderr)
            return 2
        print(json.dumps(generated))
        print(f"wrote {out}" + ("" if args.output or out != Path.cwd() / "tasks" else
                                "; use it with --tasks-dir ./tasks or EWA_TASKS_DIR=./tasks"), file=sys.stderr)
        return 0
    roots = _task_dirs_or_error(args.tasks)
    if roots is None:
        return 2
    store = TaskStore(roots)
    tasks = store.all()
    if not tasks and args.action == "list":
        for err in store.errors[:10]:
            print(f"error: {err}", file=sys.stderr)
        print(f"error: no valid task in {', '.join(map(str, roots))}; fix the files named above or "
              "regenerate them with `ewa-mcp tasks generate -o DIR`", file=sys.stderr)
        return 2
    if args.action == "validate":
        from .taskrefs import ReferenceChecker, street_dirs_of

        for err in store.errors:
            print(f"error: {err}", file=sys.stderr)
        # The schema passed; now every kitchen, city, node, recipe, product and standpoint must exist.
        checker = ReferenceChecker(street_dirs_of(roots))
        missing = 0
        for t in sorted(tasks, key=lambda t: t.id):
            for problem in checker.missing(t):
                missing += 1
                print(f"error: {store.sources.get(t.id, '?')}: task {t.id}: {problem}; fix the reference or "
                      "regenerate the suite (`ewa-mcp tasks generate`)", file=sys.stderr)
        counts: dict[str, int] = {}
        for t in tasks:
            counts[t.domain] = counts.get(t.domain, 0) + 1
        print(json.dumps({"tasks": len(tasks), "by_domain": counts, "errors": len(store.errors) + missing,
                          "bad_files": len(store.errors), "missing_references": missing}))
        return 1 if store.errors or missing else 0
    _report_skipped(store.errors)
    for t in sorted(tasks, key=lambda t: t.id):
        if args.domain and t.domain not in args.domain:
            continue
        print(f"{t.id}\t{t.domain}\t{t.intent}")
    return 0


def _split_task_dirs(args: argparse.Namespace) -> list[Path] | None:
    """eval --split train|hidden --seed N: the split's tasks, generated into a directory that lives as long as
    this process (worker processes read it too)."""
    import atexit
    import shutil
    import tempfile

    from .taskgen.splits import write_split

    if args.tasks_dir:
        print("error: --split draws its own tasks; leave out --tasks-dir (or generate the split with "
              "`ewa-mcp tasks generate --split ... -o DIR` and pass --tasks-dir DIR)", file=sys.stderr)
        return None
    out = Path(tempfile.mkdtemp(prefix=f"ewa-{args.split}{args.seed}-"))
    atexit.register(shutil.rmtree, out, True)
    try:
        counts = write_split(out, args.split, args.seed, domains=args.domain)
    except ValueError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return None
    print(f"{args.split} split, seed {args.seed}: {json.dumps(counts)} tasks", file=sys.stderr)
    return [out]


def cmd_eval(args: argparse.Namespace) -> int:
    from .evaluation.agents import NoopAgent, OracleAgent, RandomAgent, ReplayAgent, ReplayError, load_replay
    from .evaluation.heuristics import heuristic_agent
    from .evaluation.runner import EvalError, play_from_args, run_dir_from, select_tasks, task_dirs_from
    from .graders import grade_run, render_report
    from .core.taskmodel import TaskStore

    if _task_dirs_or_error(args.tasks_dir) is None:
        return 2
    task_dirs = task_dirs_from(args.tasks_dir)
    if args.split != "test" or args.seed:
        split_dirs = _split_task_dirs(args)
        if split_dirs is None:
            return 2
        task_dirs = split_dirs
    try:
        if args.agent == "replay":
            if not args.replay:
                raise EvalError("--agent replay needs a FILE: ewa-mcp eval --agent replay path/to/replay.jsonl")
            agent: Any = ReplayAgent(load_replay(Path(args.replay)))
        elif args.agent in HEURISTIC_NAMES:
            agent = heuristic_agent(args.agent)
        else:
            agent = {"oracle": OracleAgent, "noop": NoopAgent, "random": RandomAgent}[args.agent]()
        if args.observation:
            # start_episode's options (playing.play_episode reads them from the agent, which travels to workers)
            agent.episode_options = {"observation": args.observation}
        patterns = args.tasks
        if args.agent == "replay" and not patterns:
            patterns = sorted(agent.calls)  # a replay runs the tasks it has calls for
        store = TaskStore(task_dirs)
        try:
            tasks = select_tasks(store, patterns, args.sample, args.domain, args.difficulty)
        finally:
            _report_skipped(store.errors)
    except (EvalError, ReplayError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    from .evaluation.workers import EvalInterrupted

    # A refused tool call is part of the episode's record; the SDK's INFO line for each (as the workers do).
    logging.getLogger("mcp").setLevel(logging.WARNING)
    run_dir = run_dir_from(args.run_dir)
    try:
        summary = play_from_args(tasks, agent, args, run_dir=run_dir, task_dirs=task_dirs, announce=lambda scale: print(
            f"{agent.name}: {len(tasks)} tasks, {scale.describe()}, {args.transport}; recording to {run_dir}",
            file=sys.stderr))
    except EvalError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    except EvalInterrupted as exc:
        print(f"\neval: stopped by {exc}; the workers and their browsers are stopped, and {run_dir} holds only "
              "the episodes accepted before it", file=sys.stderr)
        return 128 + exc.signum
    print(render_report(grade_run(run_dir), fmt=args.format))
    return 1 if any(o.failure for o in summary.outcomes) else 0


def cmd_play(args: argparse.Namespace) -> int:
    from .evaluation.human import HumanAgent
    from .evaluation.runner import play, run_dir_from, task_dirs_from
    from .graders import grade_run, render_report
    from .core.taskmodel import TaskStore

    if _task_dirs_or_error(args.tasks_dir) is None:
        return 2
    task_dirs = task_dirs_from(args.tasks_dir)
    task = TaskStore(task_dirs).get(args.task_id)
    if task is None:
        print(f"error: unknown task id {args.task_id!r}; see `ewa-mcp tasks list`", file=sys.stderr)
        return 2
    run_dir = run_dir_from(args.run_dir, prefix="human-")
    outcome = play([task], HumanAgent(), run_dir=run_dir, task_dirs=task_dirs, progress=False).outcomes[0]
    if outcome.failure:
        return 1
    print(f"recorded: {run_dir / (outcome.episode_id or '')}")
    print(render_report(grade_run(run_dir), fmt="table"))
    return 0


def cmd_demo(args: argparse.Namespace) -> int:
    from .demo import run_demo

    return run_demo()


def cmd_export_sft(args: argparse.Namespace) -> int:
    import anyio

    from .sft import ExportError, export_run

    out = Path(args.output)
    try:
        summary = anyio.run(lambda: export_run(Path(args.run_dir), out, include_failed=args.all))
    except ExportError as exc:
        print(f"ewa-mcp export-sft: error: {exc}", file=sys.stderr)
        return 2
    print(f"{summary.exported} episode(s) written to {out}; {summary.skipped_unsuccessful} unsuccessful left out"
          + ("" if args.all else " (--all keeps them)"), file=sys.stderr)
    for why in summary.not_replayable:
        print(f"left out, did not replay as recorded: {why}", file=sys.stderr)
    return 0


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="ewa-mcp", description="Embodied web agent benchmark as an MCP server.")
    parser.add_argument("--version", action="version", version=f"ewa-mcp {__version__}")
    sub = parser.add_subparsers(dest="command", required=True)

    # serve's flags are settings (ewa_mcp/settings.py): each left out keeps its EWA_* variable, else its default.
    # Their values are checked by the settings, which name the flag and the fix.
    p = sub.add_parser("serve", help="run the MCP server (stdio or streamable HTTP)",
                       epilog="Each flag overrides its EWA_* variable (EWA_TRANSPORT, EWA_HOST, EWA_PORT, ...); "
                       "docs/architecture.md, 'Settings', lists them all.")
    p.add_argument("--transport", help="stdio or http (default: stdio)")
    p.add_argument("--host", help="address to listen on (default: 127.0.0.1)")
    p.add_argument("--port", help="port to listen on (default: 8765)")
    p.add_argument("--allow-remote", action="store_const", const=True, default=None,
                   help="allow a non-loopback --host; every request then needs a bearer token")
    p.add_argument("--token", help="bearer token every HTTP request must carry (default: EWA_MCP_TOKEN; past "
                   "loopback one is generated and printed when neither is set)")
    p.add_argument("--tasks-dir", dest="tasks", action="append", metavar="DIR", help="task directory (repeatable; "
                   "default: EWA_TASKS_DIR, else the bundled suites)")
    p.add_argument("--tasks", dest="tasks", action="append", help=argparse.SUPPRESS)  # the 0.x spelling
    p.add_argument("--run-dir", metavar="DIR", help="where episodes are recorded (default: runs/<new id>)")
    p.add_argument("-v", "--verbose", action="store_const", const=True, default=None)
    p.add_argument("--bind-task", metavar="TASK", help="serve one episode of TASK, started at once: its tools "
                   "without episode_id, no list_tasks or start_episode (docs/training.md)")
    p.add_argument("--episode-options", metavar="JSON", help="with --bind-task: start_episode options as JSON, "
                   "e.g. '{\"observation\": \"both\"}'")
    p.set_defaults(func=cmd_serve)

    p = sub.add_parser("sites", help="serve the five embedded web sites for people to browse")
    p.add_argument("--host", default="127.0.0.1")
    p.add_argument("--base-port", type=int, default=0, help="first port (default: 8701..8705)")
    p.set_defaults(func=cmd_sites)

    p = sub.add_parser("tasks", help="list, validate, generate or import task suites; export the task JSON Schema")
    p.add_argument("action", choices=["list", "validate", "generate", "schema", "import-ewa"])
    p.add_argument("paths", nargs="*", metavar="PATH", help="import-ewa: the paper's navi_env_merge_v1.json (or "
                   "any file of its environments)")
    p.add_argument("--tasks-dir", dest="tasks", action="append", metavar="DIR", help="task directory (repeatable)")
    p.add_argument("--tasks", dest="tasks", action="append", help=argparse.SUPPRESS)  # the 0.x spelling
    p.add_argument("--domain", action="append", help="restrict to a domain (repeatable)")
    p.add_argument("-o", "--output", "--out", dest="output", help="output file (schema) or directory (generate; "
                   "import-ewa, default ~/.local/share/ewa-mcp/imported)")
    p.add_argument("--annotations", metavar="FILE", help="import-ewa: the release's annotation file (default: the "
                   "navi_anno*.json beside PATH; 'none' to ignore it)")
    _add_split_arguments(p, "generate: ")
    p.set_defaults(func=cmd_tasks)

    p = sub.add_parser("eval", help="run an agent over tasks through the MCP server, then grade the run")
    p.add_argument("--agent", choices=["oracle", "noop", "random", "replay", *HEURISTIC_NAMES], default="oracle",
                   help="oracle, noop, random, replay FILE, or a heuristic agent (no model; docs/verified.md)")
    p.add_argument("replay", nargs="?", metavar="FILE", help="replay: a JSONL of tool calls or a run directory")
    p.add_argument("--tasks", action="append", metavar="GLOB", help="task id glob (repeatable)")
    p.add_argument("--domain", action="append", help="restrict to a domain (repeatable)")
    p.add_argument("--difficulty", action="append", choices=["easy", "medium", "hard"],
                   help="restrict to a difficulty (repeatable)")
    p.add_argument("--sample", type=int, metavar="N", help="N tasks per domain, chosen deterministically")
    p.add_argument("--observation", choices=["text", "vision", "both"],
                   help="the episodes' observation mode (start_episode option; default: the server's, text)")
    _add_split_arguments(p, "")
    add_scale_arguments(p)
    p.add_argument("--transport", choices=["inprocess", "stdio", "http"], default="inprocess")
    p.add_argument("--run-dir", metavar="DIR")
    p.add_argument("--tasks-dir", action="append", metavar="DIR", help="task directory (default: tasks/)")
    p.add_argument("--format", choices=["table", "json", "markdown"], default="table")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    p.set_defaults(func=cmd_eval)

    p = sub.add_parser("play", help="play a task yourself at a terminal prompt (recorded and graded)")
    p.add_argument("task_id")
    p.add_argument("--run-dir", metavar="DIR")
    p.add_argument("--tasks-dir", action="append", metavar="DIR")
    p.set_defaults(func=cmd_play)

    p = sub.add_parser("export-sft", help="a run's episodes as chat-format JSONL (messages + tools) for "
                       "supervised fine-tuning (docs/training.md)")
    p.add_argument("run_dir", metavar="RUN_DIR")
    p.add_argument("-o", "--output", required=True, metavar="FILE", help="the JSONL file to write")
    p.add_argument("--all", action="store_true", help="export failed episodes too (default: successful only)")
    p.set_defaults(func=cmd_export_sft)

    p = sub.add_parser("demo", help="start the server in-process, play one episode, print what happened")
    p.set_defaults(func=cmd_demo)
    return parser


@quiet_on_closed_pipe
def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    from .settings import SettingsError

    try:
        return int(args.func(args) or 0)
    except SettingsError as exc:  # an EWA_* variable with a bad value: the message names it and the fix
        print(f"ewa-mcp {args.command}: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        return 130


if __name__ == "__main__":
    sys.exit(main())
