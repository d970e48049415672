"""Content check for the wiki: ``python -m ewa_mcp.websites.wiki.check`` (exit 1 on any problem).

Reports malformed files, clashing slugs/titles/aliases, [[links]] to missing articles, and
landmark POIs whose article is missing or whose infobox disagrees with the POI file.
"""

from __future__ import annotations

import sys

from .landmarks import check_landmarks
from .store import check_articles, index


def main() -> int:
    problems = [str(p) for p in check_articles()] + check_landmarks()
    for problem in problems:
        print(problem)
    print(f"{len(index())} articles, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
