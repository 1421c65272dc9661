"""Errata of the four texts: every place where they disagree with each other or with arithmetic, with
the consequence computed here (from workflow/report/errata.yaml) and the test that shows it."""

import importlib
import textwrap

import numpy as np
import pandas as pd
import yaml

NUMPY_NAMES = ("pi", "sqrt", "cos", "sin", "tan", "arccos", "radians", "degrees", "log", "exp",
               "array", "dot", "maximum")
COLUMNS = ["text", "location", "printed", "correct", "consequence", "value", "test"]


def load_errata(path):
    """The errata file: its rows and the namespace (numpy + library imports) they evaluate in."""
    data = yaml.safe_load(open(path))
    namespace = {name: getattr(np, name) for name in NUMPY_NAMES} | {"norm": np.linalg.norm}
    for dotted in data["imports"]:
        module, _, name = dotted.rpartition(".")
        namespace[name] = getattr(importlib.import_module(module), name)
    return data, namespace


def evaluate(row, namespace, variables):
    """Evaluate a row's ``let`` expressions in order; return (consequence text, value, names)."""
    scope = dict(variables)
    for name, expression in row["let"].items():
        try:
            value = eval(expression, {"__builtins__": {}, **namespace}, scope)  # noqa: S307
        except Exception as err:
            raise ValueError(f"errata row {row['location']!r}: let {name} = {expression!r}: "
                             f"{err}") from None
        scope[name] = float(value) if np.ndim(value) == 0 else value
    return row["consequence"].format(**scope), scope[row["value"]], scope


def errata_table(path, variables):
    """The errata as a DataFrame with the columns of :data:`COLUMNS`."""
    data, namespace = load_errata(path)
    records = []
    for row in data["rows"]:
        consequence, value, _ = evaluate(row, namespace, variables)
        records.append({"text": data["texts"][row["text"]], "location": row["location"],
                        "printed": row["printed"], "correct": row["correct"],
                        "consequence": consequence, "value": value, "test": row["test"]})
    return pd.DataFrame(records, columns=COLUMNS)


def render(table, png, pdf):
    from reflectance.io.figures import new_figure, savefig

    widths = {"text": 16, "location": 34, "printed": 48, "correct": 60, "consequence": 60,
              "test": 52}
    xs = np.cumsum([0.004] + [0.00345 * (w + 2) for w in list(widths.values())[:-1]])
    short = table.assign(text=table.text.str.split(" (", regex=False).str[0],
                         test=table.test.str.replace("::", ":: "))
    cells = [[textwrap.wrap(str(r[c]), w, break_long_words=False) or [""]
              for c, w in widths.items()] for _, r in short.iterrows()]
    heights = [max(len(c) for c in row) for row in cells]
    fig = new_figure(24, 0.9 + 0.155 * (sum(heights) + 0.6 * len(heights)))
    ax = fig.add_axes((0.0, 0.0, 1.0, 1.0 - 0.55 / fig.get_figheight()))
    ax.set_axis_off()
    total = sum(heights) + 0.6 * len(heights)
    ax.set_xlim(0, 1)
    ax.set_ylim(total + 1.6, -1.6)
    for x, title in zip(xs, ("Text", "Location", "As printed", "Correct / other text",
                             "Consequence (computed)", "Test that shows it")):
        ax.text(x, -0.8, title, fontsize=9, fontweight="bold", va="center")
    y = 0.0
    for i, (row, h) in enumerate(zip(cells, heights)):
        if i % 2 == 0:
            ax.axhspan(y - 0.3, y + h + 0.3 - 0.6 + 0.3, color="0.93", lw=0)
        for j, (x, lines) in enumerate(zip(xs, row)):
            ax.text(x, y, "\n".join(lines), fontsize=7.5, va="top", linespacing=1.25,
                    family="monospace" if j == len(xs) - 1 else None)
        y += h + 0.6
    sources = sorted(set(table.text[table.text.str.contains(" (", regex=False)]))
    ax.text(0.004, total + 0.9, "; ".join(sources), fontsize=8, color="0.3", va="bottom")
    fig.suptitle("Errata: where Blinn 1977, Cook & Torrance 1982, the lecture and the article "
                 "disagree with each other or with arithmetic", fontsize=11, y=0.995, va="top")
    savefig(fig, png, pdf)


if "snakemake" in globals():
    from reflectance.io.tables import write_csv
    from reflectance.scripting import script_log

    with script_log(snakemake) as log:
        settings = dict(snakemake.params.errata)
        variables = {k: v for k, v in settings.items() if k != "rows"}
        table = errata_table(snakemake.input.rows, variables)
        table.pipe(write_csv, snakemake.output.csv, float_format="%.6g")
        render(table, snakemake.output.png, snakemake.output.pdf)
        for r in table.itertuples():
            log.info("%s | %s | %s", r.text, r.location, r.consequence)
