"""The repository's source layout (issue 29): no import cycle among the
sibling modules of any crate, no source file over 600 lines and no
function over 120 (outside tests and the paper's studies). The checks are
the scripts a developer runs, scripts/module-cycles and scripts/long-code;
these tests run them in CI."""

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]


def script(name):
    return subprocess.run(
        [sys.executable, str(ROOT / "scripts" / name)],
        cwd=ROOT,
        capture_output=True,
        text=True,
    )


def test_no_crate_has_an_import_cycle_among_sibling_modules():
    done = script("module-cycles")
    assert done.returncode == 0, done.stdout + done.stderr


def test_no_source_file_passes_600_lines_nor_a_function_120():
    done = script("long-code")
    assert done.returncode == 0, done.stdout + done.stderr


def test_the_checks_find_what_they_look_for(tmp_path):
    # A cycle and a long function in a made-up crate are found.
    src = tmp_path / "crates" / "toy" / "src"
    src.mkdir(parents=True)
    (src / "lib.rs").write_text("mod a;\nmod b;\n")
    (src / "a.rs").write_text("use crate::b::B;\npub struct A;\n")
    body = "\n".join("    let _x = 1;" for _ in range(130))
    (src / "b.rs").write_text(
        "use crate::a::A;\npub struct B;\npub fn long() {\n" + body + "\n}\n"
    )
    cycles = subprocess.run(
        [sys.executable, str(ROOT / "scripts" / "module-cycles"), str(src)],
        capture_output=True,
        text=True,
    )
    assert cycles.returncode == 1 and "cycle among a, b" in cycles.stdout
    long = subprocess.run(
        [sys.executable, str(ROOT / "scripts" / "long-code")],
        cwd=tmp_path,
        capture_output=True,
        text=True,
    )
    assert long.returncode == 1 and "fn long: 132 lines" in long.stdout
