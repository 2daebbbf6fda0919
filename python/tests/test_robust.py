"""The package never crashes or hangs the interpreter: no Rust panic
reaches Python, memory beyond what is available is MemoryError before
anything is allocated, Ctrl-C interrupts long calls within a second, bad
arrays are TypeError/ValueError naming the argument."""

import datetime
import os
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

import asperity
from conftest import REPO, assert_same, cli, record


def run_python(code, *, timeout=120, env=None):
    """Runs `code` in a fresh interpreter; returns the CompletedProcess."""
    return subprocess.run(
        [sys.executable, "-c", textwrap.dedent(code)],
        capture_output=True,
        text=True,
        timeout=timeout,
        cwd=REPO,
        env={**os.environ, **(env or {})},
    )


# -- panics --------------------------------------------------------------


def test_a_three_by_three_map_is_solved_not_a_panic():
    h = np.random.default_rng(1).normal(0, 1e-9, (3, 3))
    out = asperity.bem(h, 1e-7, 1e9, pressures=[1e6])
    assert len(out["states"]) == 1
    assert 0 < out["states"][0]["area_fraction"] <= 1
    # The command line on the same map: a result, not exit 101.
    path = REPO / "target" / "map3x3.npy"
    np.save(path, h)
    try:
        r = cli("bem", path, "--pixel-size", "1e-7", "--estar", "1e9", "--pressures", "1e6", "--json")
        assert r.returncode == 0, r.stderr
    finally:
        path.unlink()


@pytest.mark.parametrize(
    "name,call",
    [
        ("bem", lambda: asperity.bem(np.random.default_rng(3).normal(0, 1e-9, (8, 8)), 1e-7, 1e9, pressures=[1e6])),
        ("fn", lambda: asperity.fn("gaussian", 1.0, [0.0])),
        ("run", lambda: asperity.run(asperity.default_scene())),
        ("law", lambda: asperity.law("jkr")),
    ],
)
def test_an_internal_panic_is_a_runtime_error(name, call, monkeypatch):
    monkeypatch.setenv("ASPERITY_TEST_PANIC", name)
    with pytest.raises(RuntimeError) as e:
        call()
    msg = record(e)
    assert msg.startswith(f"internal error in asperity.{name}: "), msg
    assert "please report" in msg
    # `except Exception` catches it (a PanicException would not be).
    try:
        call()
    except Exception as caught:  # noqa: BLE001
        assert isinstance(caught, RuntimeError)
    monkeypatch.delenv("ASPERITY_TEST_PANIC")
    call()  # and the interpreter is fine afterwards


# -- memory --------------------------------------------------------------

MEMORY_CASES = {
    "surface": "asperity.surface(np.broadcast_to(1e-9, (100000, 100000)), 1e-7)",
    "bem": "asperity.bem(np.broadcast_to(1e-9, (100000, 100000)), 1e-7, 1e9, pressures=[1e6])",
    "fn": 'asperity.fn("gaussian", 1.5, np.broadcast_to(0.5, (2 * 10**9,)))',
}


@pytest.mark.parametrize("case", sorted(MEMORY_CASES))
def test_memory_beyond_the_limit_is_memory_error(case):
    r = run_python(
        f"""
        import resource
        resource.setrlimit(resource.RLIMIT_AS, (6 * 2**30, 6 * 2**30))
        import numpy as np
        import asperity
        try:
            {MEMORY_CASES[case]}
        except MemoryError as e:
            print("MemoryError:", e)
        """
    )
    assert r.returncode == 0, (r.returncode, r.stderr[-2000:])
    line = r.stdout.strip()
    assert line.startswith("MemoryError: "), (line, r.stderr[-2000:])
    record(line[len("MemoryError: "):])
    assert "GB" in line and "available" in line, line


# -- Ctrl-C --------------------------------------------------------------

INTERRUPTED = """
import os, resource, signal, sys, threading, time
import numpy as np
import asperity

def cpu():
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime

def interrupt_after(seconds):
    def fire():
        time.sleep(seconds)
        global sent
        sent = time.monotonic()
        os.kill(os.getpid(), signal.SIGINT)
    threading.Thread(target=fire, daemon=True).start()

interrupt_after(DELAY)
start = time.monotonic()
try:
    CALL
    print("finished without interruption", time.monotonic() - start)
    sys.exit(3)
except KeyboardInterrupt:
    latency = time.monotonic() - sent
    c0 = cpu()
    time.sleep(0.5)
    busy = cpu() - c0
    print(f"interrupted latency={latency:.3f} busy={busy:.3f} threads={threading.active_count()}")
"""

