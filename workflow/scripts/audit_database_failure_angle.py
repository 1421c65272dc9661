"""Audit 8, figure 1: from which angle does a shortcut (figures.failure_angle.method, Schlick's)
fail on the datasets of one kind (metal-like)? The distribution of its first angle above each
CIEDE2000 level, and the share of the datasets it has failed by each angle."""

import numpy as np

from reflectance.audit.database import read_table
from reflectance.io.atomic import write_text
from reflectance.io.figures import OKABE_ITO, PRINT_WIDTH_IN, TEXT_SIZE, new_figure, savefig
from reflectance.scripting import script_log

with script_log(snakemake) as log:
    cfg, levels = snakemake.params.figure, snakemake.params.levels
    method, kind, step = cfg["method"], cfg["kind"], snakemake.params.angle_step_deg
    table = read_table(snakemake.input.csv)
    rows = table[(table.status == "audited") & (table.kind == kind)]
    first = {level: rows[f"{method}_first_deg_above_{level:g}"].to_numpy() for level in levels}
    angles = np.arange(0.0, 90.0 + step / 2, step)
    bins = np.arange(0.0, 90.0 + cfg["bin_deg"] / 2, cfg["bin_deg"])

    fig = new_figure(PRINT_WIDTH_IN, 4.4)
    top, bottom = fig.subplots(2, 1, sharex=True, gridspec_kw={"height_ratios": (1.2, 1),
                                                               "hspace": 0.1})
    colours = [OKABE_ITO[i] for i in (0, 4, 1, 2, 3)]
    for level, colour in zip(levels, colours):
        found = first[level][np.isfinite(first[level])]
        top.hist(found, bins=bins, histtype="stepfilled", color=colour, alpha=0.25)
        top.hist(found, bins=bins, histtype="step", color=colour, linewidth=1.2,
                 label=f"\u0394E00 > {level:g}: {found.size} of {len(rows)}")
        # NaN (never above the level) compares False: such a dataset never counts as failed
        share = 100.0 * (first[level][:, None] <= angles[None, :]).mean(axis=0)
        bottom.step(angles, share, where="post", color=colour, linewidth=1.5)
    top.set_ylabel(f"datasets per {cfg['bin_deg']:g}\u00b0")
    top.legend(loc="upper left", title=f"first angle at which {method} exceeds",
               title_fontsize=TEXT_SIZE["annotation"])
    top.set_title(f"{method} on the {len(rows)} {kind} datasets of refractiveindex.info "
                  f"({snakemake.params.illuminant}): where its colour first fails")
    bottom.set_ylim(0, 100)
    bottom.set_yticks([0, 25, 50, 75, 100])
    bottom.set_ylabel("% failed by \u03b8")
    bottom.set_xlim(0, 90)
    bottom.set_xticks(np.arange(0, 91, 10))
    bottom.set_xlabel("incidence angle \u03b8 (\u00b0)")
    for ax in (top, bottom):
        ax.grid(True)
    savefig(fig, snakemake.output.png, snakemake.output.pdf)

    parts = []
    for level in levels:
        found = first[level][np.isfinite(first[level])]
        if not found.size:
            parts.append(f"CIEDE2000 {level:g} on none")
            continue
        q1, q2, q3 = np.percentile(found, [25, 50, 75])
        earliest = rows.iloc[int(np.nanargmin(first[level]))]
        parts.append(f"CIEDE2000 {level:g} on {found.size} ({100 * found.size / len(rows):.0f} %), "
                     f"first at a median {q2:g}\u00b0 (quartiles {q1:g}-{q3:g}\u00b0; earliest "
                     f"{found.min():g}\u00b0, {earliest.dataset})")
    by = 100.0 * np.mean(first[levels[0]] <= cfg["at_deg"])
    answer = (f"**Answer:** of the {len(rows)} {kind} datasets, {method}'s colour exceeds "
              + "; ".join(parts) + f". By {cfg['at_deg']:g}\u00b0 it has exceeded CIEDE2000 "
              f"{levels[0]:g} on {by:.0f} % of them.\n")
    write_text(snakemake.output.answer, answer)
    log.info("%s", answer.strip())
