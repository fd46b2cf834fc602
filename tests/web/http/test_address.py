"""The client's address: the peer, or a configured header, believed only on connections from a trusted proxy."""

import pytest

from app.web.http.address import client_address


def scope(peer: str, *headers: tuple[str, str]) -> dict:
    return {"client": (peer, 40000), "headers": [(k.lower().encode(), v.encode()) for k, v in headers]}


def test_without_a_configured_header_the_peer_is_the_client():
    seen = scope("10.0.0.5", ("X-Forwarded-For", "1.2.3.4"))
    assert client_address(seen, header="", trusted="10.0.0.5") == "10.0.0.5"


def test_a_trusted_proxy_names_the_client():
    seen = scope("127.0.0.1", ("X-Forwarded-For", "203.0.113.7"))
    assert client_address(seen, header="X-Forwarded-For", trusted="127.0.0.1") == "203.0.113.7"


def test_a_client_talking_directly_cannot_name_itself():
    seen = scope("198.51.100.9", ("X-Forwarded-For", "203.0.113.7"))
    assert client_address(seen, header="X-Forwarded-For", trusted="127.0.0.1") == "198.51.100.9"


@pytest.mark.parametrize(
    ("chain", "expected"),
    [
        ("6.6.6.6, 203.0.113.7", "203.0.113.7"),  # what the client wrote (left) proves nothing
        ("203.0.113.7, 10.0.0.2", "203.0.113.7"),  # a second trusted proxy in the chain is skipped
        ("10.0.0.2", "127.0.0.1"),  # only proxies: the peer
    ],
)
def test_the_rightmost_address_that_is_not_a_trusted_proxy_counts(chain, expected):
    seen = scope("127.0.0.1", ("X-Forwarded-For", chain))
    assert client_address(seen, header="X-Forwarded-For", trusted="127.0.0.1, 10.0.0.2") == expected


def test_a_single_address_header_works_too():
    seen = scope("127.0.0.1", ("X-Real-IP", "203.0.113.7"))
    assert client_address(seen, header="x-real-ip", trusted="127.0.0.1") == "203.0.113.7"


def test_no_peer_is_unknown():
    assert client_address({"headers": []}, header="", trusted="") == "unknown"


def test_trusted_proxies_may_be_cidr_ranges():
    behind = scope("10.42.3.17", ("X-Forwarded-For", "203.0.113.7, 10.42.0.5"))  # an ingress pod, then another hop
    assert client_address(behind, header="X-Forwarded-For", trusted="10.42.0.0/16") == "203.0.113.7"
    outside = scope("10.43.0.1", ("X-Forwarded-For", "203.0.113.7"))  # not in the range: its header proves nothing
    assert client_address(outside, header="X-Forwarded-For", trusted="10.42.0.0/16") == "10.43.0.1"
    six = scope("fd00::5", ("X-Forwarded-For", "2001:db8::9"))
    assert client_address(six, header="X-Forwarded-For", trusted="fd00::/8,127.0.0.1") == "2001:db8::9"
