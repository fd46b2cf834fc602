"""A shared window whose store cannot be reached counts in this replica, so a class keeps working."""

from __future__ import annotations

import asyncio

from app.errors import OverCapacity
from app.service.classroom.shared_rates import SharedWindow, Store


def test_an_unreachable_store_falls_back_to_counting_here(tmp_path):
    async def run() -> list[bool]:
        store = Store(f"unix://{tmp_path}/no-such.sock")
        window = SharedWindow(2, "joins to this class", store, "test")
        taken = []
        for _ in range(3):
            try:
                await window.take("ABC123")
                taken.append(True)
            except OverCapacity:
                taken.append(False)
        await store.close()
        return taken

    # the class keeps working, and this replica still holds the limit
    assert asyncio.run(run()) == [True, True, False]
