"""Blinn 1977, Fig. 8: surface shininess varying with two texture patterns. The object of Fig. 7
with Blinn's Torrance-Sparrow model, D3 with C3 = C_min + (1 - C_min) t(u, v) normalised by C_min
(scene key roughness_texture), one oblique light; grey, i = 1 is white. Below each render, the
C3 map over (u, v)."""

from reflectance.papers.draw.blinn77_fig8 import run
from reflectance.scripting import run_job

run_job(snakemake, run)
