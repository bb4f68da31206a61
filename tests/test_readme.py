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


def test_citation_names_the_package_and_the_paper():
    # Issue 24, item 17: a CITATION.cff (Citation File Format 1.2.0) in step with pyproject.toml.
    import yaml

    try:
        import tomllib
    except ImportError:  # Python 3.10
        import tomli as tomllib

    citation = yaml.safe_load((ROOT / "CITATION.cff").read_text())
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    assert {"cff-version", "message", "title", "authors"} <= set(citation)  # the fields CFF 1.2.0 requires
    assert citation["cff-version"] == "1.2.0" and citation["title"].startswith(project["name"])
    assert citation["version"] == project["version"] and citation["license"] == project["license"]["text"]
    (paper,) = citation["references"]
    assert paper["title"] == "Nonlinear Wave Propagation in 1D Polycatenated Ring Chains"
    assert [a["family-names"] for a in paper["authors"]] == ["Xiong", "Yanagi", "Zhou", "Daraio"]
    assert paper["title"] in (ROOT / "README.md").read_text().replace("*", "")


def test_changelog_opens_with_the_unreleased_changes():
    lines = (ROOT / "CHANGELOG.md").read_text().splitlines()
    assert lines[0] == "# Changelog"
    sections = [line for line in lines if line.startswith("## ")]
    assert sections and sections[0] == "## Unreleased"
