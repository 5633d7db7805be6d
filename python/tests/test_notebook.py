"""examples/vibra.ipynb runs from top to bottom (so it cannot rot), and its
video and still show in the cells."""

import json
import os
import sys
from pathlib import Path

import nbformat
from nbclient import NotebookClient


def test_the_example_notebook_runs(tmp_path, monkeypatch):
    # A kernel for this very interpreter, whatever python3 the machine's
    # default kernel names; it inherits PYTHONPATH, so it imports this build.
    spec = tmp_path / "jupyter" / "kernels" / "vibra-test"
    spec.mkdir(parents=True)
    (spec / "kernel.json").write_text(json.dumps({
        "argv": [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"],
        "display_name": "vibra test", "language": "python"}))
    monkeypatch.setenv("JUPYTER_PATH", str(tmp_path / "jupyter"))
    monkeypatch.setenv("JUPYTER_RUNTIME_DIR", str(tmp_path / "runtime"))
    monkeypatch.setenv("JUPYTER_PLATFORM_DIRS", "1")
    notebook = nbformat.read(Path(os.environ["VIBRA_SOURCE_DIR"]) / "examples" / "vibra.ipynb", as_version=4)
    work = tmp_path / "work"
    work.mkdir()
    NotebookClient(notebook, kernel_name="vibra-test", timeout=300,
                   resources={"metadata": {"path": str(work)}}).execute()

    outputs = [output for cell in notebook.cells if cell.cell_type == "code" for output in cell.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    data = [o.get("data", {}) for o in outputs]
    assert any("data:video/mp4;base64," in d.get("text/html", "") for d in data)
    assert any("image/png" in d for d in data)
    assert any("<th>w_tilde</th>" in d.get("text/html", "") for d in data)
    assert (work / "pendulum.mp4").is_file() and (work / "pendulum_at_1.5.png").is_file()
