"""The README's Python section runs as written."""
import os
import re
import subprocess
import sys

from conftest import SOURCE


def python_blocks(section):
    text = (SOURCE / "README.md").read_text()
    start = text.index(f"## {section}\n")
    end = text.find("\n## ", start + 1)
    return re.findall(r"```python\n(.*?)```", text[start:end if end >= 0 else None], re.S)


def test_readme_python_section_runs(corpus_model, tmp_path):
    blocks = python_blocks("Using acd from Python")
    assert blocks, "README.md has no python block under 'Using acd from Python'"
    script = tmp_path / "readme.py"
    script.write_text("\n".join(blocks))
    # From the repository root, as a reader would run it; the package comes from PYTHONPATH.
    p = subprocess.run([sys.executable, str(script)], cwd=SOURCE, capture_output=True, text=True, timeout=600,
                       env=dict(os.environ))
    assert p.returncode == 0, p.stdout + p.stderr
