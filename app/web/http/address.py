"""The client's network address: the connection's peer, or what a trusted reverse proxy says it is.

Behind a reverse proxy every request arrives from the proxy, so per-address limits would treat the
whole world as one client.  A proxy names the client in a header (``X-Forwarded-For: client,
proxy1``; ``X-Real-IP: client``), but any client can send that header too.  So the header is read
only when it is configured (``LAGRANGE_PROXY_HEADER``) and only on connections from a configured
proxy (``LAGRANGE_TRUSTED_PROXIES``: addresses or CIDR ranges, as a cluster's ingress has); the address taken is the rightmost one in it that is not
itself a trusted proxy (the entries left of it were written by the client and prove nothing).

uvicorn rewrites the peer from ``X-Forwarded-For`` by itself when a connection comes from
127.0.0.1 (its ``--proxy-headers``, on by default); the server's options turn that off
(app/web/http/server_options.py), so this module is the one place that decides.
"""

from __future__ import annotations

import ipaddress
from functools import lru_cache

from starlette.types import Scope

from app.settings import settings

UNKNOWN = "unknown"


Proxies = tuple[ipaddress.IPv4Network | ipaddress.IPv6Network, ...]


@lru_cache(maxsize=4)
def _trusted(listed: str) -> Proxies:
    """The trusted proxies: addresses or CIDR ranges (``10.0.0.0/8``), as networks (checked by the settings)."""
    return tuple(ipaddress.ip_network(a.strip(), strict=False) for a in listed.split(",") if a.strip())


def _is_proxy(address: str, proxies: Proxies) -> bool:
    try:
        ip = ipaddress.ip_address(address)
    except ValueError:
        return False  # not an address (a test client's name, "unknown"): never a proxy
    return any(ip in network for network in proxies)


def client_address(scope: Scope, header: str | None = None, trusted: str | None = None) -> str:
    """The address per-address limits apply to, for an HTTP connection's scope."""
    peer = scope.get("client")
    address = peer[0] if peer else UNKNOWN
    header = (settings().proxy_header if header is None else header).strip().lower()
    if not header:
        return address
    proxies = _trusted(settings().trusted_proxies if trusted is None else trusted)
    if not _is_proxy(address, proxies):
        return address  # a client talking to us directly: its own header proves nothing
    name = header.encode("latin-1")
    values = [v.decode("latin-1") for k, v in scope.get("headers", ()) if k == name]
    hops = [h.strip() for value in values for h in value.split(",") if h.strip()]
    for hop in reversed(hops):
        if not _is_proxy(hop, proxies):
            return hop[:64]
    return address
