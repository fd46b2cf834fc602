"""Fair shares of the worker pool: sessions, per-address caps, a global cap, minting limits, the queue."""

import asyncio
import threading
import time
from concurrent.futures import Future

import pytest

from app.main import app
from app.service.runtime.fairness import COOKIE, Busy, Fairness
from app.service.users import user_systems
from app.service.users.user_checks import checked
from app.web.api.deps import user_systems_service
from app.web.http.disconnect import ClientGone, unless_gone
from tests.web.api.test_api_user_worker import run_in_own_loop


@pytest.fixture
def gate():
    return Fairness(capacity=4, workers=2, per_address=2, mint_per_minute=3)


def test_one_job_per_client(gate):
    ticket = gate.admit("session:a", "10.0.0.1")
    with pytest.raises(Busy) as caught:
        gate.admit("session:a", "10.0.0.1")
    assert not caught.value.whole_server and caught.value.retry_after >= 1
    ticket.release()
    gate.admit("session:a", "10.0.0.1").release()


def test_a_classroom_behind_one_address_shares_it_up_to_the_cap(gate):
    first = gate.admit("session:a", "school")
    second = gate.admit("session:b", "school")
    with pytest.raises(Busy) as caught:
        gate.admit("session:c", "school")
    assert not caught.value.whole_server and "network address" in str(caught.value)
    # another address is not affected by the classroom's share
    other = gate.admit("session:d", "home")
    for ticket in (first, second, other):
        ticket.release()


def test_the_global_cap_answers_503(gate):
    tickets = [gate.admit(f"session:{i}", f"10.0.0.{i}") for i in range(4)]
    with pytest.raises(Busy) as caught:
        gate.admit("session:late", "10.0.0.99")
    assert caught.value.whole_server and 1 <= caught.value.retry_after <= 30
    tickets[0].release()
    gate.admit("session:late", "10.0.0.99").release()
    for ticket in tickets[1:]:
        ticket.release()
    assert gate.in_flight == 0


def test_release_is_idempotent(gate):
    ticket = gate.admit("session:a", "x")
    ticket.release()
    ticket.release()
    assert gate.in_flight == 0
    gate.admit("session:a", "x")
    assert gate.in_flight == 1


def test_sessions_are_signed(gate):
    token = gate.mint("10.0.0.1")
    session = gate.verify(token)
    assert session and token.startswith(session + ".")
    assert gate.verify(session + ".forged") is None
    assert gate.verify("no-signature") is None
    assert gate.verify(None) is None
    assert gate.verify("a." * 200) is None
    # a server with another key does not accept this one's tokens
    assert Fairness(capacity=1, secret="another key").verify(token) is None


def test_sessions_cost_nothing_to_issue_and_an_address_that_hoards_them_shares_one_key(gate):
    tokens = [gate.mint("10.0.0.1") for _ in range(5)]
    assert all(gate.verify(t) for t in tokens)  # minting is never refused
    keys = [gate.key(gate.verify(t), "10.0.0.1") for t in tokens]
    assert keys[:3] == [f"session:{gate.verify(t)}" for t in tokens[:3]]
    assert keys[3:] == ["many:10.0.0.1"] * 2  # beyond mint_per_minute sessions presented in a minute
    assert gate.key(gate.verify(tokens[0]), "10.0.0.1") == keys[0]  # a session already seen keeps its key
    assert gate.key(gate.verify(tokens[4]), "10.0.0.2").startswith("session:")  # another address has its own
    assert gate.key(None, "10.0.0.1") == "new:10.0.0.1"  # no cookie: the address's newcomers


def test_the_newcomers_of_an_address_share_its_cap_but_not_the_one_job_rule(gate):
    tickets = [gate.admit("new:school", "school") for _ in range(2)]
    with pytest.raises(Busy) as caught:
        gate.admit("new:school", "school")
    assert "network address" in str(caught.value)
    for ticket in tickets:
        ticket.release()


