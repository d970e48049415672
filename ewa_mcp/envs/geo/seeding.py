"""Deterministic randomness: every scene detail is drawn from a generator seeded by a stable
hash of its context, so a view renders identically in every process and on every machine."""

from __future__ import annotations

import hashlib
import random


def rng_for(*parts: object) -> random.Random:
    digest = hashlib.sha256("|".join(str(p) for p in parts).encode("utf-8")).digest()
    return random.Random(int.from_bytes(digest[:8], "big"))
