"""The README's code runs as written: every ```python block of README.md,
in order, in one namespace (a later block may use an earlier one's names),
from a scratch folder that sees the repository's examples/ where the
README's paths expect them, so its results land in the scratch folder."""

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]
README = ROOT / "README.md"


def python_blocks(text):
    """The bodies of the ```python fenced blocks of a Markdown text, with
    the line each starts on."""
    blocks = []
    for m in re.finditer(r"^```python\n(.*?)^```$", text, re.S | re.M):
        blocks.append((text.count("\n", 0, m.start()) + 2, m.group(1)))
    return blocks


def test_the_readme_has_python_snippets():
    blocks = python_blocks(README.read_text())
    # The Python package's and the coupling's.
    assert len(blocks) >= 2
    assert any("stancf.Simulation(" in code for _, code in blocks)
    assert any("stancf.run(" in code for _, code in blocks)


def test_the_readme_python_snippets_run(tmp_path, monkeypatch):
    (tmp_path / "examples").symlink_to(ROOT / "examples")
    monkeypatch.chdir(tmp_path)
    namespace = {"__name__": "readme"}
    for line, code in python_blocks(README.read_text()):
        try:
            exec(compile(code, "README.md, block at line %d" % line, "exec"), namespace)
        except Exception as e:
            pytest.fail("README.md, the python block at line %d: %s: %s"
                        % (line, type(e).__name__, e))


def test_the_coupling_examples_instructions_use_the_venv_and_write_outside_the_root():
    text = (ROOT / "examples" / "coupling" / "README.md").read_text()
    commands = [line for m in re.finditer(r"^```sh\n(.*?)^```$", text, re.S | re.M)
                for line in m.group(1).splitlines()]
    # Python is the virtual environment's, where stancf is installed.
    assert not any(re.match(r"\s*python3? ", c) for c in commands), commands
    assert any(c.startswith(".venv/bin/python examples/coupling/oc4_surge.py") for c in commands)
    # The C program and the figure go under target/ and out/, which git
    # ignores, not into the repository's root.
    assert any("-o target/examples/oc4_surge" in c for c in commands), commands
    assert any("--plot out/" in c for c in commands), commands
    assert not any(re.search(r"-o oc4_surge\b|\./oc4_surge\b", c) for c in commands), commands
