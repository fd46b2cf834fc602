"""Security headers on every response: one small ASGI middleware.

* ``Content-Security-Policy``: scripts, styles, fonts, images and requests
  from this origin only (the pages load KaTeX, plotly.js and swagger-ui from
  static/vendor and have no inline scripts; the JSON data blocks are not run).
  ``'unsafe-eval'``: the live preview (static/js/preview.js) turns the
  right-hand side the server printed from the engine's expressions into a
  function with ``new Function``; no inline or injected script may run.
  Inline *styles* stay allowed: KaTeX writes ``style`` attributes and plotly.js
  adds style rules as it draws. ``frame-ancestors 'none'``: no other site may
  frame a page (clickjacking); ``X-Frame-Options: DENY`` says it to old browsers.
  The one exception is the embed pages (``/embed/…``, app/web/pages/embed.py): the sites the
  ``embed_ancestors`` setting lists may frame those (and ``X-Frame-Options``, which
  cannot name a site, is left off them); with the setting empty they are refused too.
* ``X-Content-Type-Options: nosniff``: a browser takes each file as its declared type.
* ``Referrer-Policy: same-origin``: the pages' addresses do not leave the site.
"""

from __future__ import annotations

from starlette.types import ASGIApp, Message, Receive, Scope, Send

from app.settings import settings

EMBED_PREFIX = b"/embed/"
SOURCES = (
    "default-src 'self'",
    "script-src 'self' 'unsafe-eval'",
    "style-src 'self' 'unsafe-inline'",
    "img-src 'self' data: blob:",
    "font-src 'self' data:",
    "connect-src 'self'",
    "object-src 'none'",
    "base-uri 'self'",
    "form-action 'self'",
)
CSP = "; ".join((*SOURCES, "frame-ancestors 'none'"))
HEADERS = [
    (b"content-security-policy", CSP.encode()),
    (b"x-content-type-options", b"nosniff"),
    (b"x-frame-options", b"DENY"),
    (b"referrer-policy", b"same-origin"),
]


def embed_headers(ancestors: str) -> list[tuple[bytes, bytes]]:
    """The headers of an embed page: framed by the listed origins (comma-separated), or by none."""
    sites = [a.strip() for a in ancestors.split(",") if a.strip()]
    if not sites:
        return HEADERS
    csp = "; ".join((*SOURCES, "frame-ancestors " + " ".join(sites)))
    return [(b"content-security-policy", csp.encode()), *(h for h in HEADERS[1:] if h[0] != b"x-frame-options")]


class SecurityHeaders:
    def __init__(self, app: ASGIApp, embed_ancestors: str | None = None):
        self.app = app
        # read from the settings on the first request unless given (the app is built before they are read)
        self._embed = None if embed_ancestors is None else embed_headers(embed_ancestors)

    def _headers(self, path: bytes) -> list[tuple[bytes, bytes]]:
        if not path.startswith(EMBED_PREFIX):
            return HEADERS
        if self._embed is None:
            self._embed = embed_headers(settings().embed_ancestors)
        return self._embed

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return

        ours = self._headers(scope.get("raw_path") or scope["path"].encode())

        async def with_headers(message: Message) -> None:
            if message["type"] == "http.response.start":
                present = {name.lower() for name, _ in message.get("headers", [])}
                message["headers"] = [*message.get("headers", []), *(h for h in ours if h[0] not in present)]
            await send(message)

        await self.app(scope, receive, with_headers)
