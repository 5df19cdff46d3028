"""Bash completion (completions/apprentice.bash) and the man page made
from --help (build/apprentice.1)."""
import re
import shutil
import subprocess

import pytest

from conftest import BINARY, SOURCE_DIR

COMPLETION = SOURCE_DIR / "completions" / "apprentice.bash"
MANPAGE = BINARY.parent / "apprentice.1"


def complete(line, cwd=None):
    """What Tab offers after `line` (the last word is the one completed)."""
    words = line.split(" ")
    script = """
source {completion}
apprentice() {{ "{binary}" "$@"; }}
COMP_WORDS=({words})
COMP_CWORD={cword}
_apprentice
printf '%s\\n' "${{COMPREPLY[@]}}"
""".format(completion=COMPLETION, binary=BINARY,
           words=" ".join("'%s'" % w for w in words), cword=len(words) - 1)
    done = subprocess.run(["bash", "-c", script], capture_output=True, text=True, cwd=cwd, check=True)
    return sorted(w for w in done.stdout.splitlines() if w)


def test_completes_subcommands_from_the_programs_help():
    words = complete("apprentice ")
    assert {"world", "plan", "experiment", "teach", "run", "knowledge", "interpret"} <= set(words)
    assert complete("apprentice ex") == ["experiment", "export-pddl"]


def test_completes_a_subcommands_flags():
    flags = complete("apprentice experiment --")
    assert {"--scenario", "--conditions", "--json", "--plot", "--llm", "--generalization"} <= set(flags)
    assert "--goal" not in flags
    assert complete("apprentice plan --d") == ["--depth"]


def test_completes_values_of_known_form(tmp_path):
    assert complete("apprentice experiment --generalization ") == ["full", "paper"]
    assert complete("apprentice experiment --conditions inst+search4,inst+s") == ["inst+search4,inst+search2+llm",
                                                                                 "inst+search4,inst+search4",
                                                                                 "inst+search4,inst+search4+llm"]
    (tmp_path / "kitchen.yaml").write_text("")
    (tmp_path / "notes.txt").write_text("")
    (tmp_path / "store.sqlite").write_text("")
    assert complete("apprentice world --scenario ", cwd=tmp_path) == ["kitchen.yaml"]
    assert complete("apprentice run --scenario kitchen.yaml --knowledge ", cwd=tmp_path) == ["store.sqlite"]


def test_completes_every_llm_backend_the_program_knows():
    # Issue 25: a second, stale list of backends drifts. The schemes Tab
    # offers are those --help lists (the llm module's one list).
    helped = subprocess.run([str(BINARY), "experiment", "--help"], capture_output=True, text=True, check=True).stdout
    line = " ".join(helped.split())
    listed = line[line.index("LLM backend: ") + len("LLM backend: "):line.index("(default: $APPRENTICE_LLM)")]
    schemes = {form.strip().split(":")[0] for form in listed.split(", ") if form.strip()}
    offered = {word.split(":")[0] for word in complete("apprentice experiment --llm ")}
    assert schemes == offered
    assert "openai-chat" in offered


def test_the_man_page_has_every_command_and_flag():
    page = MANPAGE.read_text()
    assert page.startswith(".TH APPRENTICE 1")
    for section in ("NAME", "SYNOPSIS", "DESCRIPTION", "OPTIONS", "COMMANDS", "EXIT STATUS", "ENVIRONMENT"):
        assert re.search(r"^\.SH %s$" % section, page, re.M), section
    for command in ("world", "plan", "export\\-pddl", "interpret", "experiment", "teach", "run", "knowledge"):
        assert '.SS "apprentice %s"' % command in page, command
    help_text = subprocess.run([str(BINARY), "experiment", "--help"], capture_output=True, text=True).stdout
    for flag in re.findall(r"^ +(?:-\w,)?(--[\w-]+)", help_text, re.M):
        assert "\\fB%s\\fR" % flag.replace("-", "\\-") in page, flag


@pytest.mark.skipif(shutil.which("groff") is None, reason="groff is not installed (Debian: groff-base)")
def test_the_man_page_renders_without_warnings():
    done = subprocess.run(["groff", "-man", "-Tutf8", "-ww", "-z", str(MANPAGE)], capture_output=True, text=True)
    assert done.returncode == 0
    assert done.stderr == ""
