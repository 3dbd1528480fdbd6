"""Shared by the Python module's tests: the command line of the same build, run as a user would."""

import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def cli():
    """Runs `springlab ARGS` from this build; returns the CompletedProcess (text)."""
    exe = os.environ.get("SPRINGLAB_EXECUTABLE")
    if not exe:
        pytest.skip("this build has no springlab executable (SPRINGLAB_BUILD_APP=OFF)")

    def run(*args):
        return subprocess.run([exe, *map(str, args)], capture_output=True, text=True, timeout=240)

    return run


def cli_message(result):
    """The one line the command line prints for bad input, without its 'springlab: ' prefix."""
    lines = [line for line in result.stderr.splitlines() if line.startswith("springlab: ")]
    assert lines, f"no message on stderr: {result.stderr!r}"
    return lines[-1][len("springlab: "):]
