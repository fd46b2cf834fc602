"""Slow clients: headers and bodies that never finish lose their connection instead of holding it."""

import socket
import threading
import time

import pytest
import uvicorn
from starlette.responses import PlainTextResponse

from app.web.api.limits import BodyLimit
from app.web.http.server_options import options
from app.web.http.slow_clients import HeaderDeadline

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

SECONDS = 0.5


class QuickHeaders(HeaderDeadline):
    seconds = SECONDS


async def echo(scope, receive, send):
    body = b""
    while True:
        message = await receive()
        body += message.get("body", b"")
        if not message.get("more_body"):
            break
    await PlainTextResponse(f"{len(body)} bytes")(scope, receive, send)


@pytest.fixture(scope="module")
def server():
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    config = uvicorn.Config(BodyLimit(echo, seconds=SECONDS), port=port, http=QuickHeaders, log_level="warning", lifespan="off")
    running = uvicorn.Server(config)
    thread = threading.Thread(target=running.run, daemon=True)
    thread.start()
    while not running.started:
        time.sleep(0.02)
    yield port
    running.should_exit = True
    thread.join(10)


def talk(port, data, wait=5.0):
    """Send ``data`` and read until the server closes the connection (or ``wait`` s pass)."""
    with socket.create_connection(("127.0.0.1", port)) as connection:
        connection.settimeout(wait)
        connection.sendall(data)
        received = b""
        try:
            while chunk := connection.recv(4096):
                received += chunk
        except TimeoutError:
            return received, False
        return received, True


def test_an_honest_request_is_served(server):
    answer, _ = talk(server, b"POST / HTTP/1.1\r\nHost: x\r\nContent-Length: 3\r\nConnection: close\r\n\r\nabc")
    assert answer.startswith(b"HTTP/1.1 200") and answer.endswith(b"3 bytes")


def test_headers_that_never_finish_lose_the_connection(server):
    answer, closed = talk(server, b"POST / HTTP/1.1\r\nHost: x\r\nX-Slow: ")
    assert closed and answer == b""


def test_a_connection_that_sends_nothing_is_closed(server):
    answer, closed = talk(server, b"")
    assert closed and answer == b""


def test_a_body_that_never_comes_gets_408(server):
    answer, closed = talk(server, b"POST / HTTP/1.1\r\nHost: x\r\nContent-Length: 100\r\n\r\nabc")
    assert closed and answer.startswith(b"HTTP/1.1 408") and b"did not arrive" in answer


def test_expect_100_continue_without_a_body_gets_408(server):
    request = b"POST / HTTP/1.1\r\nHost: x\r\nContent-Length: 100\r\nExpect: 100-continue\r\n\r\n"
    answer, closed = talk(server, request)
    assert closed and answer.startswith(b"HTTP/1.1 100 Continue") and b"HTTP/1.1 408" in answer


def test_the_server_options_bound_connections_and_use_the_header_deadline():
    given = options()
    assert given[given.index("--http") + 1] == "app.web.http.slow_clients:HeaderDeadline"
    assert int(given[given.index("--limit-concurrency") + 1]) > 0
    assert int(given[given.index("--timeout-keep-alive") + 1]) > 0
