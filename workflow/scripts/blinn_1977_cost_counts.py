"""Blinn 1977, "Conclusions": D3 "is, happily, easier to compute than D1 or D2. This savings
effectively offsets the extra computation time for G and F". Each term's operations per pixel,
counted as Blinn would count them (reflectance.papers.highlight_cost): the deterministic half of
the claim's table; the times are blinn_1977_cost_timing.py's."""

import pandas as pd

from reflectance.io.captions import write_caption_values
from reflectance.io.tables import write_csv
from reflectance.optics.microfacet import (beta_to_c1_Blinn1977, beta_to_c2_Blinn1977,
                                           c3_to_beta_Blinn1977)
from reflectance.papers.highlight_cost import count_table, frame_constants
from reflectance.scripting import script_log

with script_log(snakemake) as log:
    panel = snakemake.params.panels[snakemake.params.fig["panel"]]
    beta = c3_to_beta_Blinn1977(panel["c3"])  # Blinn's equal-beta rule: D1, D2 halve where D3 does
    c1, c2 = float(beta_to_c1_Blinn1977(beta)), float(beta_to_c2_Blinn1977(beta))
    k = frame_constants(c1, c2, panel["c3"], panel["n"])
    table = pd.DataFrame(count_table(k))
    table.pipe(write_csv, snakemake.output.csv)
    log.info("%s: c1 %.6g (integer %d), c2 %.6g\n%s", panel["label"], c1, k.c1_integer, c2,
             table.drop(columns=["printed", "blinn_1977_section"]).to_string())

    row = pd.read_csv(snakemake.output.csv, keep_default_na=False).set_index("term")
    phong, ts, frame = (row.loc[key] for key in ("phong", "torrance_sparrow",
                                                 "torrance_sparrow_F_per_frame"))
    squaring = row.loc["D1_squaring"]
    write_caption_values(snakemake.output.values, {
        "c1": f"{c1:.2f}", "c1_integer": f"{k.c1_integer}",
        "squaring_multiplies": f"{squaring.multiplies}",
        "d3_arithmetic": f"{row.loc['D3'].arithmetic}",
        "d2_calls": f"{row.loc['D2'].transcendental}",
        "ts_arithmetic": f"{ts.arithmetic}", "ts_calls": f"{ts.transcendental}",
        "frame_arithmetic": f"{frame.arithmetic}",
        "phong_calls": f"{phong.transcendental}",
        # the claim holds by the counts where one pow costs at least what the Torrance-Sparrow
        # highlight adds in other operations
        "break_even": f"{ts.arithmetic - phong.arithmetic}",
        "break_even_frame": f"{frame.arithmetic - phong.arithmetic}",
        "squaring_verdict": ("holds" if frame.arithmetic <= squaring.arithmetic else "fails")})
