"""Wikipedia, "Specular highlight" (oldid 793299363), "Phong distribution": the worked example
N = (0, 1, 0), E = (sqrt3/2, 1/2, 0), L = (-0.6, 0.8, 0), n = 3, recomputed step by step. Each step's
value as printed (config.yaml) is compared with the value recomputed from the exact inputs; "agree"
means within one unit of the last printed digit. A second column recomputes each step from the
article's own printed previous step, which shows where a discrepancy comes from."""

import numpy as np
import pandas as pd

from reflectance.io.captions import write_caption_values
from reflectance.optics.brdf import brdf
from reflectance.io.figures import PRINT_WIDTH_IN, STYLE, TEXT_SIZE, new_figure, savefig
from reflectance.scripting import script_log
from reflectance.io.tables import write_csv


def number(text):
    return np.array([float(t) for t in np.atleast_1d(text)]) if isinstance(text, list) else float(text)


def tolerance(text):
    """One unit of the last printed digit (of the most precise component); integers are exact."""
    places = [len(t.split(".")[1]) for t in np.atleast_1d(text) if "." in t]
    return 10.0 ** -max(places) if places else 1e-12


def show(x):
    return "{" + "; ".join(f"{v:.6g}" for v in x) + "}" if np.ndim(x) else f"{x:.6g}"


with script_log(snakemake) as log:
    cfg = snakemake.params.fig
    N, E, L = (np.asarray(cfg[k], dtype=np.float64) for k in ("N", "E", "L"))
    n = cfg["n"]
    pr = {k: number(v) for k, v in cfg["printed"].items()}
    R = E - 2 * N * (N @ E)  # article: R = E - 2N(N.E)
    S = L + E
    # step key: (formula, exact value, value from the article's printed previous step)
    steps = {
        "two_N_NE": ("2N(N\u00b7E)", 2 * N * (N @ E), 2 * N * (N @ E)),
        "R": ("R = E - 2N(N\u00b7E)", R, E - pr["two_N_NE"]),
        "LR_terms": ("terms of L\u00b7R (x, y)", (L * R)[:2], (L * pr["R"])[:2]),
        "LR": ("L\u00b7R", L @ R, pr["LR_terms"].sum()),
        "k_phong": ("k = (L\u00b7R)^n", (L @ R) ** n, pr["LR"] ** n),
        "L_plus_E": ("L + E", S, S),
        "H_half": ("H = (L + E)/2 (unnormalised)", S / 2, pr["L_plus_E"] / 2),
        "NH_half": ("N\u00b7H, H unnormalised", N @ (S / 2), N @ pr["H_half"]),
        "k_half": ("k = (N\u00b7H)^n, H unnormalised", (N @ (S / 2)) ** n, pr["NH_half"] ** n),
        "H_length": ("|H|", np.linalg.norm(S / 2), np.linalg.norm(pr["H_half"])),
        "H_unit": ("H/|H|", S / np.linalg.norm(S), pr["H_half"] / np.linalg.norm(pr["H_half"])),
        "NH_unit": ("N\u00b7H, H normalised", N @ S / np.linalg.norm(S), N @ pr["H_unit"]),
        "k_unit": ("k = (N\u00b7H)^n, H normalised", (N @ S / np.linalg.norm(S)) ** n, pr["NH_unit"] ** n),
    }
    rows = []
    for key, (formula, exact, from_printed) in steps.items():
        agree = bool(np.all(np.abs(np.asarray(exact) - pr[key]) <= tolerance(cfg["printed"][key]) * (1 + 1e-9)))
        rows.append({"step": key, "formula": formula, "as_printed": show(pr[key]),
                     "recomputed": show(exact), "agree": "yes" if agree else "NO",
                     "from_printed_previous_step": show(from_printed)})
    # Not printed by the article: its NOTE's max(0, .), the true mirror direction, and the library.
    mirror = 2 * N * (N @ E) - E
    NL, NE = N @ L, N @ E
    extra = {
        "k_phong_clamped": ("k = max(0, L\u00b7R)^n (article's NOTE)", max(L @ R, 0.0) ** n),
        "k_phong_mirror": ("k = (L\u00b7R)^n with R = 2N(N\u00b7E) - E", (L @ mirror) ** n),
        "k_phong_library": ("brdf_Phong1975 x N\u00b7L", brdf(L, E, N, "Phong1975", p_d=0.0, c1=n) * NL),
        "k_unit_library": ("brdf_BlinnPhong1977 x N\u00b7L", brdf(L, E, N, "BlinnPhong1977", p_d=0.0, c1=n) * NL),
    }
    for key, (formula, value) in extra.items():
        rows.append({"step": key, "formula": formula, "as_printed": "(not printed)",
                     "recomputed": show(value), "agree": "", "from_printed_previous_step": ""})
    table = pd.DataFrame(rows)
    table.pipe(write_csv, snakemake.output.csv)
    log.info("N.E = %.6g, N.L = %.6g; steps that disagree: %s", NE, NL,
             ", ".join(table.step[table.agree == "NO"]))

    row_in = 1.9 * TEXT_SIZE["table"] / 72  # a table row, in inches
    fig = new_figure(PRINT_WIDTH_IN, row_in * (len(table) + 1) + 0.45)
    ax = fig.add_axes((0.0, 0.0, 1.0, 1.0 - 0.45 / fig.get_figheight()))
    ax.axis("off")
    columns = ["formula", "as_printed", "recomputed", "agree", "from_printed_previous_step"]
    cells = ax.table(cellText=table[columns].values,
                     colLabels=["step", "as printed", "recomputed", "agree?", "from printed step before"],
                     loc="upper center", cellLoc="left", colWidths=[0.28, 0.21, 0.2, 0.08, 0.23],
                     bbox=(0.0, 0.0, 1.0, 1.0))
    cells.auto_set_font_size(False)
    cells.set_fontsize(TEXT_SIZE["table"])
    for (r, c), cell in cells.get_celld().items():
        cell.set_edgecolor("0.8")
        cell.set_linewidth(0.5)
        cell.PAD = 0.03
        if r == 0:
            cell.set_text_props(weight="bold")
            cell.set_facecolor("0.94")
        elif table.agree.iloc[r - 1] == "NO":
            cell.set_facecolor("#fbdada")
    fig.suptitle("Wikipedia, \u201cSpecular highlight\u201d: the Phong example recomputed from exact inputs\n"
                 f"N = {show(N)}, E = {show(E)}, L = {show(L)}, n = {n:g}; red: off beyond the last printed digit",
                 size=STYLE["axes.titlesize"], y=0.995, va="top")
    savefig(fig, snakemake.output.png, snakemake.output.pdf)

    # the caption's recomputed numbers (workflow/report/article_phong_example.rst), to the digits
    # the article prints, from the table as written
    recomputed = pd.read_csv(snakemake.output.csv, dtype=str).set_index("step").recomputed
    write_caption_values(snakemake.output.values, {
        "LR": f"{float(recomputed.LR):.4f}", "k_phong": f"{float(recomputed.k_phong):.4f}",
        "k_mirror": f"{float(recomputed.k_phong_mirror):.4f}",
        "k_library": f"{float(recomputed.k_phong_library):.4f}",
        "H_length": f"{float(recomputed.H_length):.4f}",
        "k_unit": f"{float(recomputed.k_unit):.6f}"})
