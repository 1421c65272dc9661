"""Blinn 1977, "Conclusions": "... for no increase in computation time". Each term's time per
evaluation over random light and eye directions, in the project's own implementation and as the
counted formula (reflectance.papers.highlight_cost), beside the operation counts of
blinn_1977_cost_counts.py. A measurement: the date and the CPU go with it, and a rerun gives
other digits (the verdict's margin keeps its word)."""

import datetime
import platform
from pathlib import Path

import numpy as np
import pandas as pd
import yaml

from reflectance.io.atomic import atomic_write
from reflectance.io.captions import write_caption_values
from reflectance.io.tables import write_csv
from reflectance.optics.microfacet import (beta_to_c1_Blinn1977, beta_to_c2_Blinn1977,
                                           c3_to_beta_Blinn1977)
from reflectance.papers.highlight_cost import (OPERATIONS, formula_terms, frame_constants, project_terms,
                                               sample_dot_products, time_per_evaluation,
                                               timing_verdict)
from reflectance.scripting import script_log


def cpu_name():
    try:
        with open("/proc/cpuinfo") as cpuinfo:
            for line in cpuinfo:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


with script_log(snakemake) as log:
    cfg = snakemake.params.fig
    panel = snakemake.params.panels[cfg["panel"]]
    beta = c3_to_beta_Blinn1977(panel["c3"])
    c1, c2 = float(beta_to_c1_Blinn1977(beta)), float(beta_to_c2_Blinn1977(beta))
    k = frame_constants(c1, c2, panel["c3"], panel["n"])
    n = cfg["n_samples"]
    samples = sample_dot_products(n, cfg["seed"])
    project = project_terms(samples, c1, c2, panel["c3"], panel["n"], panel["p_s"], panel["p_d"])
    formulas = formula_terms(samples, k)
    formulas["one_multiply"] = lambda: samples["NH"] * samples["NL"]  # the unit: one numpy multiply
    functions = {("project", key): f for key, (_, f) in project.items()}
    functions.update({("formula", key): f for key, f in formulas.items()})
    when = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    ns = time_per_evaluation(functions, n, cfg["repeats"])

    counts = pd.read_csv(snakemake.input.counts, keep_default_na=False)
    extra = pd.DataFrame({"term": ["one_multiply", "brdf_phong", "brdf_torrance_sparrow"],
                          "label": ["one multiply (numpy)", "Phong model, whole BRDF",
                                    "Torrance-Sparrow model, whole BRDF"]})
    table = pd.concat([counts, extra], ignore_index=True)
    numbers = [*OPERATIONS, "arithmetic"]
    table[numbers] = table[numbers].astype("Int64")  # counts stay integers beside the empty rows
    table["project_function"] = [project[t][0] if t in project else "" for t in table.term]
    table["ns_project"] = [ns.get(("project", t), np.nan) for t in table.term]
    table["ns_formula"] = [ns.get(("formula", t), np.nan) for t in table.term]
    table.pipe(write_csv, snakemake.output.csv, float_format="%.3g")
    log.info("%s, %s, %d samples, best of %d\n%s", when, cpu_name(), n, cfg["repeats"],
             table[["term", "arithmetic", "transcendental", "ns_project", "ns_formula"]].to_string())

    t = table.set_index("term")
    ratios = {  # Torrance-Sparrow highlight over Phong's, as the verdict reads them
        "project": t.ns_project["torrance_sparrow"] / t.ns_project["phong"],
        "project_F_per_frame": t.ns_project["torrance_sparrow_F_per_frame"] / t.ns_project["phong"],
        "formula_F_per_frame": (t.ns_formula["torrance_sparrow_F_per_frame"]
                                / t.ns_formula["phong"]),
        "brdf": t.ns_project["brdf_torrance_sparrow"] / t.ns_project["brdf_phong"]}
    bounds = cfg["verdict"]
    verdicts = {key: timing_verdict(r, bounds["holds_at_most"], bounds["fails_at_least"])
                for key, r in ratios.items()}
    pow_in_multiplies = t.ns_formula["D1_pow"] / t.ns_formula["one_multiply"]
    measurement = {
        "measurement": "timings differ from run to run; not byte-identical (docs: results guide)",
        "measured": when, "cpu": cpu_name(), "machine": platform.machine(),
        "python": platform.python_version(), "numpy": np.__version__,
        "n_samples": n, "repeats": cfg["repeats"], "seed": cfg["seed"],
        "ratios": {key: round(float(r), 3) for key, r in ratios.items()},
        "verdicts": verdicts, "verdict_bounds": dict(bounds),
        "pow_in_multiplies": round(float(pow_in_multiplies), 2)}
    with atomic_write(snakemake.output.measurement) as tmp:
        Path(tmp).write_text(yaml.safe_dump(measurement, sort_keys=False))
    log.info("ratios %s; verdicts %s", ratios, verdicts)

    write_caption_values(snakemake.output.values, {
        "measured": when, "cpu": measurement["cpu"], "numpy": np.__version__,
        "ratio_project": f"{ratios['project']:.1f}",
        "ratio_project_frame": f"{ratios['project_F_per_frame']:.1f}",
        "ratio_formula_frame": f"{ratios['formula_F_per_frame']:.1f}",
        "ratio_brdf": f"{ratios['brdf']:.1f}",
        "verdict_project": verdicts["project"],
        "verdict_formula_frame": verdicts["formula_F_per_frame"],
        "d3_ns": f"{t.ns_project['D3']:.0f}", "d1_ns": f"{t.ns_project['D1_pow']:.0f}",
        "d2_ns": f"{t.ns_project['D2']:.0f}",
        "g_ns": f"{t.ns_project['G_over_NE']:.0f}", "f_ns": f"{t.ns_project['F']:.0f}",
        "pow_in_multiplies": f"{pow_in_multiplies:.0f}",
        # from the counts: the pow at which Blinn's claim holds, F once per frame
        "break_even_frame": f"{int(t.arithmetic['torrance_sparrow_F_per_frame'] - t.arithmetic['phong'])}"})