LONG_CALLS = {
    "sweep": (
        'd = asperity.default_scene(); d["program"]["points"] = 60\n'
        'asperity.sweep(d, {"surface.sigma": np.linspace(3e-9, 8e-9, 400)}, threads=2)'
    ),
    "bem": (
        "h = np.random.default_rng(0).normal(0, 1e-9, (512, 512))\n"
        "asperity.bem(h, 1e-7, 1e9, pressures=np.geomspace(1e5, 1e8, 40), tolerance=1e-14)"
    ),
}


@pytest.mark.parametrize("case", sorted(LONG_CALLS))
def test_ctrl_c_interrupts_a_long_call_within_a_second(case):
    call = textwrap.indent(LONG_CALLS[case], "    ").strip()
    code = INTERRUPTED.replace("DELAY", "2.0").replace("CALL", call)
    r = run_python(code, timeout=300)
    assert r.returncode == 0, (r.returncode, r.stdout, r.stderr[-2000:])
    line = r.stdout.strip().splitlines()[-1]
    fields = dict(kv.split("=") for kv in line.split()[1:])
    assert line.startswith("interrupted"), line
    assert float(fields["latency"]) < 1.0, line
    # No thread left computing: the process is idle once it has returned.
    assert float(fields["busy"]) < 0.1, line
    assert int(fields["threads"]) == 1, line


# -- arrays --------------------------------------------------------------


@pytest.mark.parametrize(
    "heights,dtype",
    [
        (np.ones((4, 4), dtype=bool), "bool"),
        (np.ones((4, 4), dtype=complex), "complex128"),
        (np.array([[1, None, 2]] * 3, dtype=object), "object"),
        (np.array([["2020-01-01"] * 3] * 3, dtype="datetime64[D]"), "datetime64[D]"),
        (np.array([["a"] * 3] * 3), "<U1"),
    ],
)
def test_non_real_heights_are_type_errors_naming_the_argument(heights, dtype):
    for call in (
        lambda: asperity.surface(heights, 1e-7),
        lambda: asperity.bem(heights, 1e-7, 1e9, pressures=[1e6]),
    ):
        with pytest.raises(TypeError) as e:
            call()
        msg = record(e)
        assert msg.startswith("heights: "), msg
        assert dtype in msg, msg


def test_masked_heights_are_a_type_error():
    m = np.ma.masked_array(np.ones((4, 4)), mask=np.eye(4))
    with pytest.raises(TypeError) as e:
        asperity.surface(m, 1e-7)
    msg = record(e)
    assert msg.startswith("heights: a masked array"), msg


@pytest.mark.parametrize("shape", [(10,), (4, 4, 4), (2, 5), ()])
def test_wrong_shapes_are_value_errors_with_the_shape(shape):
    h = np.zeros(shape)
    with pytest.raises(ValueError) as e:
        asperity.surface(h, 1e-7)
    msg = record(e)
    assert msg.startswith("heights: expected a 2-D array"), msg
    assert "at least 3 x 3" in msg
    want = f"({shape[0]},)" if len(shape) == 1 else "(" + ", ".join(map(str, shape)) + ")"
    assert f"got shape {want}" in msg, msg


def test_other_arrays_refuse_non_real_values_too():
    for call, name in [
        (lambda: asperity.fn("gaussian", 1.0, [True, False]), "h"),
        (lambda: asperity.spots([0j], [0.0], [1e-7], 2e-8), "x"),
        (lambda: asperity.persson(0.8, 1e5, 4e5, 4e8, 1e9, ["1e6"], h_rms=1e-8), "pressures"),
        (lambda: asperity.rough_sphere(10, [[1.0, 2.0]]), "d"),
    ]:
        with pytest.raises((TypeError, ValueError)) as e:
            call()
        msg = record(e)
        assert msg.startswith(f"{name}: "), msg