def test_a_session_lighter_than_the_flood_of_its_address_is_admitted_beyond_the_cap():
    async def main():
        room = Fairness(capacity=8, workers=1, per_address=2, queue_seconds=30)
        flood = room.admit("new:school", "school")
        await room.turn(flood)
        await asyncio.sleep(0.05)  # the newcomers' job has run a while
        second = room.admit("new:school", "school")
        await asyncio.sleep(0)
        waits = asyncio.ensure_future(room.turn(second))
        await asyncio.sleep(0.01)
        student = room.admit("session:student", "school")  # takes the waiting flood job's place
        with pytest.raises(Busy):
            await waits
        with pytest.raises(Busy):
            room.admit("new:school", "school")  # the flood itself stays within the cap
        third = room.admit("session:student2", "school")  # a second student: beyond the cap, lighter than the flood
        student_turn = asyncio.ensure_future(room.turn(student))
        third_turn = asyncio.ensure_future(room.turn(third))
        await asyncio.sleep(0.01)
        flood.release()
        await student_turn  # a free slot goes to a student
        student.release()
        await third_turn
        third.release()
        return room.in_flight, room.waiting

    assert run(main) == (0, 0)


class FakeJob:
    """A running job's future: cancelling it ends the job (the pool kills its worker), releasing its ticket."""

    def __init__(self, ticket):
        self.ticket, self.cancelled = ticket, False

    def cancel(self):
        self.cancelled = True
        self.ticket.release("cancelled")
        return True


def test_a_session_takes_the_slot_of_a_running_newcomers_job():
    async def main():
        room = Fairness(capacity=8, workers=1, per_address=2, queue_seconds=30)
        flood = room.admit("new:school", "school")
        await room.turn(flood)
        flood.job = FakeJob(flood)
        await asyncio.sleep(0.02)
        student = room.admit("session:student", "school")
        await asyncio.wait_for(room.turn(student), 1)  # at once: the newcomers' job gave way
        assert flood.job.cancelled and "gave way" in flood.job.gave_way
        other = room.admit("new:school", "school")
        waiting = asyncio.ensure_future(room.turn(other))
        await asyncio.sleep(0.02)
        assert not waiting.done()  # a shared key never stops a session's job
        student.release()
        await waiting
        other.release()
        return room.in_flight

    assert run(main) == 0


PENDULUM = {"coordinates": ["q"], "parameters": [{"name": "k", "value": 1.0}], "lagrangian": "q_dot**2/2 - k*q**2/2"}
SPRING = {"coordinates": ["x"], "kinetic": "x_dot**2/2", "potential": "x**2/2"}


# ---- the queue: turns, deadlines, floors, back-off ---------------------------------------------------


def run(coroutine_function):
    return run_in_own_loop(coroutine_function)


def test_a_free_slot_goes_to_the_session_that_used_the_least(gate):
    async def main():
        busy = Fairness(capacity=20, workers=1, per_address=20, queue_seconds=30)
        # ten flooding sessions behind one address have each had a job (some worker time)
        for i in range(10):
            ticket = busy.admit(f"session:flood{i}", "school")
            await busy.turn(ticket)
            await asyncio.sleep(0.01)
            ticket.release()
        holder = busy.admit("session:flood0", "school")
        await busy.turn(holder)  # the worker is taken
        order = []

        async def wait(client):
            ticket = busy.admit(client, "school")
            await busy.turn(ticket)
            order.append(client)
            ticket.release()

        floods = [asyncio.ensure_future(wait(f"session:flood{i}")) for i in range(1, 10)]
        await asyncio.sleep(0.05)
        honest = asyncio.ensure_future(wait("session:honest"))  # arrives last
        await asyncio.sleep(0.05)
        assert busy.waiting == 10 and order == []
        holder.release()
        await asyncio.gather(honest, *floods)
        return order

    order = run(main)
    assert order[0] == "session:honest"  # the next turn, whatever the number of floods queued before it


def test_a_full_address_share_gives_a_newcomer_the_place_of_the_heaviest_waiting_session():
    async def main():
        busy = Fairness(capacity=20, workers=1, per_address=3, queue_seconds=30)
        heavy = busy.admit("session:heavy", "school")
        await busy.turn(heavy)
        await asyncio.sleep(0.05)
        heavy.release()  # heavy has used the worker for a while
        running = busy.admit("session:a", "school")
        await busy.turn(running)
        queued = [busy.admit("session:b", "school"), busy.admit("session:heavy", "school")]
        waits = [asyncio.ensure_future(busy.turn(t)) for t in queued]
        await asyncio.sleep(0.01)
        newcomer = busy.admit("session:new", "school")  # the address is at its share: heavy's place is taken
        with pytest.raises(Busy) as caught:
            await waits[1]
        running.release()
        await waits[0]
        queued[0].release()
        await busy.turn(newcomer)
        newcomer.release()
        with pytest.raises(Busy):  # with nobody heavier waiting, a newcomer is refused as before
            for i in range(4):
                busy.admit(f"session:more{i}", "school")
        return caught.value

    refused = run(main)
    assert not refused.whole_server and "used the server less" in str(refused)


