# SPDX-License-Identifier: Apache-2.0
# Shared fixtures of the Python module's tests: the built `ifsfx` command (IFSFX_CLI, set by
# CTest) and a source image made here, so that no test depends on files outside the tree.
import os
import signal
import subprocess
import threading
import time

import numpy as np
import pytest

import ifsfx


def pytest_collection_modifyitems(session, config, items):
    # A test file that collects fewer tests than it declares fails the run: a file whose tests
    # were silently skipped by a rename or an import error must not pass.
    declared = {}
    for item in items:
        module = item.module
        declared[module.__file__] = getattr(module, "EXPECTED_TESTS", 1)
    counts = {}
    for item in items:
        counts[item.module.__file__] = counts.get(item.module.__file__, 0) + 1
    for path, expected in declared.items():
        if counts[path] < expected:
            raise pytest.UsageError(f"{path}: collected {counts[path]} tests, expected {expected}")
    if not items:
        raise pytest.UsageError("no tests collected")


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("IFSFX_CLI")
    if not path:
        pytest.fail("IFSFX_CLI: the built ifsfx command, set by CTest (got nothing)")
    return path


def run_cli(cli, *args):
    """Runs `ifsfx ARGS`, returns the completed process (stdout, stderr as text)."""
    return subprocess.run([cli, *args], capture_output=True, text=True, check=False)


def cli_image(cli, tmp_path, *args, name="cli.png"):
    """`ifsfx ARGS -o TMP/name`, the written image read back by the module's reader."""
    out = tmp_path / name
    done = run_cli(cli, *args, "-q", "-o", str(out))
    assert done.returncode == 0, done.stderr
    return ifsfx.read_image(str(out))


@pytest.fixture(scope="session")
def photo(tmp_path_factory):
    """A 160×120 BGR uint8 image with structure in every channel, and its PNG file."""
    y, x = np.mgrid[0:120, 0:160]
    image = np.stack([(x * 255 // 159), (y * 255 // 119), ((x ^ y) & 0xFF)], axis=-1)
    image = image.astype(np.uint8)
    path = tmp_path_factory.mktemp("photo") / "photo.png"
    ifsfx.write_image(str(path), image)
    return image, path


# How soon a KeyboardInterrupt must follow SIGINT: the target is 0.5 s (typically 10-50 ms); the
# bound is generous for a loaded CI machine running other tests on the same cores, as the
# command's own signal tests (tests/cli/safety_cli_test.sh) allow.
STOP_BOUND = float(os.environ.get("IFSFX_STOP_BOUND_MS", "2000")) / 1000


def interrupted_after(delay, work):
    """Runs work(), sending SIGINT to this process `delay` s after it starts; returns the
    seconds from the signal to the KeyboardInterrupt."""
    sent = []

    def send():
        sent.append(time.monotonic())
        os.kill(os.getpid(), signal.SIGINT)

    timer = threading.Timer(delay, send)
    timer.start()
    try:
        work()
    except KeyboardInterrupt:
        return time.monotonic() - sent[0]
    finally:
        timer.cancel()
    raise AssertionError("the work finished before the interrupt")