def test_strided_fortran_and_big_endian_maps_equal_the_contiguous_one():
    rng = np.random.default_rng(7)
    big = rng.normal(0, 1e-9, (64, 96))
    base = big[::2, ::3].copy()
    want = asperity.surface(base, 5e-8)
    for variant in (
        big[::2, ::3],  # strided view
        np.asfortranarray(base),
        base.astype(">f8"),
        base.astype(np.float32).astype(np.float64),  # same values only if exact
    ):
        if not np.array_equal(variant, base):
            continue
        # Bit for bit (rtol 0); the model-error arrays compared element-wise.
        assert_same(asperity.surface(variant, 5e-8), want, rtol=0.0)
    # An integer map equals its float copy.
    ints = (rng.normal(0, 100, (20, 20))).astype(np.int64)
    assert_same(asperity.surface(ints, 1.0), asperity.surface(ints.astype(float), 1.0), rtol=0.0)


def test_heights_arrive_bit_for_bit():
    # Tiny and subnormal heights: no text formatting on the way.
    h = np.array(
        [[1e-300, 5e-324, 2.5e-310], [np.nextafter(0, 1), 1e-300 / 3, -4.9e-324], [1e-308, 3e-320, 7e-301]]
    )
    got = asperity._asperity._heights_as_received(h)
    assert got.view(np.uint64).tolist() == h.view(np.uint64).tolist()
    # A list argument likewise: rough_sphere echoes its separations.
    d = [5e-324, 1e-300, 2.5e-310]
    out = asperity.rough_sphere(10, d)
    assert [s["d"] for s in out["states"]] == d


# -- sweeps --------------------------------------------------------------


def small_scene():
    d = asperity.default_scene()
    d["program"]["points"] = 20
    return d


def test_a_sweep_beyond_its_cpu_limit_is_refused_with_the_estimate():
    with pytest.raises(ValueError) as e:
        asperity.sweep(small_scene(), {"surface.sigma": np.linspace(3e-9, 8e-9, 50)}, max_cpu_seconds=1e-6)
    msg = record(e)
    assert msg.startswith("max_cpu_seconds: the first point took "), msg
    assert "the 49 others need an estimated" in msg and "s of CPU" in msg, msg
    with pytest.raises(ValueError) as e:
        asperity.sweep(small_scene(), {"surface.sigma": [3e-9]}, max_cpu_seconds=-1)
    record(e)


def test_sweep_progress_and_callback(capfd):
    rows = []
    t = asperity.sweep(
        small_scene(),
        {"surface.sigma": np.linspace(3e-9, 8e-9, 6)},
        progress=True,
        callback=rows.append,
    )
    err = capfd.readouterr().err
    assert "sweep: 6 points; the first took" in err, err
    assert "6/6 points (100 %)" in err, err
    assert "points/s" in err and "ETA" in err, err
    assert sorted(r["index"] for r in rows) == list(range(6))
    assert all(set(r) == set(t) for r in rows)
    for r in rows:
        i = r["index"]
        assert r["status"] == "ok"
        for k, v in r.items():
            want = t[k][i]
            assert v == want or (v != v and want != want), (k, v, want)


def test_a_callback_that_raises_stops_the_sweep():
    seen = []

    def stop(row):
        seen.append(row)
        raise LookupError("enough")

    with pytest.raises(LookupError, match="enough"):
        asperity.sweep(small_scene(), {"surface.sigma": np.linspace(3e-9, 8e-9, 200)}, callback=stop, threads=1)
    assert len(seen) == 1


# -- the typed command API underneath ----------------------------------


def test_no_command_takes_text_lists_or_law_names_as_strings():
    src = (REPO / "src" / "commands").glob("*.rs")
    text = "\n".join(p.read_text() for p in src)
    # No command-line list text parsed, no law names as String arguments
    # (CSV files are read as files: spots, punch-fit).
    for banned in ("fn parse_list", "positive_list", "list::parse", "parse_cycle", "pub law: String"):
        assert banned not in text, banned
    assert "LawKind::parse" not in text
    # The Python layer formats no numbers into text for the library.
    binding = "\n".join(p.read_text() for p in (REPO / "python" / "src").glob("*.rs"))
    assert 'format!("{x:?}")' not in binding and ".join(\",\")" not in binding