def test_a_wait_past_the_queue_deadline_is_a_503_with_retry_after():
    async def main():
        busy = Fairness(capacity=4, workers=1, queue_seconds=0.2)
        holder = busy.admit("session:a", "x")
        await busy.turn(holder)
        late = busy.admit("session:b", "y")
        with pytest.raises(Busy) as caught:
            await busy.turn(late)
        assert busy.in_flight == 1 and busy.waiting == 0  # the late ticket gave up its place
        holder.release()
        return caught.value

    refused = run(main)
    assert refused.whole_server and refused.retry_after >= 1 and "0.2 s" in str(refused)


def test_a_cancelled_wait_leaves_the_queue():
    async def main():
        busy = Fairness(capacity=4, workers=1, queue_seconds=30)
        holder = busy.admit("session:a", "x")
        await busy.turn(holder)
        waiting = asyncio.ensure_future(busy.turn(busy.admit("session:b", "y")))
        await asyncio.sleep(0.01)
        waiting.cancel()
        with pytest.raises(asyncio.CancelledError):
            await waiting
        left = (busy.in_flight, busy.waiting)
        holder.release()
        return left

    assert run(main) == (1, 0)


def test_a_session_whose_jobs_keep_running_out_of_time_backs_off():
    async def main():
        busy = Fairness(capacity=4, workers=1, per_address=4, queue_seconds=30)
        waits = []
        for _ in range(3):  # the first failure is forgiven; from the second in a row, a wait that doubles
            ticket = busy.admit("session:bomb", "x")
            await busy.turn(ticket)
            ticket.release("timeout")
            try:
                busy.admit("session:bomb", "x").release()
                waits.append(0)
            except Busy as refused:
                assert not refused.whole_server and "ran out of time or memory" in str(refused)
                waits.append(refused.retry_after)
                busy._strikes["session:bomb"] = (busy._strikes["session:bomb"][0], 0.0)  # as if the wait had passed
        ticket = busy.admit("session:honest", "x")  # others at the address are not held back yet
        await busy.turn(ticket)
        ticket.release()
        return waits

    assert run(main) == [0, 5, 10]


def test_an_address_that_keeps_failing_backs_off_for_its_newcomers_but_not_for_its_sessions():
    async def main():
        room = Fairness(capacity=8, workers=1, per_address=2, queue_seconds=30)
        for _ in range(3):  # three jobs in a row out of time, from the address's newcomers (no cookie)
            ticket = room.admit("new:school", "school")
            await room.turn(ticket)
            ticket.release("timeout")
        with pytest.raises(Busy) as caught:
            room.admit("new:school", "school")
        ticket = room.admit("session:student", "school")  # a student's own session is held back only by its own
        ticket.release()
        room.admit("new:elsewhere", "elsewhere").release()  # another address is not affected
        return caught.value

    refused = run(main)
    assert not refused.whole_server and refused.retry_after >= 5


# ---- the service and the routes, with a pool that runs nothing (a spy) ------------------------------


class SpyPool:
    """Stands in for the worker pool: records each submitted job and finishes it when the test says."""

    workers = 1

    def __init__(self):
        self.submitted = []  # (job name, first argument, future)
        self.arrived = threading.Semaphore(0)

    def submit(self, job, *args, timeout):
        future = Future()
        future.set_running_or_notify_cancel()
        self.submitted.append((job.__name__, args[0] if args else None, future))
        self.arrived.release()
        return future

    async def run_async(self, future, timeout):
        return await asyncio.wrap_future(future)

    def finish(self, index, body=b'{"done": true}'):
        self.submitted[index][2].set_result(body)

    def wait_for_job(self):
        assert self.arrived.acquire(timeout=30), "no job reached the pool"


