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
