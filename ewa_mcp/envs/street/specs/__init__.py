"""Hand-written, compact city specifications the generator turns into street graphs.

Each module exposes ``build() -> CitySpec``. See ``ewa_mcp/envs/street/README.md`` for how positions were fixed."""
