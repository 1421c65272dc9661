"""Audit 8, figure 5: how much does the data, rather than the shortcut, decide the answer? For
each material with several datasets (figures.spread), how far its datasets disagree (CIEDE2000
between their F0 colours, every pair) against the method's own error, and where each dataset
puts the method's first failure."""

from itertools import combinations

import numpy as np
import pandas as pd

from reflectance.audit.database import read_table
from reflectance.colour.difference import delta_E_CIE2000
from reflectance.io.atomic import write_text
from reflectance.io.figures import OKABE_ITO, PRINT_WIDTH_IN, TEXT_SIZE, new_figure, savefig
from reflectance.io.tables import write_csv
from reflectance.scripting import script_log

with script_log(snakemake) as log:
    cfg = snakemake.params.figure
    method, level = cfg["method"], cfg["level"]
    first, error = f"{method}_first_deg_above_{level:g}", f"{method}_max_dE2000"
    table = read_table(snakemake.input.csv)
    rows = table[(table.status == "audited") & table.kind.isin(cfg["kinds"])
                 & table.shelf.isin(cfg["shelves"])]
    groups = [(key, part) for key, part in rows.groupby(["shelf", "material"])
              if len(part) >= cfg["min_datasets"]]
    spread = []
    for (shelf, material), part in groups:
        Lab = part[["F0_L", "F0_a", "F0_b"]].to_numpy()
        pairs = np.array([delta_E_CIE2000(Lab[i], Lab[j])
                          for i, j in combinations(range(len(Lab)), 2)])
        spread.append({"shelf": shelf, "material": material, "datasets": len(part),
                       "F0_dE2000_median_pair": np.median(pairs), "F0_dE2000_max_pair": pairs.max(),
                       f"{error}_median": part[error].median(), f"{error}_min": part[error].min(),
                       f"{error}_max": part[error].max(), f"{first}_min": part[first].min(),
                       f"{first}_median": part[first].median(), f"{first}_max": part[first].max(),
                       f"{first}_never": int(part[first].isna().sum())})
    spread = pd.DataFrame(spread).sort_values(f"{first}_median", na_position="last")
    spread.pipe(write_csv, snakemake.output.csv, float_format="%.4f")

    fig = new_figure(PRINT_WIDTH_IN, 1.3 + 0.2 * len(spread))
    left, right = fig.subplots(1, 2, gridspec_kw={"width_ratios": (1.25, 1), "wspace": 0.45})
    for y, (_, s) in enumerate(spread.iterrows()):
        part = rows[(rows.shelf == s.shelf) & (rows.material == s.material)]
        angles = part[first].dropna()
        left.plot([angles.min(), angles.max()], [y, y], color="0.8", linewidth=2.5,
                  solid_capstyle="butt")
        left.scatter(angles, np.full(len(angles), y), s=10, c=list(part.loc[angles.index, "F0_sRGB"]),
                     edgecolors="0.3", linewidths=0.4, zorder=3)
        right.scatter(s[f"{error}_median"], s.F0_dE2000_median_pair, s=14, color=OKABE_ITO[0])
        right.annotate(s.material, (s[f"{error}_median"], s.F0_dE2000_median_pair),
                       xytext=(3, 2), textcoords="offset points", fontsize=TEXT_SIZE["table"])
    never = spread[f"{first}_never"]
    left.set_yticks(range(len(spread)), [f"{m} ({n}{f', {v} never' if v else ''})" for m, n, v in
                                          zip(spread.material, spread.datasets, never)])
    left.set_ylim(len(spread) - 0.5, -0.5)
    left.margins(x=0.04)
    left.set_xlabel(f"angle (\u00b0), one dot per dataset")
    left.set_title(f"where {method} first exceeds \u0394E00 {level:g}", loc="left")
    left.grid(True, axis="x")
    top = 1.1 * max(spread[f"{error}_median"].max(), spread.F0_dE2000_median_pair.max())
    right.fill_between([0, top], [0, top], [top, top], color="0.94", linewidth=0, zorder=0)
    right.plot([0, top], [0, top], color="0.5", linewidth=0.8, linestyle="--")
    right.set_xlim(0, top)
    right.set_ylim(0, top)
    right.set_xlabel(f"{method}'s largest \u0394E00\n(median over the datasets)")
    right.set_ylabel("\u0394E00 between two datasets' F0\n(median over the pairs)")
    right.set_title("shaded: the data disagree more\nthan the shortcut errs", loc="left",
                    fontsize=TEXT_SIZE["annotation"])
    right.grid(True)
    savefig(fig, snakemake.output.png, snakemake.output.pdf)

    more = spread[spread.F0_dE2000_median_pair > spread[f"{error}_median"]]
    widest = spread.loc[(spread[f"{first}_max"] - spread[f"{first}_min"]).idxmax()]
    answer = (f"**Answer:** for {len(more)} of the {len(spread)} {' and '.join(cfg['kinds'])} "
              f"materials with at least {cfg['min_datasets']} datasets, two datasets' F0 colours "
              f"typically differ (median over the pairs) by more CIEDE2000 than {method} errs at "
              f"its worst angle (median over the datasets). {widest.material}'s "
              f"{int(widest.datasets)} datasets put {method}'s first angle above {level:g} "
              f"anywhere from {widest[f'{first}_min']:g} to {widest[f'{first}_max']:g}\u00b0, and "
              f"their F0 colours differ by up to {widest.F0_dE2000_max_pair:.1f}.\n")
    write_text(snakemake.output.answer, answer)
    log.info("%s", answer.strip())
