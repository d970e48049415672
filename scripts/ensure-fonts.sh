#!/usr/bin/env bash
# Optional: Noto fonts so geolocation street views draw signs in their own scripts (Devanagari, Thai,
# CJK, Ethiopic, ...). Without them the renderer falls back to Latin transliteration, deterministically.
set -uo pipefail
# grep without -q reads all input: with pipefail, an early exit would SIGPIPE fc-list and fail the test.
if fc-list 2>/dev/null | grep -i "Noto Sans CJK\|Noto Serif CJK" >/dev/null; then exit 0; fi
if [ "$(id -u)" = "0" ] && command -v apt-get >/dev/null; then
  echo "fonts: installing Noto fonts for non-Latin street signs"
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends fonts-noto-core fonts-noto-cjk >/dev/null 2>&1 \
    || { apt-get update -qq >/dev/null 2>&1 && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends fonts-noto-core fonts-noto-cjk >/dev/null 2>&1; } \
    || echo "fonts: could not install Noto fonts; signs in non-Latin scripts are transliterated"
else
  echo "fonts: Noto fonts not found (apt-get install fonts-noto-core fonts-noto-cjk); signs are transliterated"
fi
exit 0
