"""docs/rl.md: its throughput table (in benchmarks/results/rl.md) is filled in and
its screenshot script draws.

Its code blocks run through the shared doc runner (tests/test_docs.py)."""

from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
DOC = ROOT / "docs" / "rl.md"
RESULTS = ROOT / "benchmarks" / "results" / "rl.md"


def test_the_throughput_table_is_filled_in() -> None:
    text = RESULTS.read_text()
    assert "THROUGHPUT_TABLE" not in text
    assert "| kge batched (make_vec) | 64 |" in text
    assert "benchmarks/results/rl.md" in DOC.read_text()


def test_the_screenshot_script_draws_both_envs(tmp_path: Path) -> None:
    import importlib.util

    script = DOC.parent / "rl_screenshot.py"
    spec = importlib.util.spec_from_file_location("rl_screenshot", script)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    out = module.main(tmp_path / "envs.png")
    data = out.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    assert int.from_bytes(data[16:20], "big") == 600 + 8 + 600  # two frames side by side
