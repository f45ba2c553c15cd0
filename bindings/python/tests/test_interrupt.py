"""Ctrl-C during long calls: a timer thread, started as the library call
begins (not while Python converts the points), sends SIGINT to this process
while insert_many or epsilon_net runs; the call must stop part way, raise
KeyboardInterrupt, keep the points done in a valid triangulation, and put
the previous SIGINT handler back. And a signal handler that runs inside such
a call (as every handler does, the call running Python code) and uses the
triangulation: close() is deferred to the call's end, anything else raises,
never a crash."""

import contextlib
import os
import random
import signal
import threading

import pytest

import hdt


def disk_points(n, seed):
    """n random points of the disk of radius 0.4 (inside F_g)."""
    r = random.Random(seed)
    points = []
    while len(points) < n:
        x, y = 0.8 * r.random() - 0.4, 0.8 * r.random() - 0.4
        if x * x + y * y < 0.16:
            points.append((x, y))
    return points


@pytest.fixture
def sigint_during_call(monkeypatch):
    """SIGINT 0.05 s into the next interruptible library call; yields the timers."""
    from hdt import triangulation

    timers = []
    original = triangulation.interruptible

    @contextlib.contextmanager
    def with_timer(handle, *args):
        with original(handle, *args):
            timer = threading.Timer(0.05, os.kill, (os.getpid(), signal.SIGINT))
            timers.append(timer)
            timer.start()
            yield

    monkeypatch.setattr(triangulation, "interruptible", with_timer)
    yield timers
    for timer in timers:
        timer.join()


def test_insert_many_stops_on_sigint(sigint_during_call, monkeypatch):
    points = disk_points(400_000, 1)
    previous = signal.getsignal(signal.SIGINT)
    t = hdt.Triangulation(2)
    dummies = t.vertex_count
    with pytest.raises(KeyboardInterrupt):
        t.insert_many(points)
    sigint_during_call[0].join()
    monkeypatch.undo()  # the second insert_many runs without a SIGINT
    assert signal.getsignal(signal.SIGINT) is previous
    t.validate()
    inserted = t.vertex_count - dummies
    assert 0 < inserted < len(points), inserted
    # The rest goes in afterwards: all new, so nothing was half inserted.
    t.insert_many(points)
    assert t.vertex_count == dummies + len(points)
    t.validate()


def test_epsilon_net_stops_on_sigint(sigint_during_call):
    t = hdt.Triangulation(2)
    with pytest.raises(KeyboardInterrupt):
        t.epsilon_net(0.003)  # some 940,000 points: seconds
    sigint_during_call[0].join()
    t.validate()
    assert t.vertex_count > t.dummy_count
    assert t.quality().max_radius > 0.003


def test_without_sigint_nothing_changes():
    points = disk_points(3000, 2)
    a, b = hdt.Triangulation(2), hdt.Triangulation(2)
    a.insert_many(points)
    b.insert_many(points)
    assert a.to_bytes() == b.to_bytes()
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_off_the_main_thread():
    """No handler can be installed there: the call runs as before."""
    out = []
    thread = threading.Thread(target=lambda: out.append(hdt.Triangulation(2).insert_many(disk_points(100, 3))))
    thread.start()
    thread.join()
    assert len(out[0]) == 100


@pytest.fixture
def handler_during_call(monkeypatch):
    """Runs a function from a SIGALRM handler 0.05 s into the next
    interruptible library call (inside it: the handler runs when the
    progress callback runs Python code); yields the list of its results
    (the value, or the exception it raised)."""
    from hdt import triangulation

    results, action = [], []
    original = triangulation.interruptible

    def on_alarm(signum, frame):
        try:
            results.append(action[0]())
        except Exception as error:  # noqa: BLE001 - the test looks at it
            results.append(error)

    @contextlib.contextmanager
    def with_alarm(handle, *args):
        with original(handle, *args):
            signal.setitimer(signal.ITIMER_REAL, 0.05)
            try:
                yield
            finally:
                signal.setitimer(signal.ITIMER_REAL, 0)

    previous = signal.signal(signal.SIGALRM, on_alarm)
    monkeypatch.setattr(triangulation, "interruptible", with_alarm)
    yield action, results
    signal.signal(signal.SIGALRM, previous)


@pytest.mark.parametrize("call", ["insert_many", "epsilon_net"])
def test_close_from_a_handler_inside_the_call(handler_during_call, call):
    action, results = handler_during_call
    t = hdt.Triangulation(2)
    action.append(t.close)
    if call == "insert_many":
        ids = t.insert_many(disk_points(400_000, 4))
        assert len(ids) == 400_000
    else:
        t.epsilon_net(0.003)  # seconds, unless the close stops it
    assert results == [None], results
    assert t.closed
    with pytest.raises(hdt.HandleClosed):
        t.vertex_count
    t.close()  # again: nothing


def test_changes_from_a_handler_inside_the_call_raise(handler_during_call):
    action, results = handler_during_call
    t = hdt.Triangulation(2)
    first_new = t.vertex_id_bound  # the first id insert_many gives
    action.append(lambda: t.remove(first_new))
    points = disk_points(150_000, 5)
    ids = t.insert_many(points)
    assert len(results) == 1, results
    error = results[0]
    assert isinstance(error, hdt.InvalidArgument), error
    assert "busy in insert_many" in str(error)
    # Nothing changed: every id returned is a live vertex at its point.
    assert len(t) == t.dummy_count + len(points)
    for i in range(0, len(points), 997):
        assert t.vertex_point(ids[i]) == pytest.approx(points[i], abs=0)
    assert t.vertex_point(first_new) is not None
    t.validate()
    t.remove(first_new)  # idle again: allowed
    assert len(t) == t.dummy_count + len(points) - 1
