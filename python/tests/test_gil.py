"""Every call releases the GIL: while one thread is inside a long call,
another thread keeps running Python code, and two threads' calls overlap.

Proof by progress, not by timing ratios (robust on a loaded machine): a
thread that held the GIL for the whole call would stop the counting loop
of the main thread for as long as it lasts, so the loop would count ~0
iterations between the call's start and end."""

import threading
import time

import numpy as np

import asperity
from conftest import REPO

H = np.linspace(-3.0, 8.0, 3_000_000)


def progress_during(call):
    """Iterations of a pure-Python loop in this thread while `call` runs in
    another; also the call's duration."""
    state = {"inside": False, "done": False}

    def worker():
        state["inside"] = True
        t0 = time.perf_counter()
        call()
        state["seconds"] = time.perf_counter() - t0
        state["inside"] = False
        state["done"] = True

    t = threading.Thread(target=worker)
    count = 0
    t.start()
    while not state["inside"] and not state["done"]:
        pass
    while state["inside"]:
        count += 1
    t.join()
    return count, state["seconds"]


def test_fn_releases_the_gil():
    # Quadrature order: tens of ms at least.
    count, seconds = progress_during(lambda: asperity.fn("gaussian", 0.7, H[:30_000]))
    assert seconds > 0.01
    assert count > 1000, (count, seconds)


def test_run_releases_the_gil():
    scene = REPO / "examples" / "scenes" / "mems-gold.toml"
    count, seconds = progress_during(lambda: asperity.run(scene))
    assert count > 1000, (count, seconds)


def test_sweep_and_commands_release_the_gil():
    d = asperity.default_scene()
    d["program"]["points"] = 100
    heights = np.load(REPO / "examples" / "data" / "measured-topography.npy")
    calls = {
        "sweep": lambda: asperity.sweep(d, {"surface.sigma": np.linspace(3e-9, 8e-9, 6)}, threads=1),
        "sphere": lambda: asperity.sphere(0.5),
        "rough_sphere": lambda: asperity.rough_sphere(10, d=np.linspace(0.2, 3.0, 15), tolerance=1e-8),
        "surface": lambda: [asperity.surface(heights, 50e-9) for _ in range(5)],
    }
    for name, call in calls.items():
        count, seconds = progress_during(call)
        assert count > 1000, (name, count, seconds)


def test_two_calls_meet_inside_the_library(tmp_path):
    """Two asperity calls in two threads that can only finish together:
    `sphere(curve=FIFO)` blocks opening a named pipe for writing until
    `run(FIFO)` opens it for reading, and the reader waits for the writer's
    end of file. Were the GIL held by either call, the other could never
    enter the library and both would hang (the joins would time out)."""
    import os

    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    out = {}

    def reader():
        try:
            asperity.run(fifo)
        except ValueError as e:  # the sphere's CSV is not a scene
            out["reader"] = str(e)

    def writer():
        out["writer"] = asperity.sphere(0.5, resolution=0.5, curve=fifo)

    threads = [threading.Thread(target=reader, daemon=True), threading.Thread(target=writer, daemon=True)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(timeout=120)
    if any(t.is_alive() for t in threads):
        # Unblock whichever end is waiting, then fail.
        fd = os.open(fifo, os.O_RDWR | os.O_NONBLOCK)
        os.close(fd)
        raise AssertionError("the two calls did not run at the same time")
    assert out["writer"]["mu"] == 0.5
    # The reader parsed what the writer wrote: the curve's CSV header.
    assert out["reader"].startswith("central_gap,approach,load_bar"), out["reader"]
