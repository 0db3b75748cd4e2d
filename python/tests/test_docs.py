"""The notebook-style example of ``docs/python.md`` runs: every block fenced as ```python
there is executed in order in one namespace (blocks that need a real cluster are fenced as
```py and only shown)."""

import re
from pathlib import Path

DOC = Path(__file__).resolve().parents[2] / "docs" / "python.md"


def test_the_examples_in_docs_python_md_run():
    blocks = re.findall(r"^```python\n(.*?)^```", DOC.read_text(), flags=re.S | re.M)
    assert len(blocks) >= 3
    namespace: dict = {}
    for block in blocks:
        exec(compile(block, str(DOC), "exec"), namespace)
    # the example's last table: a sweep with both outcomes named
    df = namespace["df"]
    assert len(df) > 0 and "status" in df.columns
