"""Progress on long runs: on a terminal, `experiment` shows on stderr the
condition, the object the LLM is asked about, the LLM calls and the time;
nothing with --json, --quiet, or on a pipe."""
import fcntl
import os
import re
import struct
import subprocess
import termios

from conftest import BINARY, SOURCE_DIR
from fake_llm import SlowLlmServer

SMALL_KITCHEN = SOURCE_DIR / "tests" / "experiment" / "data" / "small-kitchen.yaml"


def run_experiment(llm_url, *flags, stderr_on_terminal=True):
    """Runs the experiment with stdout on a pipe and stderr on a new
    pseudo-terminal (or a pipe); returns (stdout, what reached stderr)."""
    args = [str(BINARY), "experiment", "--scenario", str(SMALL_KITCHEN), "--conditions", "inst+search4+llm",
            "--llm", "openai:" + llm_url, *flags]
    env = dict(os.environ, COLUMNS="200")
    env.pop("APPRENTICE_LLM", None)
    if not stderr_on_terminal:
        done = subprocess.run(args, capture_output=True, text=True, env=env, timeout=120)
        assert done.returncode == 0, done.stderr
        return done.stdout, done.stderr
    controller, terminal = os.openpty()
    fcntl.ioctl(terminal, termios.TIOCSWINSZ, struct.pack("HHHH", 24, 200, 0, 0))
    try:
        process = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=terminal, stdin=subprocess.DEVNULL, env=env)
        os.close(terminal)
        terminal = -1
        stdout, _ = process.communicate(timeout=120)
        assert process.returncode == 0
        seen = b""
        while True:
            try:
                chunk = os.read(controller, 65536)
            except OSError:  # EIO: the terminal's last writer has gone
                break
            if not chunk:
                break
            seen += chunk
        return stdout.decode(), seen.decode(errors="replace")
    finally:
        os.close(controller)
        if terminal >= 0:
            os.close(terminal)


def test_on_a_terminal_a_progress_line_names_condition_object_calls_and_time():
    with SlowLlmServer(delay=0.2) as server:
        stdout, stderr = run_experiment(server.url)
    assert "inst+search4+llm" in stdout
    assert "\rinst+search4+llm (1 of 1): " in stderr
    assert "asking the LLM for a goal for the " in stderr
    assert re.search(r"\d+ LLM calls?, \d+ s", stderr)
    # Drawn in place and erased at the end: nothing is left on the line.
    assert "\r" in stderr and stderr.endswith("\r\x1b[K")


def test_no_progress_with_json_quiet_or_a_pipe():
    # Each run lasts well past the half second after which a line is drawn.
    with SlowLlmServer(delay=0.1) as server:
        for flags in (["--json"], ["--quiet"]):
            _, stderr = run_experiment(server.url, *flags)
            assert stderr == "", flags
        _, stderr = run_experiment(server.url, stderr_on_terminal=False)
        assert stderr == ""


def test_make_run_explains_the_table_and_how_to_turn_on_the_llm_conditions():
    env = dict(os.environ)
    env.pop("APPRENTICE_LLM", None)
    done = subprocess.run([str(BINARY), "experiment", "--scenario", str(SOURCE_DIR / "data/scenarios/tidy-kitchen.yaml")],
                          capture_output=True, text=True, env=env, check=True)
    assert "Relevant%: yes answers over yes/no questions" in done.stdout
    assert "--: the condition asks the LLM nothing" in done.stdout
    assert "Skipped for want of an LLM: search4+llm, inst+llm, inst+search2+llm, inst+search4+llm." in done.stdout
    assert "--llm SPEC or set APPRENTICE_LLM" in done.stdout


def test_json_is_an_array_with_one_object_per_condition_as_its_help_says():
    help_text = subprocess.run([str(BINARY), "experiment", "--help"], capture_output=True, text=True).stdout
    assert "JSON array with one object per condition" in help_text
    import json
    out = subprocess.run([str(BINARY), "experiment", "--scenario", str(SOURCE_DIR / "data/scenarios/tidy-kitchen.yaml"),
                          "--conditions", "instruction,inst+search4", "--json"],
                         capture_output=True, text=True, check=True).stdout
    parsed = json.loads(out)
    assert isinstance(parsed, list) and [r["condition"] for r in parsed] == ["instruction", "inst+search4"]
