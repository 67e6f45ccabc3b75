"""The examples of docs/python.md (and README.md's) run as written: every
```python block of the page, in order, in one namespace (a block may use
what an earlier one defined), from a scratch folder that sees the source
tree's tableaux/ as ./tableaux (so that the examples' paths are those of
the top of the source tree and nothing they write lands in it), with
matplotlib drawing off screen (MPLBACKEND=Agg).  A block that fails by
importing an optional package that is not installed (matplotlib, scipy,
mpmath) skips the rest of the page rather than failing."""
import contextlib
import io
import os
import re

import pytest

OPTIONAL = {"matplotlib", "scipy", "mpmath"}


def blocks(path):
    """The ```python blocks of a Markdown file: (first line number, code)."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    found = []
    for m in re.finditer(r"^```python\n(.*?)^```\s*$", text, flags=re.S | re.M):
        found.append((text.count("\n", 0, m.start()) + 2, m.group(1)))
    return found


def test_the_pages_have_examples(source_dir):
    assert len(blocks(os.path.join(source_dir, "docs", "python.md"))) >= 5
    assert len(blocks(os.path.join(source_dir, "README.md"))) >= 1


@pytest.mark.parametrize("page", ["docs/python.md", "README.md"])
def test_examples_run(source_dir, tmp_path, monkeypatch, page):
    doc = os.path.join(source_dir, page)
    os.symlink(os.path.join(source_dir, "tableaux"), tmp_path / "tableaux")
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    namespace = {"__name__": "__docs__"}
    for line, code in blocks(doc):
        out = io.StringIO()
        try:
            with contextlib.redirect_stdout(out):
                exec(compile(code, f"{doc}:{line}", "exec"), namespace)
        except ModuleNotFoundError as e:
            if e.name in OPTIONAL:
                pytest.skip(f"{page}:{line} needs {e.name}, which is not installed")
            raise
