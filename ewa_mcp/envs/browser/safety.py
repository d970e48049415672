"""Which URLs the browser may reach: the embedded sites, plus an explicit allowlist.

Checked twice: ``UrlPolicy.check`` refuses a bad ``browser_goto``/``browser_new_tab`` before
anything happens, and the browser is launched with ``allowed_origins`` as the only destinations
its network reaches (chromium.py: everything else goes to a proxy that refuses connections), so
links, redirects, sub-resources, popups and scripts' requests to other places fail in the
browser too. Link-local and cloud-metadata addresses are refused even when allowlisted.

URLs are read the way Chromium reads them: with a WHATWG URL parser (``ada_url``, the parser of
Node.js), never with ``urllib``, which disagrees on backslashes, userinfo, IPv4 shorthand
(``127.1``, ``2130706433``), percent-encoded hosts and stripped tabs/newlines. ``check``
returns the parser's serialisation, and that is the string the browser is given, so what was
checked is what loads.
"""

from __future__ import annotations

import ipaddress
import re

from ada_url import URL, join_url

METADATA_HOSTS = frozenset({"metadata", "metadata.google.internal", "instance-data", "instance-data.ec2.internal",
                            "metadata.azure.com"})
SAFE_INTERNAL = ("about:blank",)
# Schemes named as such in the refusal (anything else before a colon is taken for a site name).
OTHER_SCHEMES = frozenset({"file", "data", "javascript", "blob", "chrome", "about", "view-source", "ftp", "ws", "wss",
                           "mailto", "filesystem", "chrome-extension", "devtools", "intent", "vbscript"})


class BlockedUrlError(ValueError):
    """A URL the browser must not visit; the message names the reason and the allowed sites."""


def parse_url(text: str) -> URL | None:
    """``text`` parsed as a browser parses an absolute URL (WHATWG), or None if it is not one."""
    try:
        return URL(text)
    except ValueError:
        return None


def _scheme(url: URL) -> str:
    return url.protocol.removesuffix(":")


def _url_origin(url: URL) -> str:
    return _origin(_scheme(url), url.hostname, int(url.port) if url.port else None)


def _origin(scheme: str, host: str, port: int | None) -> str:
    default = {"http": 80, "https": 443}.get(scheme)
    return f"{scheme}://{host}" + (f":{port}" if port and port != default else "")


def _is_link_local_or_metadata(host: str) -> bool:
    host = host.strip("[]").lower().rstrip(".")
    if host in METADATA_HOSTS:
        return True
    try:
        address = ipaddress.ip_address(host)
    except ValueError:
        return False
    if isinstance(address, ipaddress.IPv6Address) and address.ipv4_mapped is not None:
        address = address.ipv4_mapped  # ::ffff:169.254.169.254
    if address.is_link_local:
        return True
    # fd00:ec2::254 is the IPv6 address of the EC2 metadata service
    return address == ipaddress.ip_address("fd00:ec2::254")


def normalize_origin(text: str) -> str:
    """An allowlist entry as a canonical origin; raises ValueError naming the fix."""
    parts = parse_url(text.strip())
    if parts is None or _scheme(parts) not in ("http", "https") or not parts.hostname:
        raise ValueError(f"allowlist entry {text[:200]!r} is not an http(s) origin; write it like "
                         "http://127.0.0.1:9000")
    if _is_link_local_or_metadata(parts.hostname):
        raise ValueError(f"allowlist entry {text[:200]!r} is a link-local/cloud-metadata address, which is never "
                         "allowed; remove it")
    return _url_origin(parts)


