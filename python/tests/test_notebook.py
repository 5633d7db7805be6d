"""examples/vibra.ipynb runs from top to bottom (so it cannot rot), and its
video and still show in the cells."""

import os
import subprocess
import sys
from pathlib import Path

import nbformat
from nbclient import NotebookClient


def test_the_example_notebook_runs(tmp_path, monkeypatch):
    # The notebook names the kernel scripts/setup registers for .venv, "vibra"
    # (in Jupyter's system kernel, vibra is not importable). The test registers
    # that kernel the same way, for this very interpreter, in a folder of its
    # own; the kernel inherits PYTHONPATH, so it imports this build.
    notebook = nbformat.read(Path(os.environ["VIBRA_SOURCE_DIR"]) / "examples" / "vibra.ipynb", as_version=4)
    assert notebook.metadata.kernelspec.name == "vibra"
    setup = (Path(os.environ["VIBRA_SOURCE_DIR"]) / "scripts" / "setup").read_text()
    assert "ipykernel install --user --name vibra" in setup
    subprocess.run([sys.executable, "-m", "ipykernel", "install", "--prefix", str(tmp_path / "kernels"),
                    "--name", "vibra", "--display-name", "Python (vibra)"], check=True, capture_output=True)
    monkeypatch.setenv("JUPYTER_PATH", str(tmp_path / "kernels" / "share" / "jupyter"))
    monkeypatch.setenv("JUPYTER_RUNTIME_DIR", str(tmp_path / "runtime"))
    monkeypatch.setenv("JUPYTER_PLATFORM_DIRS", "1")
    work = tmp_path / "work"
    work.mkdir()
    NotebookClient(notebook, kernel_name=notebook.metadata.kernelspec.name, timeout=300,
                   resources={"metadata": {"path": str(work)}}).execute()

    outputs = [output for cell in notebook.cells if cell.cell_type == "code" for output in cell.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    data = [o.get("data", {}) for o in outputs]
    assert any("data:video/mp4;base64," in d.get("text/html", "") for d in data)
    assert any("image/png" in d for d in data)
    assert any("<th>w_tilde</th>" in d.get("text/html", "") for d in data)
    assert (work / "pendulum.mp4").is_file() and (work / "pendulum_at_1.5.png").is_file()
