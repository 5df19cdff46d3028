"""The experiment as a figure, like the paper's Figure 3: per condition, the
instructions, words and yes/no answers the instructor gave, and the task's
completion, with the paper's Table 3 figures beside ours.

    python3 -m apprentice.plot results.json -o fig.svg      # results of `apprentice experiment --json`
    python3 -m apprentice.plot --scenario data/scenarios/tidy-kitchen.yaml -o fig.png

`apprentice experiment --plot fig.svg` runs this. In an SVG each condition's
panel is a group with the id "condition-<name>" ('+' written as '-').
Exit status: 0 drawn; 2 bad arguments or results; 3 matplotlib is missing.
"""

import argparse
import json
import sys

import apprentice

MEASURES = [
    # (key, label, scale): a bar's height is its value over the scale.
    ("instructions", "Instructions", None),
    ("words", "Words", None),
    ("yes_no", "Yes/No", None),
    ("completion_rate", "Completion %", 100.0),
]
OURS_COLOR = "#2b6cb0"
PAPER_COLOR = "#b8c2cc"
EXIT_MISSING_MATPLOTLIB = 3


def condition_id(name):
    """The SVG group id of a condition's panel."""
    return "condition-" + "".join(c if c.isalnum() or c in "-_." else "-" for c in name)


def _scales(results, paper):
    """Each count measure is drawn relative to its largest value in the
    figure (ours and the paper's), so that panels compare at a glance."""
    scales = {}
    for key, _, fixed in MEASURES:
        values = [r[key] for r in results] + [p[key] for p in paper.values()]
        scales[key] = fixed or max([v for v in values if v is not None] + [1])
    return scales


def draw(results, output, with_paper=True, title=None):
    """Draws `results` (a list of dicts as apprentice.experiment() returns)
    into `output` (.svg or .png)."""
    import matplotlib

    matplotlib.use("Agg")
    matplotlib.rcParams.update({"svg.fonttype": "none", "svg.hashsalt": "apprentice", "font.size": 9})
    import matplotlib.pyplot as plt

    if not results:
        raise ValueError("no results to draw")
    paper = {}
    if with_paper:
        for r in results:
            row = apprentice.paper_row(r["condition"])
            if row is not None:
                paper[r["condition"]] = row
    scales = _scales(results, paper)
    columns = min(len(results), 3)
    rows = (len(results) + columns - 1) // columns
    figure, axes = plt.subplots(rows, columns, figsize=(3.4 * columns, 2.9 * rows), squeeze=False, sharey=True)
    width = 0.38 if paper else 0.6
    for index, axis in enumerate(axes.flat):
        if index >= len(results):
            axis.set_visible(False)
            continue
        result = results[index]
        name = result["condition"]
        axis.set_gid(condition_id(name))
        series = [("ours", result, OURS_COLOR, "")]
        if name in paper:
            series.append(("paper", paper[name], PAPER_COLOR, "//"))
        for offset, (label, values, color, hatch) in enumerate(series):
            shift = (offset - (len(series) - 1) / 2) * width
            for position, (key, _, _) in enumerate(MEASURES):
                value = values[key]
                height = (value or 0) / scales[key]
                axis.bar(position + shift, height, width, color=color, hatch=hatch, edgecolor="#4a5568",
                         linewidth=0.5, label=label if position == 0 else None)
                text = "%g" % round(value or 0, 1)
                axis.text(position + shift, height + 0.02, text, ha="center", va="bottom", fontsize=7)
        axis.set_title(name, fontsize=10)
        axis.set_xticks(range(len(MEASURES)))
        axis.set_xticklabels([label for _, label, _ in MEASURES], fontsize=8)
        axis.set_ylim(0, 1.18)
        axis.set_yticks([])
        for side in ("top", "right", "left"):
            axis.spines[side].set_visible(False)
    handles = [plt.Rectangle((0, 0), 1, 1, color=OURS_COLOR)]
    labels = ["apprentice"]
    if paper:
        handles.append(plt.Rectangle((0, 0), 1, 1, facecolor=PAPER_COLOR, hatch="//", edgecolor="#4a5568"))
        labels.append("the paper (Table 3)")
    figure.legend(handles, labels, loc="lower center", ncol=2, frameon=False)
    figure.suptitle(title or "The experiment: what the instructor said, and how much of the task was done")
    figure.text(0.5, 0.065, "Bar heights: each measure relative to its largest value in the figure; "
                "the numbers are the values.", ha="center", fontsize=7, color="#4a5568")
    figure.tight_layout(rect=(0, 0.09, 1, 0.95))
    figure.savefig(output, metadata={"Date": None} if str(output).endswith(".svg") else None)
    plt.close(figure)


def _load_results(path):
    text = sys.stdin.read() if path == "-" else open(path, encoding="utf-8").read()
    results = json.loads(text)
    if isinstance(results, dict):
        results = [results]
    if not isinstance(results, list) or not all(isinstance(r, dict) and "condition" in r for r in results):
        raise ValueError("%s: expected the JSON array that `apprentice experiment --json` prints" % path)
    return results


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m apprentice.plot", description=__doc__.split("\n\n")[0])
    parser.add_argument("results", nargs="?", help="results JSON of `apprentice experiment --json` ('-': stdin)")
    parser.add_argument("--scenario", help="run the experiment on this scenario instead of reading results")
    parser.add_argument("--conditions", help="with --scenario: comma-separated conditions (default: all that can run)")
    parser.add_argument("--llm", help="with --scenario: the LLM backend spec (default: $APPRENTICE_LLM)")
    parser.add_argument("-o", "--output", required=True, help="the figure: FILE.svg or FILE.png")
    parser.add_argument("--no-paper", action="store_true", help="leave out the paper's figures")
    parser.add_argument("--title", help="the figure's title")
    args = parser.parse_args(argv)
    if not args.output.endswith((".svg", ".png")):
        parser.error("the figure must be an .svg or .png file")
    if (args.results is None) == (args.scenario is None):
        parser.error("give a results file or --scenario")
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        print("apprentice.plot: the figure needs matplotlib: sudo apt-get install python3-matplotlib",
              file=sys.stderr)
        return EXIT_MISSING_MATPLOTLIB
    try:
        if args.scenario:
            conditions = args.conditions.split(",") if args.conditions else None
            results = apprentice.experiment(args.scenario, conditions=conditions, llm=args.llm)
        else:
            results = _load_results(args.results)
        draw(results, args.output, with_paper=not args.no_paper, title=args.title)
    except (OSError, ValueError, KeyError, apprentice.Error) as error:
        print("apprentice.plot: %s" % error, file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
