"""The testbed command line: --list and a single headless sample."""

import subprocess
import sys

from kge.testbed import all_samples
from kge.testbed.cli import main


def test_list_prints_one_sample_per_line_name_first(capsys) -> None:
    assert main(["--list"]) == 0
    lines = capsys.readouterr().out.strip().splitlines()
    assert [line.split("\t")[0] for line in lines] == [s.slug for s in all_samples()]


def test_unknown_sample_is_a_clear_error(capsys) -> None:
    assert main(["--headless", "--sample", "no-such-thing", "--frames", "1"]) == 2
    assert "no sample named 'no-such-thing'" in capsys.readouterr().err


def test_python_dash_m_kge_testbed_runs_one_sample_headless(tmp_path) -> None:
    shot = tmp_path / "hello.png"
    out = subprocess.run(
        [sys.executable, "-m", "kge", "testbed", "--headless", "--sample", "hello-world",
         "--frames", "60", "--screenshot", str(shot)],
        capture_output=True, text=True, timeout=120,
    )
    assert out.returncode == 0, out.stderr
    assert out.stdout.startswith("hello-world")
    assert shot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
