"""Audit 8, figure 4, a check: the manufacturers' glasses (figures.glasses.shelf) are k = 0
dielectrics, for which Cook & Torrance's k = 0 fit and Gulbrandsen's model give back the exact
index: their error must be zero. Each method's largest CIEDE2000 over the glasses, and Schlick's
and F82's against the glass's index."""

import numpy as np

from reflectance.audit.database import read_table
from reflectance.io.atomic import write_text
from reflectance.io.figures import OKABE_ITO, PRINT_WIDTH_IN, TEXT_SIZE, new_figure, savefig
from reflectance.scripting import script_log

with script_log(snakemake) as log:
    cfg = snakemake.params.figure
    methods, shelf = cfg["methods"], cfg["shelf"]
    table = read_table(snakemake.input.csv)
    glasses = table[(table.status == "audited") & ((table.dataset.str.startswith(shelf + "/"))
                                                   | (table.dataset == shelf))]
    dE = {m: glasses[f"{m}_max_dE2000"].to_numpy() for m in methods}

    fig = new_figure(PRINT_WIDTH_IN, 3.4)
    left, right = fig.subplots(1, 2, gridspec_kw={"width_ratios": (1, 1.1), "wspace": 0.35,
                                                  "top": 0.88})
    positions = np.arange(len(methods))[::-1]
    left.boxplot([dE[m] for m in methods], positions=positions, vert=False, whis=(0, 100),
                 widths=0.55, showfliers=False, medianprops={"color": OKABE_ITO[1]})
    for y, m in zip(positions, methods):
        left.text(dE[m].max() + 0.08, y, f"max {dE[m].max():.4f}", va="center",
                  fontsize=TEXT_SIZE["annotation"], color="0.25")
    left.set_yticks(positions, methods)
    left.set_xlim(0, 1.45 * max(v.max() for v in dE.values()) + 0.1)
    left.set_xlabel("largest \u0394E00 over 0-90\u00b0 (box: quartiles, whiskers: range)")
    left.grid(True, axis="x")
    for m, colour, marker in zip([m for m in ("schlick", "f82") if m in methods],
                                 (OKABE_ITO[0], OKABE_ITO[4]), ("o", "s")):
        right.scatter(glasses.mean_n, dE[m], s=6, color=colour, marker=marker, label=m,
                      linewidths=0)
    right.set_xlabel("mean n over the grid")
    right.set_ylabel("largest \u0394E00")
    right.legend(loc="center right", markerscale=2)
    right.margins(x=0.03, y=0.08)
    right.grid(True)
    fig.suptitle(f"The check: {len(glasses)} glasses of {shelf} (k = 0 dielectrics)",
                 y=0.9, va="bottom")
    savefig(fig, snakemake.output.png, snakemake.output.pdf)

    missing = int((glasses.k_source == "missing").sum())
    formula = int(glasses.n_source.str.startswith("formula").sum())
    zero = [m for m in methods if dE[m].max() == 0.0]
    rest = [f"{m} {np.median(dE[m]):.2f} (median; range {dE[m].min():.2f}-{dE[m].max():.2f})"
            for m in methods if m not in zero]
    pair = [m for m in ("schlick", "f82") if m in methods]
    worse = (f" F82 errs more than Schlick on {int((dE['f82'] > dE['schlick']).sum())} of "
             f"them." if len(pair) == 2 else "")
    answer = (f"**Answer:** over the {len(glasses)} glasses of {shelf} ({missing} without k, "
              f"audited with k = 0; {formula} with n from a dispersion formula), "
              + (f"{' and '.join(zero)} are exact to the table's 4 decimals at every angle "
                 f"(largest CIEDE2000 0.0000), as they must be for a k = 0 dielectric; "
                 if zero else "no method is exact; ")
              + "the others' largest CIEDE2000: " + "; ".join(rest) + "." + worse + "\n")
    write_text(snakemake.output.answer, answer)
    log.info("%s", answer.strip())
