"""The notebook-style example of ``docs/python.md`` runs: every block fenced as ```python
there is executed in order in one namespace, from the repository root as the page says (model
files are named by their paths there); blocks that need a real cluster are fenced as ```py and
only shown."""

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
DOC = ROOT / "docs" / "python.md"


def test_the_examples_in_docs_python_md_run(monkeypatch):
    monkeypatch.chdir(ROOT)
    blocks = re.findall(r"^```python\n(.*?)^```", DOC.read_text(), flags=re.S | re.M)
    assert len(blocks) >= 3
    namespace: dict = {}
    for block in blocks:
        exec(compile(block, str(DOC), "exec"), namespace)
    # the example's last table: a sweep with both outcomes named
    df = namespace["df"]
    assert len(df) > 0 and "status" in df.columns
