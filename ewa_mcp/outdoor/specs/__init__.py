"""Hand-written, compact city specifications the generator turns into street graphs.

Each module exposes ``build() -> CitySpec``. See ``docs/outdoor.md`` for how positions were fixed."""
