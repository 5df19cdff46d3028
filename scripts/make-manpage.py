#!/usr/bin/env python3
"""Writes apprentice's man page (roff) from its own --help: the program's
and every subcommand's. The build runs it (build/apprentice.1); read it
with `man -l build/apprentice.1`.

    scripts/make-manpage.py build/apprentice -o build/apprentice.1
"""
import argparse
import re
import subprocess
import sys

# What --help does not say, kept short; README.md and docs/cli.md say more.
EXIT_STATUS = [
    ("0", "success"),
    ("1", "the goal or task was not reached"),
    ("2", "bad input: a malformed file, flag or sentence; a missing file; a missing dependency for --plot"),
    ("3", "local storage failed or holds unreadable data"),
    ("4", "the LLM server is unavailable or timed out"),
    ("130", "interrupted"),
]
ENVIRONMENT = [
    ("APPRENTICE_LLM", "the LLM backend spec when --llm is not given, e.g. openai:http://127.0.0.1:8080/v1"),
    ("OPENAI_MODEL, OPENAI_API_KEY, OPENAI_BASE_URL", "defaults for --llm-model, --llm-api-key and openai without a URL"),
    ("APPRENTICE_PYTHON", "the Python that draws --plot figures (default /usr/bin/python3)"),
]


def roff(text):
    text = text.replace("\\", "\\e")
    text = text.replace("-", "\\-")
    if text.startswith((".", "'")):
        text = "\\&" + text
    return text


def run_help(program, *words):
    done = subprocess.run([program, *words, "--help"], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit("make-manpage: %s %s --help failed: %s" % (program, " ".join(words), done.stderr.strip()))
    return done.stdout


def sections(help_text):
    """Splits CLI11's help into its description, and its 'Options:',
    'Positionals:' and 'Subcommands:' entries as (term, description)."""
    description, current, found = [], None, {}
    for line in help_text.splitlines():
        header = re.match(r"^([A-Z][A-Za-z ]*):\s*$", line)
        if header:
            current = header.group(1)
            found[current] = []
            continue
        if current is None:
            if line.strip() and not line.startswith("Usage:"):
                description.append(line.strip())
            continue
        if not line.strip():
            continue
        entry = re.match(r"^ {1,6}(\S.*?)(?: {2,}(.*))?$", line)
        if entry:
            found[current].append([entry.group(1).strip(), (entry.group(2) or "").strip()])
        elif found[current]:  # a wrapped description
            found[current][-1][1] += " " + line.strip()
    return " ".join(description), found


def option_term(term):
    """'-v,--verbose' -> bold flags; 'TEXT REQUIRED' -> italic value."""
    parts = term.split(" ", 1)
    flags = ", ".join("\\fB%s\\fR" % roff(f) for f in parts[0].split(","))
    if len(parts) > 1:
        flags += " \\fI%s\\fR" % roff(parts[1])
    return flags


def entries(pairs, term=option_term):
    out = []
    for name, text in pairs:
        out += [".TP", term(name), roff(text)]
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("program")
    parser.add_argument("-o", "--output", required=True)
    args = parser.parse_args()
    version = subprocess.run([args.program, "--version"], capture_output=True, text=True).stdout.strip()
    description, top = sections(run_help(args.program))
    name, _, summary = description.partition(": ")
    lines = ['.TH APPRENTICE 1 "" "%s" "User Commands"' % roff(version or "apprentice"),
             ".SH NAME", "apprentice \\- " + roff(summary or description),
             ".SH SYNOPSIS", ".B apprentice", "[\\fIOPTIONS\\fR] \\fICOMMAND\\fR [\\fICOMMAND OPTIONS\\fR]",
             ".SH DESCRIPTION", roff(description),
             "Every command has \\fB\\-\\-help\\fR; this page is made from them.",
             ".SH OPTIONS"]
    lines += entries(top.get("Options", []))
    lines.append(".SH COMMANDS")
    for command, _ in top.get("Subcommands", []):
        command = command.split()[0]
        text, found = sections(run_help(args.program, command))
        lines += ['.SS "apprentice %s"' % roff(command), roff(text)]
        lines += entries(found.get("Positionals", []))
        lines += entries(found.get("Options", []))
    lines += [".SH EXIT STATUS"] + entries(EXIT_STATUS, term=lambda t: "\\fB%s\\fR" % t)
    lines += [".SH ENVIRONMENT"] + entries(ENVIRONMENT, term=lambda t: "\\fB%s\\fR" % roff(t))
    lines += [".SH SEE ALSO", "The README and docs/ of the source: docs/cli.md, docs/experiment.md, docs/python.md."]
    with open(args.output, "w", encoding="utf-8") as out:
        out.write("\n".join(lines) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
