"""Blinn 1977, Fig. 7: an object rendered with Phong's and the Torrance-Sparrow highlight, edge lit
and front lit, (a) aluminium and (b) magnesium oxide with Blinn's measured parameters; Phong's c1
from the beta of c3. Grey images whose Y is Blinn's intensity i = p_a + d p_d + s p_s (no exposure:
i = 1 is display white; the default figure's edge-lit images share one exposure, white = their
brightest i). One figure per reading of Phong's p_s; a table of the differences."""

from reflectance.papers.draw.blinn77_fig7 import run
from reflectance.scripting import run_job

run_job(snakemake, run)