class UrlPolicy:
    def __init__(self, site_urls: dict[str, str], extra_origins: list[str] | tuple[str, ...] = ()):
        self.site_urls = {name: url.rstrip("/") for name, url in site_urls.items()}
        self.site_origins = {normalize_origin(url): name for name, url in self.site_urls.items()}
        self.extra_origins = [normalize_origin(o) for o in extra_origins]
        self.allowed_origins = list(self.site_origins) + [o for o in self.extra_origins if o not in self.site_origins]
        # A canonical (browser-serialised) URL starting with one of these is allowed without parsing.
        self.allowed_prefixes = tuple(origin + "/" for origin in self.allowed_origins)

    # ------------------------------------------------------------ addressing
    def describe_allowed(self) -> str:
        sites = ", ".join(f"{name}:/ ({url})" for name, url in self.site_urls.items())
        extra = f"; also allowed: {', '.join(self.extra_origins)}" if self.extra_origins else ""
        return f"the embedded sites are {sites or 'none'}{extra}"

    def site_relative(self, url: str) -> str | None:
        """'recipes:/recipe/r001' for a loopback URL of a site, else None."""
        parts = parse_url(url)
        if parts is None or _scheme(parts) not in ("http", "https") or parts.username or parts.password:
            return None
        site = self.site_origins.get(_url_origin(parts))
        if site is None:
            return None
        return f"{site}:{parts.pathname or '/'}{parts.search}{parts.hash}"

    def resolve(self, text: str, current_url: str | None = None) -> str:
        """An absolute, allowed URL for what an agent or task wrote; raises BlockedUrlError."""
        url = text.strip()
        if not url:
            raise BlockedUrlError("empty URL; " + self.describe_allowed())
        if url in SAFE_INTERNAL:
            return url
        scheme, sep, rest = url.partition(":")
        if sep and scheme in self.site_urls and not rest.startswith("//"):
            return self.check(self.site_urls[scheme] + (rest if rest.startswith("/") else "/" + rest))
        if url.startswith("/") and not url.startswith("//"):
            if current_url and self.site_relative(current_url) is not None:
                try:
                    joined = join_url(current_url, url)  # as the browser resolves it: "/\\host" is another host
                except ValueError:
                    raise BlockedUrlError(f"{url[:200]!r} is not a valid path; " + self.describe_allowed()) from None
                return self.check(joined)
            raise BlockedUrlError(f"{url!r} is a path, but the current page is not on an embedded site; "
                                  f"write it as site:{url} (e.g. home:{url}); " + self.describe_allowed())
        lowered = scheme.lower()
        if sep and lowered not in ("http", "https") and re.fullmatch(r"[a-z][a-z0-9+.-]*", lowered):
            if lowered in OTHER_SCHEMES:
                raise BlockedUrlError(f"{lowered}: URLs are refused: the browser may only open the embedded "
                                      "sites; " + self.describe_allowed())
            raise BlockedUrlError(f"unknown site {scheme!r} in {url!r}; " + self.describe_allowed())
        if not sep:
            raise BlockedUrlError(f"{url!r} is not a URL; write a site-relative URL such as home:/ or an "
                                  "absolute http:// URL; " + self.describe_allowed())
        return self.check(url)

    def check(self, url: str) -> str:
        """The URL as the browser reads it (its WHATWG serialisation) when the browser may load
        it; otherwise BlockedUrlError saying why. Give the browser the returned string."""
        if url in SAFE_INTERNAL:
            return url
        shown = repr(url[:200])
        parts = parse_url(url)
        if parts is None:
            raise BlockedUrlError(f"{shown} is not a valid URL (a browser cannot parse it: check the host, port and "
                                  "characters); " + self.describe_allowed())
        scheme = _scheme(parts)
        if scheme not in ("http", "https"):
            raise BlockedUrlError(f"{scheme}: URLs are refused ({shown}); " + self.describe_allowed())
        host = parts.hostname
        if not host:
            raise BlockedUrlError(f"{shown} has no host; " + self.describe_allowed())
        if _is_link_local_or_metadata(host):
            raise BlockedUrlError(f"{shown} is a link-local/cloud-metadata address and is always refused; "
                                  + self.describe_allowed())
        origin = _url_origin(parts)
        read_as = (f" (a browser reads it as {parts.href[:200]!r}: host {host[:100]!r})" if parts.href != url
                   else f" (host {host[:100]!r})")
        if origin not in self.allowed_origins:
            raise BlockedUrlError(f"{shown}{read_as} is not one of the embedded sites (only loopback sites are "
                                  "reachable); " + self.describe_allowed() + "; use site-relative URLs like home:/")
        if parts.username or parts.password:
            raise BlockedUrlError(f"{shown} carries a user name or password before its host, which is refused; "
                                  "write the site's URL without 'user@'; " + self.describe_allowed())
        return parts.href

    def is_allowed(self, url: str) -> bool:
        try:
            self.check(url)
        except BlockedUrlError:
            return False
        return True
