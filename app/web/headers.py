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
* ``X-Content-Type-Options: nosniff``: a browser takes each file as its declared type.
* ``Referrer-Policy: same-origin``: the pages' addresses do not leave the site.
"""

from __future__ import annotations

from starlette.types import ASGIApp, Message, Receive, Scope, Send

CSP = "; ".join(
    (
        "default-src 'self'",
        "script-src 'self' 'unsafe-eval'",
        "style-src 'self' 'unsafe-inline'",
        "img-src 'self' data: blob:",
        "font-src 'self' data:",
        "connect-src 'self'",
        "object-src 'none'",
        "base-uri 'self'",
        "form-action 'self'",
        "frame-ancestors 'none'",
    )
)
HEADERS = [
    (b"content-security-policy", CSP.encode()),
    (b"x-content-type-options", b"nosniff"),
    (b"x-frame-options", b"DENY"),
    (b"referrer-policy", b"same-origin"),
]


class SecurityHeaders:
    def __init__(self, app: ASGIApp):
        self.app = app

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return

        async def with_headers(message: Message) -> None:
            if message["type"] == "http.response.start":
                present = {name.lower() for name, _ in message.get("headers", [])}
                message["headers"] = [*message.get("headers", []), *(h for h in HEADERS if h[0] not in present)]
            await send(message)

        await self.app(scope, receive, with_headers)
