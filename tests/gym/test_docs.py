"""The runnable examples of docs/rl.md run (and their asserts hold)."""

import re
from pathlib import Path

import pytest

DOC = Path(__file__).resolve().parents[2] / "docs" / "rl.md"
BLOCKS = re.findall(r"<!-- runnable -->\n```python\n(.*?)```", DOC.read_text(), re.S)


def test_the_page_has_runnable_examples() -> None:
    assert len(BLOCKS) >= 3


@pytest.mark.parametrize("code", BLOCKS, ids=[f"block{i}" for i in range(len(BLOCKS))])
def test_rl_doc_example_runs(code: str) -> None:
    exec(compile(code, "docs/rl.md", "exec"), {"__name__": "rl_doc"})


def test_the_throughput_table_is_filled_in() -> None:
    text = DOC.read_text()
    assert "THROUGHPUT_TABLE" not in text
    assert "| kge batched (make_vec) | 64 |" in text


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
