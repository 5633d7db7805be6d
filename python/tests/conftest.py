"""Shared fixtures: the command-line vibra (to compare with) and a scratch directory."""

import os
import subprocess

import pytest


@pytest.fixture
def cli():
    """Runs build/vibra with arguments; returns the CompletedProcess (text)."""
    exe = os.environ.get("VIBRA_EXE")
    if not exe:
        pytest.fail("VIBRA_EXE is not set: run the Python tests through ctest")

    def run(*args):
        return subprocess.run([exe, *args], capture_output=True, text=True)

    return run


@pytest.fixture
def in_tmp(tmp_path, monkeypatch):
    """Works in a fresh temporary directory (outputs land there)."""
    monkeypatch.chdir(tmp_path)
    return tmp_path
