"""The README's two commands and CI stay in step."""

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def readme_commands():
    text = (ROOT / "README.md").read_text()
    return re.findall(r"```bash\n(.*?)\n```", text, flags=re.S)


def test_readme_opens_with_exactly_two_commands():
    commands = readme_commands()
    assert len(commands) == 2
    setup_and_run, tests = commands
    assert setup_and_run.strip().endswith("ringchain paper")
    assert tests.strip().endswith("pytest")
    # Each command sets up on its own, so it works without the other having run.
    for command in commands:
        assert command.startswith("python3 -m venv .venv && .venv/bin/pip install -e")


def test_ci_runs_the_readme_test_command():
    ci = (ROOT / ".ci" / "run").read_text()
    assert readme_commands()[1].strip() in ci.splitlines()


def test_readme_ten_lines_run(capsys):
    # The README's Python example is code a reader copies: it must run against the package as it is.
    (example,) = re.findall(r"```python\n(.*?)\n```", (ROOT / "README.md").read_text(), flags=re.S)[:1]
    exec(compile(example, "README.md", "exec"), {})
    assert capsys.readouterr().out.count("\n") == 4  # one line per print
