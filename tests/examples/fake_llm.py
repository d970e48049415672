"""A local HTTP server that speaks the Anthropic Messages and OpenAI Chat Completions wire formats and
answers with scripted tool calls, so the real SDKs' code paths run in tests without a network."""

from __future__ import annotations

import json
import socket
import threading
import time
from typing import Any

import uvicorn
from starlette.applications import Starlette
from starlette.requests import Request
from starlette.responses import JSONResponse
from starlette.routing import Route


class ScriptedModel:
    def __init__(self, script: list[tuple[str, dict[str, Any]]]):
        self.script = list(script)
        self.requests: list[dict[str, Any]] = []

    def _next(self) -> tuple[str, dict[str, Any]] | None:
        return self.script.pop(0) if self.script else None

    async def anthropic(self, request: Request) -> JSONResponse:
        body = await request.json()
        self.requests.append(body)
        step = self._next()
        n = len(self.requests)
        content = ([{"type": "tool_use", "id": f"toolu_{n}", "name": step[0], "input": step[1]}] if step
                   else [{"type": "text", "text": "I am done."}])
        return JSONResponse({"id": f"msg_{n}", "type": "message", "role": "assistant", "model": body["model"],
                             "content": content, "stop_reason": "tool_use" if step else "end_turn",
                             "stop_sequence": None, "usage": {"input_tokens": 10, "output_tokens": 5}})

    async def openai(self, request: Request) -> JSONResponse:
        body = await request.json()
        self.requests.append(body)
        step = self._next()
        n = len(self.requests)
        message: dict[str, Any] = {"role": "assistant", "content": None if step else "I am done."}
        if step:
            message["tool_calls"] = [{"id": f"call_{n}", "type": "function",
                                      "function": {"name": step[0], "arguments": json.dumps(step[1])}}]
        return JSONResponse({"id": f"chatcmpl-{n}", "object": "chat.completion", "created": int(time.time()),
                             "model": body["model"], "choices": [{"index": 0, "message": message,
                                                                  "finish_reason": "tool_calls" if step else "stop"}],
                             "usage": {"prompt_tokens": 10, "completion_tokens": 5, "total_tokens": 15}})


class FakeLLMServer:
    def __init__(self, model: ScriptedModel):
        self.model = model
        app = Starlette(routes=[Route("/v1/messages", model.anthropic, methods=["POST"]),
                                Route("/v1/chat/completions", model.openai, methods=["POST"])])
        with socket.socket() as s:
            s.bind(("127.0.0.1", 0))
            self.port = s.getsockname()[1]
        self.server = uvicorn.Server(uvicorn.Config(app, host="127.0.0.1", port=self.port, log_level="warning"))
        self.thread = threading.Thread(target=self.server.run, daemon=True)

    def __enter__(self) -> "FakeLLMServer":
        self.thread.start()
        while not self.server.started:
            time.sleep(0.01)
        return self

    def __exit__(self, *exc: Any) -> None:
        self.server.should_exit = True
        self.thread.join(timeout=10)

    @property
    def url(self) -> str:
        return f"http://127.0.0.1:{self.port}"
