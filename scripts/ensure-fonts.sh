#!/usr/bin/env bash
# The fonts street and geolocation views draw signs with ship inside the package
# (ewa_mcp/street_drawing/fonts/, refreshed by scripts/make-fonts.py); nothing is installed on the system and no
# system font is read. This only checks that the checkout has them.
set -uo pipefail
dir="$(dirname "$0")/../ewa_mcp/street_drawing/fonts"
if [ ! -f "$dir/DejaVuSans-Bold.ttf" ] || [ ! -f "$dir/NotoSansCJKjp-Bold-subset.otf" ]; then
  echo "fonts: $dir is incomplete; restore it from git (git checkout -- ewa_mcp/street_drawing/fonts)" >&2
  exit 1
fi
exit 0