@pytest.fixture
def spy():
    pool = SpyPool()
    service = user_systems.UserSystems(pool=pool, gate=Fairness(capacity=8, workers=1, queue_seconds=30))
    app.dependency_overrides[user_systems_service] = lambda: service
    yield pool, service
    app.dependency_overrides.pop(user_systems_service)


def test_one_job_at_a_time_per_session(client, spy):
    """A second request while the first still runs gets 429 with Retry-After; the first completes."""
    pool, service = spy
    token = service.gate.mint("testclient")
    cookie = {"cookie": f"{COOKIE}={token}"}
    results = {}
    first = threading.Thread(
        target=lambda: results.update(first=client.post("/api/derive", json=PENDULUM, headers=cookie))
    )
    first.start()
    try:
        pool.wait_for_job()
        second = client.post("/api/derive", json=SPRING, headers=cookie)
        assert second.status_code == 429 and int(second.headers["Retry-After"]) >= 1
        body = second.json()
        assert body["retry_after"] == int(second.headers["Retry-After"]) and "already" in body["detail"]
        assert len(pool.submitted) == 1
    finally:
        pool.finish(0)
        first.join(30)
    assert results["first"].status_code == 200 and results["first"].json() == {"done": True}
    # once the first is done, the same session may go again
    again = threading.Thread(
        target=lambda: results.update(again=client.post("/api/derive", json=SPRING, headers=cookie))
    )
    again.start()
    pool.wait_for_job()
    pool.finish(1)
    again.join(30)
    assert results["again"].status_code == 200


def test_the_same_system_asked_twice_at_once_is_derived_once(client, spy):
    """A classroom opening one link: a second session asking for a system being derived waits for that job."""
    pool, service = spy
    cookies = [{"cookie": f"{COOKIE}={service.gate.mint(f'pupil{i}')}"} for i in range(2)]
    results = {}

    def ask(i):
        results[i] = client.post("/api/derive", json=PENDULUM, headers=cookies[i])

    threads = [threading.Thread(target=ask, args=(i,)) for i in range(2)]
    threads[0].start()
    pool.wait_for_job()
    threads[1].start()
    try:
        # the second request is waiting on the first's job: it took no ticket and sent no job
        assert wait_until(lambda: sum(service._waiters.values()) == 2)
        assert service.gate.in_flight == 1 and len(pool.submitted) == 1
    finally:
        pool.finish(0)
        for thread in threads:
            thread.join(30)
    assert results[0].status_code == results[1].status_code == 200
    assert results[0].content == results[1].content and len(pool.submitted) == 1


def test_a_queued_job_whose_client_left_is_never_run(spy):
    pool, service = spy

    async def main():
        holder = asyncio.ensure_future(service.derive(checked(PENDULUM), "session:a", "x"))
        await asyncio.to_thread(pool.wait_for_job)
        queued = asyncio.ensure_future(service.derive(checked(SPRING), "session:b", "y"))
        while service.gate.waiting == 0:
            await asyncio.sleep(0.01)
        queued.cancel()  # what app/web/http/disconnect.py does when the client disconnects
        with pytest.raises(asyncio.CancelledError):
            await queued
        for _ in range(100):  # the job's own task ends on the loop's next turns
            if service.gate.waiting == 0:
                break
            await asyncio.sleep(0.01)
        assert (service.gate.in_flight, service.gate.waiting) == (1, 0)
        pool.finish(0)
        await holder
        await asyncio.sleep(0.05)  # a cancelled job would have reached the pool by now

    run(main)
    assert [name for name, *_ in pool.submitted] == ["derive_job"]


def test_a_client_that_disconnects_cancels_its_work():
    class LeavingRequest:
        async def receive(self):
            await asyncio.sleep(0.05)
            return {"type": "http.disconnect"}

    cancelled = []

    async def work():
        try:
            await asyncio.sleep(30)
        except asyncio.CancelledError:
            cancelled.append(True)
            raise

    async def main():
        with pytest.raises(ClientGone):
            await unless_gone(LeavingRequest(), work())

    run(main)
    assert cancelled == [True]


def wait_until(condition, seconds=30):
    deadline = time.monotonic() + seconds
    while not condition() and time.monotonic() < deadline:
        time.sleep(0.01)
    return condition()
