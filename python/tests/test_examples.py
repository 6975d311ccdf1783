"""Every ```python block of python/README.md and of the package's module docstrings runs."""

from __future__ import annotations

import importlib
import inspect
import re
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[1] / "README.md"
#: Modules whose docstring shows runnable code.
MODULES = ["touchline", "touchline.vector", "touchline.compat.gfootball", "touchline.record_replay"]
BLOCK = re.compile(r"^```python\n(.*?)^```", re.MULTILINE | re.DOTALL)


def blocks(text: str) -> list[str]:
    return [match.group(1) for match in BLOCK.finditer(text)]


README_BLOCKS = [
    pytest.param(code, id=f"README.md#{i}") for i, code in enumerate(blocks(README.read_text()))
]


def test_readme_has_examples() -> None:
    assert len(README_BLOCKS) >= 4


@pytest.mark.parametrize("code", README_BLOCKS)
def test_readme_example(code: str, tmp_path, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    exec(compile(code, "README.md", "exec"), {"__name__": "__example__"})


@pytest.mark.parametrize("module", MODULES)
def test_docstring_examples(module: str, tmp_path, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    doc = inspect.cleandoc(importlib.import_module(module).__doc__ or "")
    found = blocks(doc)
    assert found, f"{module}'s docstring has no example"
    for i, code in enumerate(found):
        exec(compile(code, f"{module} docstring #{i}", "exec"), {"__name__": "__example__"})
